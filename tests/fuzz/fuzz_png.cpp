// tiershade fuzz: PNG input both ways a user's file comes in: io/png.h's libpng reader, and a glTF
// texture (the scene loader's image callback, libpng for PNG: glue/scene/gltf_load.cpp) from a fixed scene.
#include "fuzz_util.h"
#include "io/png.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::string png = fuzz::write_file("in.png", data, size);
  ImageF img;
  std::string err;
  read_png(png, &img, Encode::SRGB, &err);
  static const std::string scene = fuzz::write_text(
      "png.gltf", R"({"asset": {"version": "2.0"}, "images": [{"uri": "in.png"}]})");
  Scene s;
  load_scene(scene, &s, &err);
  return 0;
}

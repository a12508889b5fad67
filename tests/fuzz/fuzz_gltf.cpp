// tiershade fuzz: the glTF 2.0 scene loader (scene/scene.h: load_scene) with its tiershade extras,
// on any bytes: a .glb when they start with the GLB magic, else a .gltf (buffers in data URIs).
#include <cstring>

#include "fuzz_util.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  Scene s;
  std::string err;
  load_scene(fuzz::write_file(glb ? "in.glb" : "in.gltf", data, size), &s, &err);
  return 0;
}

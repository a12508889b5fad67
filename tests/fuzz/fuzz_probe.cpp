// tiershade fuzz: a probe input file: read as the scene loader does (.hdr or .exr by its magic),
// then turned into a cube map and ambient cube (scene/textures.h: cube_from_probe).
#include <cstring>

#include "fuzz_util.h"
#include "scene/textures.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const uint8_t exr_magic[4] = {0x76, 0x2f, 0x31, 0x01};
  const bool exr = size >= 4 && std::memcmp(data, exr_magic, 4) == 0;
  const std::string path = fuzz::write_file(exr ? "probe.exr" : "probe.hdr", data, size);
  TextureDesc cube;
  float ambient[6][3];
  std::string err;
  cube_from_probe(path, "u_envmap", 4, &cube, ambient, &err);
  return 0;
}

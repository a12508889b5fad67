// tiershade fuzz: the .cube reader (io/lut_files.h: read_cube, cube_as_lut3d, read_lut_file).
#include "fuzz_util.h"
#include "io/lut_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::string path = fuzz::write_file("in.cube", data, size);
  CubeFile c;
  Lut3D l;
  std::string err;
  if (read_cube(path, &c, &err)) cube_as_lut3d(path, c, &l, &err);
  return 0;
}

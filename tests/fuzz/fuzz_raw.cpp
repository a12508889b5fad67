// tiershade fuzz: Source's .raw colour-correction LUT reader (io/lut_files.h: read_lut_file).
#include "fuzz_util.h"
#include "io/lut_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  Lut3D l;
  std::string err;
  read_lut_file(fuzz::write_file("in.raw", data, size), &l, &err);
  return 0;
}

// tiershade fuzz: the OpenEXR reader (io/exr.h) on any bytes.
#include "fuzz_util.h"
#include "io/exr.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  ImageF img;
  std::string err;
  read_exr(fuzz::write_file("in.exr", data, size), &img, &err);
  return 0;
}

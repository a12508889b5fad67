// tiershade fuzz: the Radiance .hdr reader (io/radiance_hdr.h) on any bytes.
#include "fuzz_util.h"
#include "io/radiance_hdr.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  ImageF img;
  std::string err;
  read_hdr(fuzz::write_file("in.hdr", data, size), &img, &err);
  return 0;
}

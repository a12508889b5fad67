// tiershade fuzz: the lights file reader (io/lights_file.h).
#include "fuzz_util.h"
#include "io/lights_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::vector<ts_light> lights;
  std::string err;
  read_lights(fuzz::write_file("in.lights", data, size), &lights, &err);
  return 0;
}

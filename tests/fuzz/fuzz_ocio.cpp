// tiershade fuzz: OpenColorIO inputs through glue/color/ocio_lut_bake.h: the bytes as a config
// (a look of it, LookTransform) and as file transforms (.cc, .cdl, .3dl, .spi3d), each opened and,
// when it opens, baked into a small LUT. The first byte picks the kind.
#include "color/ocio_lut_bake.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1) return 0;
  static const char *const kinds[] = {"config.ocio", "in.cc", "in.cdl", "in.3dl", "in.spi3d", "in.ccc"};
  const int k = data[0] % 6;
  const std::string path = fuzz::write_file(kinds[k], data + 1, size - 1);
  TransformSpec spec;
  if (k == 0) {
    spec.kind = TransformSpec::Kind::Look;
    spec.config = path;
    spec.looks = "desaturate";
  } else {
    spec.kind = TransformSpec::Kind::File;
    spec.file = path;
  }
  ColorTransform t;
  std::string err;
  Lut3D l;
  if (t.open(spec, &err)) bake_lut(t, 2, &l, &err);
  return 0;
}

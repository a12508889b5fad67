// tiershade tests: the host's half of the portable contract on NaN and Inf (glue/scene/finite_check.h,
// docs/conformance.md "The portable contract"): texels are clamped into the fp16 range (+-Inf and
// beyond 65504 -> +-65504) and a NaN texel is refused, naming where; uniform values must be finite;
// a Radiance probe whose RGBE texels reach 2^126 (beyond fp16) gives a cube map and an ambient cube
// clamped to 65504 (scene/textures.cpp cube_from_probe), in a private mkdtemp() directory.
//
// Usage: build/tests/test_nonfinite_inputs   Prints PASS/FAIL lines and "N passed, N failed".
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "scene/finite_check.h"
#include "scene/textures.h"
#include "unit_check.h"

using unit_check::check;

namespace {

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

void test_clamp() {
  std::vector<float> v = {1.0f, kInf, -kInf, 1e30f, -70000.0f, 65504.0f, 0.0f, -1e-40f};
  size_t clamped = 0;
  std::string err;
  const bool ok = clamp_texels_to_fp16(v.data(), v.size(), "t.exr", &clamped, &err);
  check(ok && clamped == 4, "clamp_texels_to_fp16: +-Inf, 1e30 and -70000 clamped (4 values)",
        err + " clamped " + std::to_string(clamped));
  check(v[0] == 1.0f && v[1] == 65504.0f && v[2] == -65504.0f && v[3] == 65504.0f && v[4] == -65504.0f &&
            v[5] == 65504.0f && v[6] == 0.0f && v[7] == -1e-40f,
        "clamp_texels_to_fp16: clamped to +-65504, the others kept bit for bit");
  std::vector<float> n = {0.5f, 0.25f, kNaN, 1.0f};
  err.clear();
  check(!clamp_texels_to_fp16(n.data(), n.size(), "probe.hdr: the cube map", nullptr, &err) &&
            err.find("probe.hdr: the cube map: value 2 is NaN") == 0,
        "clamp_texels_to_fp16: a NaN texel is refused, naming the place and the value", err);
}

void test_check_finite() {
  std::string err;
  const float good[3] = {0.0f, -65504.0f, 3e38f};
  check(check_finite(good, 3, "u", &err), "check_finite: finite values pass (even beyond fp16)", err);
  const float inf[3] = {0.0f, 1.0f, -kInf};
  check(!check_finite(inf, 3, "draw 0 uniforms", &err) && err == "draw 0 uniforms: value 2 is -Inf (must be finite)",
        "check_finite: -Inf refused, named", err);
  const float nan[2] = {kNaN, 1.0f};
  check(!check_finite(nan, 2, "draw 1 uniforms", &err) && err == "draw 1 uniforms: value 0 is NaN (must be finite)",
        "check_finite: NaN refused, named", err);
}

// A 4 x 2 flat Radiance file: every texel mantissa 128, exponent 255 (2^126 in stb_image's decoding).
void test_probe_clamped() {
  char dir[] = "/tmp/ts_nonfinite_XXXXXX";
  if (!mkdtemp(dir)) {
    check(false, "mkdtemp");
    return;
  }
  const std::string path = std::string(dir) + "/huge.hdr";
  FILE *f = fopen(path.c_str(), "wb");
  if (!f) {
    check(false, "write " + path);
    return;
  }
  fputs("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n", f);
  for (int i = 0; i < 8; ++i) {
    const unsigned char px[4] = {128, 128, 128, 255};
    fwrite(px, 1, 4, f);
  }
  fclose(f);
  TextureDesc cube;
  float ambient[6][3];
  std::string err;
  const bool ok = cube_from_probe(path, "u_envmap", 4, &cube, ambient, &err);
  bool all = ok && !cube.rgba.empty();
  for (size_t i = 0; all && i < cube.rgba.size(); ++i)
    if ((i % 4 != 3 && cube.rgba[i] != 65504.0f) || !std::isfinite(cube.rgba[i])) all = false;
  for (int a = 0; all && a < 6; ++a)
    for (int k = 0; k < 3; ++k)
      if (ambient[a][k] != 65504.0f) all = false;
  check(all, "cube_from_probe: RGBE texels of 2^126 give a cube map and an ambient cube of 65504", err);
  std::remove(path.c_str());
  rmdir(dir);
}

}  // namespace

int main() {
  test_clamp();
  test_check_finite();
  test_probe_clamped();
  return unit_check::finish();
}

// tiershade hdr: sRGB-encoded 8-bit codes by thresholds (glue/hdr/srgb_rgba8_codes.h).
#include "hdr/srgb_rgba8_codes.h"

#include <cmath>
#include <cstring>
#include <mutex>

#include "math/hdr_formats.h"
#include "base/srgb.h"

namespace {

float encode_clamped(float v) {
  if (!(v > 0.f)) return 0.f;
  if (v >= 1.f) return 1.f;
  return static_cast<float>(srgb_encode<double>(v));
}

float from_bits(uint32_t b) {
  float f;
  std::memcpy(&f, &b, 4);
  return f;
}

struct Thresholds {
  float first[256];  // first[c]: the smallest non-negative float whose code is >= c (c >= 1)
  Thresholds() {
    first[0] = 0.f;
    for (int c = 1; c < 256; ++c) {
      uint32_t lo = 0, hi = 0x7f800000u;  // code(lo) < c <= code(hi) (+Inf gives 255)
      while (hi - lo > 1) {
        const uint32_t mid = lo + (hi - lo) / 2;
        if (srgb_code_direct(from_bits(mid)) >= c)
          hi = mid;
        else
          lo = mid;
      }
      first[c] = from_bits(hi);
    }
  }
};

const Thresholds &thresholds() {
  static const Thresholds t;
  return t;
}

}  // namespace

uint8_t srgb_code_direct(float v) { return ts_unorm8_from_float(encode_clamped(v)); }

uint8_t srgb_code(float v) {
  if (!(v > 0.f)) return 0;  // negative, zero, denormal (DAZ) and NaN: code 0, as the formula
  const float *f = thresholds().first;
  int c = 0;
  for (int step = 128; step > 0; step >>= 1)
    if (c + step < 256 && f[c + step] <= v) c += step;
  return static_cast<uint8_t>(c);
}

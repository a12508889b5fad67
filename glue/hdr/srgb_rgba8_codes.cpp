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

// The smallest float whose code is >= c, by bisection over bit patterns (code(lo) < c <= code(hi);
// +Inf gives 255).
float threshold(int c) {
  uint32_t lo = 0, hi = 0x7f800000u;
  while (hi - lo > 1) {
    const uint32_t mid = lo + (hi - lo) / 2;
    if (srgb_code_direct(from_bits(mid)) >= c)
      hi = mid;
    else
      lo = mid;
  }
  return from_bits(hi);
}

SrgbCodeTable make_table() {
  SrgbCodeTable t;
  t.first[0] = 0.f;
  for (int c = 1; c < 256; ++c) t.first[c] = threshold(c);
  t.first[256] = HUGE_VALF;  // no code 256: the search stops at 255
  int c = 0;
  for (int i = 0; i < SrgbCodeTable::kBuckets; ++i) {  // thresholds rise with the bit pattern
    const float lo = from_bits(static_cast<uint32_t>(i) << SrgbCodeTable::kShift);
    while (c < 255 && t.first[c + 1] <= lo) ++c;
    t.bucket[i] = static_cast<uint8_t>(lo > 0.f ? c : 0);
  }
  return t;
}

}  // namespace

uint8_t srgb_code_direct(float v) { return ts_unorm8_from_float(encode_clamped(v)); }

const SrgbCodeTable &srgb_code_table() {
  static const SrgbCodeTable t = make_table();
  return t;
}

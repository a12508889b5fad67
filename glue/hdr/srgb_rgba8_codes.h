// tiershade hdr: the 8-bit code of a linear value encoded with the exact sRGB curve, as the
// integer HDR path stores linear shader outputs (ps20, world_lighting) in its RGBA8 frame:
//   code(v) = ts_unorm8_from_float(float(srgb(double(v))))
// computed by a binary search over the 255 code thresholds instead of a pow per channel. The
// thresholds are found once by bisection over float bit patterns; since every step is monotone
// in v, the result equals the direct formula for every float (tests/unit/test_scene_render.cpp).
#pragma once
#include <cstdint>

// The direct formula (the definition).
uint8_t srgb_code_direct(float v);
// The thresholds, and for each float bit pattern's top 17 bits (sign 0) the code of the bucket's
// smallest value: a bucket spans 2^-8 of its value, narrower than any two codes' thresholds apart
// (the densest, near 1, are 1/255 of the encoded value apart, 2.4/255 of the linear value), so a
// code is its bucket's code plus at most a step or two over the thresholds (a loop: exact for any
// bucket width).
struct SrgbCodeTable {
  static const int kShift = 15, kBuckets = (0x7f800000 >> kShift) + 1;
  // first[c]: the smallest non-negative float whose code is >= c (1 <= c <= 255); first[256]: +Inf
  float first[257];
  uint8_t bucket[kBuckets];
};
const SrgbCodeTable &srgb_code_table();
inline uint8_t srgb_code_in(const SrgbCodeTable &t, float v) {
  if (!(v > 0.f)) return 0;  // negative, zero, denormal (DAZ) and NaN: code 0, as the formula
  if (v >= 1.f) return 255;  // encoded as 1 (+Inf too)
  uint32_t b;
  __builtin_memcpy(&b, &v, 4);
  b >>= SrgbCodeTable::kShift;
  int c = t.bucket[b];  // b < 0x3f80 here
  c += t.first[c + 1] <= v;  // the one threshold a bucket may hold, without a branch
  while (t.first[c + 1] <= v) ++c;  // never taken with these buckets; exact whatever their width
  return static_cast<uint8_t>(c);
}
// The same code through the thresholds.
inline uint8_t srgb_code(float v) { return srgb_code_in(srgb_code_table(), v); }

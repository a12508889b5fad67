/* tiershade math: storage conversions of HDR targets and textures, mirroring
 * llvmpipe (see hdr_formats.h; measurements in docs/hdr.md). Bit manipulation only,
 * so the results do not depend on the host's F16C or rounding-mode state. */
#include "math/hdr_formats.h"

#include <string.h>

#include "math/ts_math.h"

uint16_t ts_half_from_float_rz(float x) {
  uint32_t b;
  memcpy(&b, &x, sizeof b);
  const uint16_t sign = (uint16_t)((b >> 16) & 0x8000u);
  const uint32_t a = b & 0x7fffffffu;
  if (a > 0x7f800000u) return (uint16_t)(sign | 0x7e00u | ((a >> 13) & 0x3ffu)); /* NaN, quieted */
  if (a == 0x7f800000u) return (uint16_t)(sign | 0x7c00u); /* Inf */
  const int e = (int)(a >> 23) - 127;
  if (e >= 16) return (uint16_t)(sign | 0x7bffu); /* toward zero: every finite overflow is 65504 */
  if (e >= -14) return (uint16_t)(sign | (uint16_t)((e + 15) << 10) | (uint16_t)((a >> 13) & 0x3ffu));
  if (e < -24) return sign; /* below half the smallest denormal step, and float denormals */
  /* half denormal: value = m * 2^(e - 23), in units of 2^-24: m * 2^(e + 1), truncated */
  const uint32_t m = (a & 0x7fffffu) | 0x800000u;
  return (uint16_t)(sign | (uint16_t)(m >> (-(e + 1))));
}

float ts_half_to_float(uint16_t h) {
  const uint32_t sign = (uint32_t)(h & 0x8000u) << 16;
  const uint32_t e = (h >> 10) & 0x1fu;
  const uint32_t m = h & 0x3ffu;
  uint32_t b;
  if (e == 0x1f) {
    b = sign | 0x7f800000u | (m << 13);
  } else if (e != 0) {
    b = sign | ((e + 112u) << 23) | (m << 13);
  } else if (m == 0) {
    b = sign;
  } else { /* a half denormal is a normal float: normalise the mantissa */
    uint32_t mm = m;
    int shift = 0;
    while (!(mm & 0x400u)) {
      mm <<= 1;
      ++shift;
    }
    b = sign | ((uint32_t)(113 - shift) << 23) | ((mm & 0x3ffu) << 13);
  }
  float f;
  memcpy(&f, &b, sizeof f);
  return f;
}

float ts_quantize_half(float x) { return ts_half_to_float(ts_half_from_float_rz(x)); }

uint8_t ts_unorm8_from_float(float x) {
  /* saturate with SSE max/min semantics (NaN -> 0), then gallivm's magic-number rounding:
   * x * (255/256) + 2^15 rounds to a multiple of 2^-8, whose low 8 bits are the code. */
  const float c = ts_lp_minf(ts_lp_maxf(x, 0.0f), 1.0f);
  const float r = c * 0.99609375f + 32768.0f;
  uint32_t b;
  memcpy(&b, &r, sizeof b);
  return (uint8_t)(b & 0xffu);
}

float ts_unorm8_to_float(uint8_t c) { return (float)c * (1.0f / 255.0f); }

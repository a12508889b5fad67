/* tiershade offline: lightmap encodings (see lightmap_encoding.h; fact sheet
 * section 2: VectorToColorRGBExp32 and TexLightToLinear in color_conversion.cpp,
 * MAX_HDR_OVERBRIGHT, the LDR gamma tables with overbright 2). Double-precision
 * arithmetic on purpose: these run offline, not in a shader. */
#include "offline/lightmap_encoding.h"

#include <math.h>
#include <string.h>

int ts_rgbe_encode(const float linear[3], ts_rgbe *out) {
  double v[3], mx = 0.0;
  memset(out, 0, sizeof *out);
  for (int c = 0; c < 3; ++c) {
    if (isnan(linear[c])) return -1;
    v[c] = linear[c] > 0.0f ? (double)linear[c] * 255.0 : 0.0; /* vrad units */
    if (v[c] > mx) mx = v[c];
  }
  if (mx == 0.0) return 0;
  if (isinf(mx)) mx = HUGE_VAL; /* handled below: e = 127, the infinite channels saturate */
  int e2 = 1000;
  if (!isinf(mx)) (void)frexp(mx, &e2); /* mx = m 2^e2 with m in [0.5, 1): IEEE exponent = e2 - 1 */
  int e = (e2 - 1) - 7;
  if (e < -128) e = -128;
  if (e > 127) e = 127;
  unsigned char m[3];
  for (int c = 0; c < 3; ++c) {
    const double s = ldexp(v[c], -e); /* exact */
    m[c] = (unsigned char)(s >= 255.0 ? 255 : (int)s); /* truncated, saturated (infinity too) */
  }
  out->r = m[0];
  out->g = m[1];
  out->b = m[2];
  out->exponent = (signed char)e;
  return 0;
}

void ts_rgbe_decode(ts_rgbe c, double linear[3]) {
  const double p = ldexp(1.0, c.exponent) / 255.0;
  linear[0] = c.r * p;
  linear[1] = c.g * p;
  linear[2] = c.b * p;
}

void ts_rgbe_texel(ts_rgbe c, float texel[4]) {
  texel[0] = (float)(c.r / 255.0);
  texel[1] = (float)(c.g / 255.0);
  texel[2] = (float)(c.b / 255.0);
  texel[3] = (float)((c.exponent + 128) / 255.0);
}

float ts_half_quantize(float x) {
  if (isnan(x)) return x;
  const double a = fabs((double)x);
  if (a >= 65504.0) return x < 0 ? -65504.0f : 65504.0f;
  if (a == 0.0) return x;
  int e;
  (void)frexp(a, &e); /* a = m 2^e, m in [0.5, 1) */
  /* A half has 11 significant bits for normals (exponent >= -14, i.e. a >= 2^-14);
   * below that, a fixed step of 2^-24. */
  const int step_exp = e - 11 < -24 ? -24 : e - 11;
  const double q = nearbyint(ldexp(a, -step_exp)); /* round to nearest even (default mode) */
  const double r = ldexp(q, step_exp);
  return (float)(x < 0 ? -r : r);
}

float ts_u16_412_quantize(float x) {
  double t = (double)x / 16.0;
  if (!(t > 0.0)) t = 0.0; /* also NaN */
  if (t > 1.0) t = 1.0;
  return (float)(nearbyint(t * 65535.0) / 65535.0);
}

float ts_ldr_quantize(float x) {
  double t = x > 0.0f ? 0.5 * pow((double)x, 1.0 / 2.2) : 0.0; /* also NaN */
  if (t > 1.0) t = 1.0;
  return (float)(nearbyint(t * 255.0) / 255.0);
}

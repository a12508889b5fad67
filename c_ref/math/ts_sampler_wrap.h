/* tiershade math: the per-axis addressing rules of llvmpipe (Mesa 22.3.6) texture sampling, shared by the 2D
 * and cube sampler (ts_sampler.c) and the 3D sampler (ts_sampler3d.c), which apply them to
 * each axis alike: gallivm lp_bld_sample_soa.c lp_build_sample_wrap_nearest and
 * lp_build_sample_wrap_linear, lp_bld_arit.c fract_safe, ifloor, itrunc and lerp
 * (llvmpipe_bitexact.md "Texture sampling"), and the double-precision reference with the same
 * addressing. Internal to the two samplers (static functions, include guard). */
#ifndef TS_SAMPLER_WRAP_H
#define TS_SAMPLER_WRAP_H
#include <math.h>

#include "math/ts_math.h"
#include "math/ts_sampler.h"

static int ts_is_pot(int n) { return n > 0 && (n & (n - 1)) == 0; }
static int ts_clampi(int i, int lo, int hi) { return i < lo ? lo : (i > hi ? hi : i); }

/* lp_build_fract_safe: min(u - floor(u), 0x1.fffffep-1); a NaN gives the constant. */
static float ts_fract_safe(float u) {
  float f = u - ts_floorf(u);
  return f < 0x1.fffffep-1f ? f : 0x1.fffffep-1f;
}

/* lp_build_sample_wrap_nearest (float coords, normalized). */
static int ts_wrap_nearest_f(float u, int len, int wrap) {
  float lf = (float)len;
  if (wrap == TS_WRAP_REPEAT || wrap == TS_WRAP_REPEAT_NPOT) {
    if (wrap == TS_WRAP_REPEAT && ts_is_pot(len)) /* ifloor(u*len) & (len-1) */
      return ts_lp_itruncf(ts_floorf(u * lf)) & (len - 1);
    return ts_clampi(ts_lp_itruncf(ts_fract_safe(u) * lf), 0, len - 1); /* itrunc */
  }
  return ts_clampi(ts_lp_itruncf(u * lf), 0, len - 1); /* CLAMP_TO_EDGE: itrunc, clamp */
}

/* lp_build_sample_wrap_linear: the two texels i0, i1 and the weight w of i1. */
static void ts_wrap_linear_f(float u, int len, int wrap, int *i0, int *i1, float *w) {
  float lf = (float)len, c, fl;
  if (wrap == TS_WRAP_REPEAT || wrap == TS_WRAP_REPEAT_NPOT) {
    const int pot = wrap == TS_WRAP_REPEAT && ts_is_pot(len);
    if (!pot) u = u - ts_floorf(u);
    c = u * lf - 0.5f;
    fl = ts_floorf(c);
    *w = c - fl;
    *i0 = ts_lp_itruncf(fl);
    *i1 = (int)((unsigned)*i0 + 1u);
    if (pot) {
      *i0 &= len - 1;
      *i1 &= len - 1;
    } else {
      if (*i0 < 0) *i0 = len - 1;
      if (*i1 == len) *i1 = 0;
    }
  } else {
    c = ts_lp_minf(u * lf, lf);
    c = c - 0.5f;
    c = ts_lp_maxf(c, 0.0f);
    fl = ts_floorf(c);
    *w = c - fl;
    *i0 = ts_lp_itruncf(fl);
    *i1 = *i0 + 1 < len - 1 ? *i0 + 1 : len - 1;
  }
}

/* gallivm lerp(w, a, b) = mad(w, b - a, a) (fused iff llvmpipe fuses: ts_madf). */
static ts_vec4f ts_lerp4_f(float w, ts_vec4f a, ts_vec4f b) {
  return ts_v4f(ts_madf(w, b.x - a.x, a.x), ts_madf(w, b.y - a.y, a.y), ts_madf(w, b.z - a.z, a.z),
                ts_madf(w, b.w - a.w, a.w));
}

/* ---- double reference: the same addressing in double ---- */

static int ts_itrunc_d(double x) {
  if (!(x > -2147483648.0 && x < 2147483647.0)) return x > 0 ? 2147483647 : -2147483647;
  return (int)x;
}

static int ts_wrap_nearest_d(double u, int len, int wrap) {
  if (wrap != TS_WRAP_CLAMP) u -= floor(u);
  return ts_clampi(ts_itrunc_d(floor(u * len)), 0, len - 1);
}

static void ts_wrap_linear_d(double u, int len, int wrap, int *i0, int *i1, double *w) {
  double c, fl;
  if (wrap != TS_WRAP_CLAMP) {
    u -= floor(u);
    c = u * len - 0.5;
    fl = floor(c);
    *w = c - fl;
    *i0 = ts_itrunc_d(fl); /* in [-1, len-1] */
    *i1 = *i0 + 1;
    if (*i0 < 0) *i0 += len;
    if (*i1 >= len) *i1 -= len;
  } else {
    c = u * len;
    c = (c < len ? c : len) - 0.5; /* NaN -> len - 0.5 */
    c = c > 0.0 ? c : 0.0;
    fl = floor(c);
    *w = c - fl;
    *i0 = ts_itrunc_d(fl);
    *i1 = *i0 + 1 < len - 1 ? *i0 + 1 : len - 1;
  }
}

static ts_vec4d ts_lerp4_d(double w, ts_vec4d a, ts_vec4d b) {
  return ts_v4d(a.x + w * (b.x - a.x), a.y + w * (b.y - a.y), a.z + w * (b.z - a.z), a.w + w * (b.w - a.w));
}

#endif

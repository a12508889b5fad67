/* tiershade math: RGBA32F texture sampling, mirror of llvmpipe (Mesa 22.3.6) SoA float path.
 * Addressing read in gallivm lp_bld_sample_soa.c (lp_build_sample_wrap_nearest,
 * lp_build_sample_wrap_linear), lp_bld_sample.c (lp_build_cube_lookup,
 * lp_build_cube_imapos) and lp_bld_arit.c (lerp, fract_safe, ifloor, itrunc).
 * LINEAR and cube facts also in /work/shared/docs/llvmpipe_bitexact.md;
 * everything re-verified bit for bit against the driver (docs/c_math_layer.md).
 */
#include "math/ts_sampler.h"
#include "math/ts_sampler_wrap.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

static uint32_t fb(float f) {
  uint32_t u;
  memcpy(&u, &f, 4);
  return u;
}
static float bf(uint32_t u) {
  float f;
  memcpy(&f, &u, 4);
  return f;
}
/* DAZ: denormal -> zero of the same sign (what SSE compares see under MXCSR.DAZ) */
static float daz(float x) { return (fb(x) & 0x7f800000u) ? x : bf(fb(x) & 0x80000000u); }

static ts_vec4f texel(const float *tx, int w, int x, int y) {
  const float *p = tx + ((size_t)y * (size_t)w + (size_t)x) * 4u;
  return ts_v4f(p[0], p[1], p[2], p[3]);
}

ts_vec4f ts_texelFetchf(const ts_tex2d *t, int x, int y) {
  if (x < 0 || y < 0 || x >= t->w || y >= t->h) return ts_v4f(0.0f, 0.0f, 0.0f, 0.0f);
  return texel(t->texels, t->w, x, y);
}

/* ---------------------------------------------------------------------------- */
/* float32, llvmpipe-exact                                                       */
/* ---------------------------------------------------------------------------- */

/* Fetch that never reads outside the image (llvmpipe only produces in-range
 * indices for finite coordinates; NaN/inf coordinates are clamped here). */
static ts_vec4f fetch_safe(const float *tx, int w, int h, int x, int y) {
  return texel(tx, w, ts_clampi(x, 0, w - 1), ts_clampi(y, 0, h - 1));
}

static ts_vec4f sample2d_f(const float *tx, int w, int h, int wrap_s, int wrap_t, int filter, float u, float v) {
  int x0, x1, y0, y1;
  float wx, wy;
  if (filter == TS_FILTER_NEAREST)
    return fetch_safe(tx, w, h, ts_wrap_nearest(u, w, wrap_s), ts_wrap_nearest(v, h, wrap_t));
  ts_wrap_linear(u, w, wrap_s, &x0, &x1, &wx);
  ts_wrap_linear(v, h, wrap_t, &y0, &y1, &wy);
  return ts_lerp4(wy, ts_lerp4(wx, fetch_safe(tx, w, h, x0, y0), fetch_safe(tx, w, h, x1, y0)),
                  ts_lerp4(wx, fetch_safe(tx, w, h, x0, y1), fetch_safe(tx, w, h, x1, y1)));
}

ts_vec4f ts_texture2Df(const ts_tex2d *t, ts_vec2f uv) {
  return sample2d_f(t->texels, t->w, t->h, t->wrap_s, t->wrap_t, t->filter, uv.x, uv.y);
}

/* lp_build_cube_lookup (non-seamless, no derivatives), read in lp_bld_sample.c:
 * as_gt_at = |x| > |y| (unordered: NaN -> true); mx = maxps(|x|,|y|);
 * ar_ge = |z| >= mx (unordered); major = ar_ge ? Z : (as_gt_at ? X : Y).
 * The face is negative iff the SIGN BIT of the major coordinate is set (-0 -> -face);
 * minor coords are mirrored by XOR-ing sign bits: sc = {+X:-z, -X:z, Y:x, +Z:x, -Z:-x},
 * tc = {X:-y, +Y:z, -Y:-z, Z:-y}.  s = sc * ima + 0.5 (mul, add: no mad) with
 * ima = |ma| > 0 (unordered) ? 0.5/|ma| : 0, so a zero direction samples the
 * centre of the +-Z face. */
ts_vec4f ts_textureCubef(const ts_texcube *c, ts_vec3f d) {
  const uint32_t S = 0x80000000u;
  float ax = bf(fb(d.x) & ~S), ay = bf(fb(d.y) & ~S), az = bf(fb(d.z) & ~S);
  float mx = ts_lp_maxf(ax, ay);
  int sel_x = !(daz(ax) <= daz(ay)); /* |x| UGT |y| */
  int sel_z = !(daz(az) < mx); /* |z| UGE mx  */
  float ma = sel_z ? d.z : (sel_x ? d.x : d.y);
  uint32_t sg = fb(ma) & S;
  uint32_t sc, tc;
  int face;
  if (sel_z) {
    face = 4;
    sc = fb(d.x) ^ sg;
    tc = fb(d.y) ^ S;
  } else if (sel_x) {
    face = 0;
    sc = fb(d.z) ^ S ^ sg;
    tc = fb(d.y) ^ S;
  } else {
    face = 2;
    sc = fb(d.x);
    tc = fb(d.z) ^ sg;
  }
  face += sg ? 1 : 0;
  {
    float ama = bf(fb(ma) & ~S);
    float ima = !(daz(ama) <= 0.0f) ? 0.5f / ama : 0.0f; /* |ma| UGT 0, else 0 */
    float s = bf(sc) * ima + 0.5f, t = bf(tc) * ima + 0.5f;
    return sample2d_f(c->faces[face], c->size, c->size, TS_WRAP_CLAMP, TS_WRAP_CLAMP, c->filter, s, t);
  }
}

/* ---------------------------------------------------------------------------- */
/* double reference: same addressing, computed in double                         */
/* ---------------------------------------------------------------------------- */

static ts_vec4d texel_d(const float *tx, int w, int h, int x, int y) {
  ts_vec4f p = fetch_safe(tx, w, h, x, y);
  return ts_v4d(p.x, p.y, p.z, p.w);
}

static ts_vec4d sample2d_d(const float *tx, int w, int h, int wrap_s, int wrap_t, int filter, double u, double v) {
  int x0, x1, y0, y1;
  double wx, wy;
  if (filter == TS_FILTER_NEAREST)
    return texel_d(tx, w, h, ts_wrap_nearest_d(u, w, wrap_s), ts_wrap_nearest_d(v, h, wrap_t));
  ts_wrap_linear_d(u, w, wrap_s, &x0, &x1, &wx);
  ts_wrap_linear_d(v, h, wrap_t, &y0, &y1, &wy);
  return ts_lerp4d(wy, ts_lerp4d(wx, texel_d(tx, w, h, x0, y0), texel_d(tx, w, h, x1, y0)),
                   ts_lerp4d(wx, texel_d(tx, w, h, x0, y1), texel_d(tx, w, h, x1, y1)));
}

ts_vec4d ts_texture2Dd(const ts_tex2d *t, ts_vec2d uv) {
  return sample2d_d(t->texels, t->w, t->h, t->wrap_s, t->wrap_t, t->filter, uv.x, uv.y);
}

ts_vec4d ts_textureCubed(const ts_texcube *c, ts_vec3d d) {
  /* same face rule as the float mirror, sign taken from the sign bit */
  double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z), ma, sc, tc;
  int face;
  if (az >= (ax > ay ? ax : ay)) {
    face = 4;
    ma = d.z;
    sc = signbit(ma) ? -d.x : d.x;
    tc = -d.y;
  } else if (ax > ay) {
    face = 0;
    ma = d.x;
    sc = signbit(ma) ? d.z : -d.z;
    tc = -d.y;
  } else {
    face = 2;
    ma = d.y;
    sc = d.x;
    tc = signbit(ma) ? -d.z : d.z;
  }
  face += signbit(ma) ? 1 : 0;
  ma = fabs(ma) > 0.0 ? 0.5 / fabs(ma) : 0.0;
  return sample2d_d(c->faces[face], c->size, c->size, TS_WRAP_CLAMP, TS_WRAP_CLAMP, c->filter, sc * ma + 0.5,
                    tc * ma + 0.5);
}

/* tiershade math: RGBA32F texture sampling, mirror of llvmpipe (Mesa 22.3.6) SoA float path.
 * Addressing read in gallivm lp_bld_sample_soa.c (lp_build_sample_wrap_nearest,
 * lp_build_sample_wrap_linear), lp_bld_sample.c (lp_build_cube_lookup,
 * lp_build_cube_imapos) and lp_bld_arit.c (lerp, fract_safe, ifloor, itrunc).
 * LINEAR and cube facts also in /work/shared/docs/llvmpipe_bitexact.md;
 * everything re-verified bit for bit against the driver (docs/c_math_layer.md).
 */
#include "math/ts_sampler.h"
#include "math/ts_bits.h"
#include "math/ts_sampler_wrap.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

static ts_vec4f texel(const float *tx, int w, int x, int y) {
  const float *p = tx + ((size_t)y * (size_t)w + (size_t)x) * 4u;
  return ts_v4f(p[0], p[1], p[2], p[3]);
}

ts_vec4f ts_texelFetchf(const ts_tex2d *t, int x, int y) {
  if (x < 0 || y < 0 || x >= t->w || y >= t->h) return ts_v4f(0.0f, 0.0f, 0.0f, 0.0f);
  return texel(t->texels, t->w, x, y);
}

/* One 2D lookup in precision S (f: llvmpipe-exact, d: the double reference; R its real type, V4
 * the texel type): NEAREST, or LINEAR as lerp(wy, lerp(wx, t00, t10), lerp(wx, t01, t11)). */
#define TS_SAMPLE2D(S, R, V4)                                                                           \
  static V4 sample2d_##S(const float *tx, int w, int h, int wrap_s, int wrap_t, int filter, R u, R v) { \
    int x0, x1, y0, y1;                                                                                 \
    R wx, wy;                                                                                           \
    if (filter == TS_FILTER_NEAREST)                                                                    \
      return fetch_##S(tx, w, h, ts_wrap_nearest_##S(u, w, wrap_s), ts_wrap_nearest_##S(v, h, wrap_t)); \
    ts_wrap_linear_##S(u, w, wrap_s, &x0, &x1, &wx);                                                    \
    ts_wrap_linear_##S(v, h, wrap_t, &y0, &y1, &wy);                                                    \
    return ts_lerp4_##S(wy, ts_lerp4_##S(wx, fetch_##S(tx, w, h, x0, y0), fetch_##S(tx, w, h, x1, y0)), \
                        ts_lerp4_##S(wx, fetch_##S(tx, w, h, x0, y1), fetch_##S(tx, w, h, x1, y1)));    \
  }

/* ---------------------------------------------------------------------------- */
/* float32, llvmpipe-exact                                                       */
/* ---------------------------------------------------------------------------- */

/* Fetch that never reads outside the image (llvmpipe only produces in-range
 * indices for finite coordinates; NaN/inf coordinates are clamped here). */
static ts_vec4f fetch_f(const float *tx, int w, int h, int x, int y) {
  return texel(tx, w, ts_clampi(x, 0, w - 1), ts_clampi(y, 0, h - 1));
}

TS_SAMPLE2D(f, float, ts_vec4f)

ts_vec4f ts_texture2Df(const ts_tex2d *t, ts_vec2f uv) {
  return sample2d_f(t->texels, t->w, t->h, t->wrap_s, t->wrap_t, t->filter, uv.x, uv.y);
}

/* ---- mip chains: llvmpipe's level of detail (Mesa 22.3.6 gallivm, default GALLIVM_PERF) ---- */

/* lp_bld_arit.c lp_build_fast_log2: ipart = lp_build_extract_exponent(x, -1) = biased exponent -
 * 128 (as a float), fpart = lp_build_extract_mantissa(x) = the mantissa bits under exponent 0,
 * in [1, 2); their sum. */
float ts_fast_log2f(float x) {
  const uint32_t b = ts_fbits(x);
  const int e = (int)((b & 0x7f800000u) >> 23) - 128;
  return (float)e + ts_bitsf((b & 0x007fffffu) | 0x3f800000u);
}

void ts_mip_select(const ts_tex2d *t, ts_vec4f g, int *l0, int *l1, float *weight, float *lod) {
  /* lp_build_rho, implicit derivatives, no_rho_approx (GALLIVM_PERF without rho_approx), 2D:
   * ddx_ddy = (ds/dx, ds/dy, dt/dx, dt/dy) * (w, w, h, h) of level 0, squared; rho^2 =
   * max(ds/dx^2 + dt/dx^2, ds/dy^2 + dt/dy^2) (lp_build_max: maxps). */
  const float fw = (float)t->w, fh = (float)t->h;
  float a = g.x * fw, b = g.y * fw, c = g.z * fh, d = g.w * fh;
  a = a * a;
  b = b * b;
  c = c * c;
  d = d * d;
  ts_mip_select_rho2(t, ts_lp_maxf(a + c, b + d), l0, l1, weight, lod);
}

void ts_mip_select_rho2(const ts_tex2d *t, float rho2, int *l0, int *l1, float *weight, float *lod) {
  const int last = t->mip_levels - 1;
  *weight = 0.0f;
  if (t->mip_filter == TS_MIP_NEAREST) {
    /* lp_build_lod_selector's shortcut (no bias, no min/max LOD clamp: GL's defaults):
     * lp_build_ilog2_sqrt = (biased exponent - 126) >> 1 (arithmetic), then
     * lp_build_nearest_mip_level clamps it to [0, last]. */
    const int ip = ((int)((ts_fbits(rho2) & 0x7f800000u) >> 23) - 126) >> 1;
    *lod = (float)ip;
    *l0 = *l1 = ip < 0 ? 0 : (ip > last ? last : ip);
    return;
  }
  /* LINEAR (no brilinear): lod = 0.5 * fast_log2(rho^2); lp_build_ifloor_fract (SSE4.1 round:
   * floor, then a - floor); lp_build_linear_mip_levels: level0 < first -> both first, weight 0;
   * level0 >= last -> both last, weight 0. */
  const float l = ts_fast_log2f(rho2) * 0.5f;
  const float fl = ts_floorf(l);
  float f = l - fl;
  int i0 = ts_lp_itruncf(fl), i1 = (int)((unsigned)i0 + 1u);
  *lod = l;
  if (i0 < 0) i0 = i1 = 0, f = 0.0f;
  if (i0 >= last) i0 = i1 = last, f = 0.0f;
  *l0 = i0;
  *l1 = i1;
  *weight = f;
}

ts_tex2d ts_mip_level(const ts_tex2d *t, int level) {
  ts_tex2d r = *t;
  r.mip_levels = 1;
  r.mip_filter = TS_MIP_NONE;
  if (level > 0) {
    r.w = t->mip_w[level];
    r.h = t->mip_h[level];
    r.texels = t->mip_texels[level];
  }
  /* the addressing of level 0's size (lp_sampler_static_texture_state: pot_width of width0) */
  if (t->wrap_s == TS_WRAP_REPEAT && !ts_is_pot(t->w)) r.wrap_s = TS_WRAP_REPEAT_NPOT;
  if (t->wrap_t == TS_WRAP_REPEAT && !ts_is_pot(t->h)) r.wrap_t = TS_WRAP_REPEAT_NPOT;
  return r;
}

/* lp_bld_sample_soa.c lp_build_sample_mipmap: level0's filtered texel; with a linear mip filter and
 * a weight > 0 also level1's, and lerp(weight, c0, c1) = mad(weight, c1 - c0, c0) per channel. */
ts_vec4f ts_texture2D_gradf(const ts_tex2d *t, ts_vec2f uv, const ts_vec4f *grad) {
  if (!grad || t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return ts_texture2Df(t, uv);
  int l0, l1;
  float w, lod;
  ts_mip_select(t, *grad, &l0, &l1, &w, &lod);
  const ts_tex2d a = ts_mip_level(t, l0);
  const ts_vec4f c0 = ts_texture2Df(&a, uv);
  if (!(w > 0.0f)) return c0;
  const ts_tex2d b = ts_mip_level(t, l1);
  return ts_lerp4_f(w, c0, ts_texture2Df(&b, uv));
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
  float ax = ts_bitsf(ts_fbits(d.x) & ~S), ay = ts_bitsf(ts_fbits(d.y) & ~S), az = ts_bitsf(ts_fbits(d.z) & ~S);
  float mx = ts_lp_maxf(ax, ay);
  int sel_x = !(ts_daz(ax) <= ts_daz(ay)); /* |x| UGT |y| */
  int sel_z = !(ts_daz(az) < mx); /* |z| UGE mx  */
  float ma = sel_z ? d.z : (sel_x ? d.x : d.y);
  uint32_t sg = ts_fbits(ma) & S;
  uint32_t sc, tc;
  int face;
  if (sel_z) {
    face = 4;
    sc = ts_fbits(d.x) ^ sg;
    tc = ts_fbits(d.y) ^ S;
  } else if (sel_x) {
    face = 0;
    sc = ts_fbits(d.z) ^ S ^ sg;
    tc = ts_fbits(d.y) ^ S;
  } else {
    face = 2;
    sc = ts_fbits(d.x);
    tc = ts_fbits(d.z) ^ sg;
  }
  face += sg ? 1 : 0;
  {
    float ama = ts_bitsf(ts_fbits(ma) & ~S);
    float ima = !(ts_daz(ama) <= 0.0f) ? 0.5f / ama : 0.0f; /* |ma| UGT 0, else 0 */
    float s = ts_bitsf(sc) * ima + 0.5f, t = ts_bitsf(tc) * ima + 0.5f;
    return sample2d_f(c->faces[face], c->size, c->size, TS_WRAP_CLAMP, TS_WRAP_CLAMP, c->filter, s, t);
  }
}

/* ---------------------------------------------------------------------------- */
/* double reference: same addressing, computed in double                         */
/* ---------------------------------------------------------------------------- */

static ts_vec4d fetch_d(const float *tx, int w, int h, int x, int y) {
  ts_vec4f p = fetch_f(tx, w, h, x, y);
  return ts_v4d(p.x, p.y, p.z, p.w);
}

TS_SAMPLE2D(d, double, ts_vec4d)

ts_vec4d ts_texture2Dd(const ts_tex2d *t, ts_vec2d uv) {
  return sample2d_d(t->texels, t->w, t->h, t->wrap_s, t->wrap_t, t->filter, uv.x, uv.y);
}

/* The double reference of ts_texture2D_gradf: the same levels and weight (chosen in float as
 * llvmpipe chooses them), each level filtered and the two blended in double. */
ts_vec4d ts_texture2D_gradd(const ts_tex2d *t, ts_vec2d uv, const ts_vec4f *grad) {
  if (!grad || t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return ts_texture2Dd(t, uv);
  int l0, l1;
  float w, lod;
  ts_mip_select(t, *grad, &l0, &l1, &w, &lod);
  return ts_mip_blendd(t, uv, l0, l1, w);
}

ts_vec4d ts_mip_blendd(const ts_tex2d *t, ts_vec2d uv, int l0, int l1, float w) {
  const ts_tex2d a = ts_mip_level(t, l0), b = ts_mip_level(t, l1);
  const ts_vec4d c0 = ts_texture2Dd(&a, uv);
  if (!(w > 0.0f)) return c0;
  const ts_vec4d c1 = ts_texture2Dd(&b, uv);
  const double wd = w;
  return ts_v4d(c0.x + wd * (c1.x - c0.x), c0.y + wd * (c1.y - c0.y), c0.z + wd * (c1.z - c0.z),
                c0.w + wd * (c1.w - c0.w));
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

/* tiershade math: texture lookups with EXPLICIT derivatives (GLSL ES 3.00 textureGrad, ESSL 1.00
 * texture2DGradEXT of EXT_shader_texture_lod) on a 2D mip chain: the llvmpipe mirror (f), its
 * double reference (d) and the interval of every result the GLES 3.0 spec allows (iv).
 *
 * llvmpipe (Mesa 22.3.6 gallivm), read in lp_bld_sample.c lp_build_rho (the `derivs` branch) and
 * lp_build_lod_selector, lp_bld_sample_soa.c lp_build_sample_soa_code (num_lods), lp_bld_nir.c
 * (the sample key of nir_texop_txd):
 *  - a lookup with derivatives (or an explicit LOD or bias) and a mip filter gets one LOD per
 *    PIXEL: lp_build_sample_soa_code sets num_lods = num_mips = the vector length when
 *    `lod_property == PER_ELEMENT || explicit_lod || lod_bias || derivs`, whatever the PER_QUAD
 *    property lp_bld_nir.c gives txd in a fragment shader; so lp_build_rho's rho_per_quad is
 *    false and each pixel's level comes from its own derivatives (checked: taking a quad
 *    neighbour's instead fails 38-46 % of conform's random grid);
 *  - rho, no_rho_approx (the default: GALLIVM_PERF without rho_approx) and dims 2:
 *    ddx[i] = (size_i * dPdx_i)^2, ddy[i] = (size_i * dPdy_i)^2 (lp_build_mul, twice),
 *    rho^2 = max(ddx[0] + ddx[1], ddy[0] + ddy[1]) (lp_build_add, lp_build_max = maxps): the same
 *    operations in the same order as the implicit quad path (ts_mip_select's a..d);
 *  - unlike the implicit path, a rho^2 that is Inf or NaN (an overflowed square, a NaN or Inf
 *    derivative; lp_build_is_inf_or_nan: exponent all ones) is replaced by 0 (lp_build_select),
 *    so such a pixel is magnified: level 0 (checked by conform's hard cases);
 *  - then lp_build_lod_selector as for implicit derivatives (ts_mip_select_rho2: ilog2_sqrt for
 *    a NEAREST mip filter, 0.5 * fast_log2 and ifloor_fract for LINEAR, no brilinear).
 * So the explicit lookup is the implicit one's (ts_texture2D_gradf) with the pixel's own
 * (dPdx, dPdy) and that one select.
 *
 * The GLES 3.0.6 spec, section 3.8.10 (Texture Minification, equations 3.17-3.21): with
 * u = s w, v = t h, rho_exact = max(sqrt(ux^2 + vx^2), sqrt(uy^2 + vy^2)) may be replaced by any
 * f with max(m_u, m_v) <= f <= m_u + m_v, m_u = max(|ux|, |uy|), m_v = max(|vx|, |vy|); lambda =
 * log2(f) (no bias, the default [-1000, 1000] LOD clamp); lambda <= 0 magnifies (level 0, mag
 * filter = the min filter's image part here); LINEAR_MIPMAP_*: levels floor(lambda) and + 1,
 * weight frac(lambda); *_MIPMAP_NEAREST: level 0 for lambda <= 1/2, else ceil(lambda + 1/2) - 1;
 * both clamped to the chain. ts_texture2DGradiv takes lambda in [log2(max(m_u, m_v)) - e,
 * log2(m_u + m_v) + e], e = 1/16 for the unspecified log2 (llvmpipe's
 * piecewise-linear fast_log2 is up to 0.043 below log2 on lambda; dEQP's texture tests allow
 * lodBits 6 = 1/64), and joins every level those lambdas can select (docs/conformance.md,
 * "Explicit derivatives"). */
#include "math/ts_interval.h"
#include "math/ts_sampler.h"

#include <float.h>
#include <math.h>

/* lp_build_rho's derivs branch (no_rho_approx, 2D) for GLSL's (dPdx, dPdy): rho^2, 0 if not finite */
static float explicit_rho2(const ts_tex2d *t, ts_vec4f d) {
  const float fw = (float)t->w, fh = (float)t->h;
  float sx = fw * d.x, tx = fh * d.y, sy = fw * d.z, ty = fh * d.w;
  sx = sx * sx;
  tx = tx * tx;
  sy = sy * sy;
  ty = ty * ty;
  const float rho2 = ts_lp_maxf(sx + tx, sy + ty);
  return isfinite(rho2) ? rho2 : 0.0f;
}

/* lp_bld_sample_soa.c lp_build_sample_mipmap, as ts_texture2D_gradf: level l0's lookup; with a
 * weight > 0 also l1's, and lerp(weight, c0, c1) per channel = mad(weight, c1 - c0, c0), fused iff llvmpipe fuses (ts_madf, as ts_sampler_wrap.h's ts_lerp4_f). */
ts_vec4f ts_texture2DGradf(const ts_tex2d *t, ts_vec2f uv, ts_vec4f dpdx_dpdy) {
  if (t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return ts_texture2Df(t, uv);
  int l0, l1;
  float w, lod;
  ts_mip_select_rho2(t, explicit_rho2(t, dpdx_dpdy), &l0, &l1, &w, &lod);
  const ts_tex2d a = ts_mip_level(t, l0);
  const ts_vec4f c0 = ts_texture2Df(&a, uv);
  if (!(w > 0.0f)) return c0;
  const ts_tex2d b = ts_mip_level(t, l1);
  const ts_vec4f c1 = ts_texture2Df(&b, uv);
  return ts_v4f(ts_madf(w, c1.x - c0.x, c0.x), ts_madf(w, c1.y - c0.y, c0.y), ts_madf(w, c1.z - c0.z, c0.z),
                ts_madf(w, c1.w - c0.w, c0.w));
}

/* The double reference: the same levels and weight (chosen in float as llvmpipe chooses them),
 * each level filtered and the two blended in double. */
ts_vec4d ts_texture2DGradd(const ts_tex2d *t, ts_vec2d uv, ts_vec4f dpdx_dpdy) {
  if (t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return ts_texture2Dd(t, uv);
  int l0, l1;
  float w, lod;
  ts_mip_select_rho2(t, explicit_rho2(t, dpdx_dpdy), &l0, &l1, &w, &lod);
  return ts_mip_blendd(t, uv, l0, l1, w);
}

/* [lo, hi] of lambda for one pixel's (dPdx, dPdy); returns 0 when a derivative is not finite
 * or a squared footprint u^2 + v^2 is past the float32 range (the spec then promises nothing of
 * the level: an implementation computes rho in float, and llvmpipe 22.3 turns an overflowed
 * rho^2 into 0, i.e. level 0 where the exact rho gives the last level). Computed in double. */
static int lambda_range(const ts_tex2d *t, ts_vec4f d, double *lo, double *hi) {
  const double ux = fabs((double)d.x * t->w), vx = fabs((double)d.y * t->h);
  const double uy = fabs((double)d.z * t->w), vy = fabs((double)d.w * t->h);
  if (!isfinite(ux) || !isfinite(vx) || !isfinite(uy) || !isfinite(vy)) return 0;
  if (ux * ux + vx * vx >= (double)FLT_MAX || uy * uy + vy * vy >= (double)FLT_MAX) return 0;
  const double mu = fmax(ux, uy), mv = fmax(vx, vy);
  const double e = 1.0 / 16.0;
  /* log2(0) = -inf: magnified, level 0 (any float32 derivative times a size is > 2^-160) */
  *lo = fmax(mu, mv) > 0 ? log2(fmax(mu, mv)) - e : -1e9;
  *hi = mu + mv > 0 ? log2(mu + mv) + e : -1e9;
  return 1;
}

/* the level a NEAREST mip filter selects at lambda (unclamped above) */
static double nearest_level(double l) { return l <= 0.5 ? 0.0 : ceil(l + 0.5) - 1.0; }

ts_vec4iv ts_texture2DGradiv(const ts_tex2d *t, ts_vec2iv uv, ts_vec4f dpdx_dpdy) {
  if (t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return ts_texture2Div(t, uv);
  const int last = t->mip_levels - 1;
  double lo = 0, hi = 0;
  const int any = !lambda_range(t, dpdx_dpdy, &lo, &hi);
  int l0 = 0, l1 = last;
  if (!any) {
    /* LINEAR: floor(lambda) .. floor(lambda) + 1; NEAREST: the rounded level (3.8.10) */
    const double a = t->mip_filter == TS_MIP_LINEAR ? floor(lo) : nearest_level(lo);
    const double b = t->mip_filter == TS_MIP_LINEAR ? floor(hi) + 1.0 : nearest_level(hi);
    l0 = a < 0 ? 0 : (a > last ? last : (int)a);
    l1 = b < 0 ? 0 : (b > last ? last : (int)b);
  }
  ts_vec4iv r = ts_texture2Div(t, uv);
  if (l0 > 0) {
    const ts_tex2d lv = ts_mip_level(t, l0);
    r = ts_texture2Div(&lv, uv);
  }
  for (int l = l0 + 1; l <= l1; ++l) {
    const ts_tex2d lv = ts_mip_level(t, l);
    const ts_vec4iv s = ts_texture2Div(&lv, uv);
    r = ts_v4iv(ts_ivjoin(r.x, s.x), ts_ivjoin(r.y, s.y), ts_ivjoin(r.z, s.z), ts_ivjoin(r.w, s.w));
  }
  if (l1 > l0) {
    /* a value between two levels' lookups: mix(c0, c1, w) in float32, a few ULP of the larger
     * magnitude outside their hull at most (as ts_texture2Div's lerps) */
    ts_iv *c[4] = {&r.x, &r.y, &r.z, &r.w};
    for (int k = 0; k < 4; ++k) {
      if (!(c[k]->lo <= c[k]->hi)) continue;
      const double m = fmax(fabs((double)c[k]->lo), fabs((double)c[k]->hi));
      const double e = m > 0 ? 4.0 * ldexp(1.0, ilogb(m) - 23) : 0.0;
      ts_iv w = ts_ivrange(nextafterf((float)((double)c[k]->lo - e), -INFINITY),
                           nextafterf((float)((double)c[k]->hi + e), INFINITY));
      w.nan = c[k]->nan;
      *c[k] = w;
    }
  }
  return r;
}

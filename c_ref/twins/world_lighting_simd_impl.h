/* tiershade twins: the world_lighting twin (c_ref/twins/world_lighting_impl.h and the common_rnm/lightmap/envmap/fog
 * headers, float32) on TSV_W pixels at once, in SoA, statement by statement, so that every lane
 * gives the scalar twin's bits. Combos stay scalar `if`s; the per-pixel "full envmap" test on
 * the record's contrast/saturation/R0 becomes a select. Included by world_lighting_batch.c after
 * ts_simd.h, ts_simd_sampler.h and ts_simd_sampler_nearest.h (VFN(tex2d): NEAREST or LINEAR). */

#include "twins/simd_common.h"

/* common_lightmap.h */
/* the decode of a lightmap texel t */
static V3v VFN(wl_lightmap_decode)(const wl_variant *v, V4v t) {
  const V3v rgb = VFN(v3)(t.x, t.y, t.z);
  if (v->tier == TS_TIER_ID_PS20 && v->encoding == WL_LM_LDR) {
    const V3v s = VFN(scale3)(rgb, VFN(splat)(2.0f));
    const V3v q = VFN(mul3)(s, s);
    const VF four = VFN(splat)(4.0f);
    return VFN(v3)(VFN(min)(q.x, four), VFN(min)(q.y, four), VFN(min)(q.z, four));
  }
  if (v->encoding == WL_LM_412) return VFN(scale3)(rgb, VFN(splat)(16.0f));
  if (v->encoding == WL_LM_LDR) {
    const V3v s = VFN(scale3)(rgb, VFN(splat)(2.0f));
    const VF g = VFN(splat)(2.2f), m = VFN(splat)(TS_POW_TINY_F);
    return VFN(v3)(VFN(pow)(VFN(max)(s.x, m), g), VFN(pow)(VFN(max)(s.y, m), g), VFN(pow)(VFN(max)(s.z, m), g));
  }
  if (v->encoding == WL_LM_RGBE) return VFN(scale3)(rgb, VFN(exp2)(t.w * 255.0f - 128.0f));
  return rgb;
}
static V3v VFN(wl_lightmap)(const wl_variant *v, const ts_tex2d *lm, VF u, VF w, VF ox, VF oy, float k) {
  const VF kv = VFN(splat)(k);
  return VFN(wl_lightmap_decode)(v, VFN(tex2d)(lm, u + kv * ox, w + kv * oy));
}
/* the three RNM lightmaps, k = 1, 2, 3: each its own texture2D at uv + k * offset
 * (ts_simd_sampler_nearest.h tex2d_n shares what their addressing has in common) */
static void VFN(wl_lightmap3)(const wl_variant *v, const ts_tex2d *lm, VF u, VF w, VF ox, VF oy, V3v *l) {
  VF us[3], ws[3];
  V4v t[3];
  for (int k = 0; k < 3; ++k) {
    const VF kv = VFN(splat)((float)(k + 1));
    us[k] = u + kv * ox;
    ws[k] = w + kv * oy;
  }
  VFN(tex2d_n)(lm, 3, us, ws, t);
  for (int k = 0; k < 3; ++k) l[k] = VFN(wl_lightmap_decode)(v, t[k]);
}

/* common_rnm.h itself, on lanes */
#include "math/ts_generic_lanes.h"
#include "common/common_rnm.h"

/* common_envmap.h */
TSV_INL V3v VFN(reflect_unnormalized)(V3v N, V3v E) {
  return VFN(sub3)(VFN(scale3)(N, 2.0f * VFN(dot3)(N, E)), VFN(scale3)(E, VFN(dot3)(N, N)));
}
/* mix() as Mesa compiles it, unfused (common_envmap.h): s * ((1 - c) + s*c) and
 * luma*(1 - t) + s*t */
TSV_INL V3v VFN(envmap_contrast)(V3v s, VF contrast) {
  const VF u = 1.0f - contrast;
  return VFN(v3)((u + s.x * contrast) * s.x, (u + s.y * contrast) * s.y, (u + s.z * contrast) * s.z);
}
TSV_INL V3v VFN(envmap_saturation)(V3v s, VF saturation) {
  const VF luma = VFN(dot3)(s, VFN(v3)(VFN(splat)(0.299f), VFN(splat)(0.587f), VFN(splat)(0.114f)));
  const VF a = luma * (1.0f - saturation);
  return VFN(v3)(a + s.x * saturation, a + s.y * saturation, a + s.z * saturation);
}
TSV_INL VF VFN(cosine_between)(V3v N, V3v E) {
  return VFN(dot3)(N, E) *
      VFN(inversesqrt)(VFN(max)(VFN(dot3)(N, N) * VFN(dot3)(E, E), VFN(splat)(1.0e-30f))); /* 0 in fp16 */
}
TSV_INL VF VFN(wl_fresnel)(VF NdotV, VF one_minus_r0, VF r0) {
  const VF x = 1.0f - VFN(saturate)(NdotV);
  const VF x2 = x * x;
  return (x2 * x2) * (x * one_minus_r0) + r0;
}

static V4v VFN(wl_block)(const wl_variant *v, const wl_batch_input *in, const wl_textures *tx, const size_t *pix) {
  const VF zero = VFN(splat)(0.0f), one = VFN(splat)(1.0f);
  const V4v uv = TSV_REC(in, WL_SLOT_UV, pix);
  const V4v lm_offset = TSV_REC(in, WL_SLOT_LM_OFFSET, pix);
  const V4v tint_scale = TSV_REC(in, WL_SLOT_TINT_SCALE, pix);
  V4v base;

  V3v diffuse, n = VFN(v3)(zero, zero, one);
  V4v bump = {zero, zero, zero, zero};
  if (v->bumpmap == WL_BUMP_NONE) {
    base = VFN(tex2d_grad)(tx->base, uv.x, uv.y, tx->uv_grad, tx->uv_grad_stride, pix);
    diffuse = VFN(wl_lightmap)(v, tx->lightmap, uv.z, uv.w, lm_offset.x, lm_offset.y, 0.0f);
  } else {
    /* base and bump: one uv, one level selection when their chains match */
    VFN(tex2d_grad2)(tx->base, tx->normalmap, uv.x, uv.y, tx->uv_grad, tx->uv_grad_stride, pix, &base, &bump);
    V3v lm[3];
    VFN(wl_lightmap3)(v, tx->lightmap, uv.z, uv.w, lm_offset.x, lm_offset.y, lm);
    const V3v l0 = lm[0], l1 = lm[1], l2 = lm[2];
    const V3v t = VFN(xyz)(bump);
    if (v->bumpmap == WL_BUMP_RNM) {
      n = VFN(sub3)(VFN(scale3)(t, VFN(splat)(2.0f)), VFN(v3)(one, one, one));
      diffuse = VFN(rnm_blend)(VFN(rnm_weights)(n), l0, l1, l2);
    } else {
      n = v->tier == TS_TIER_ID_PS20 ? VFN(ssbump_direction)(t) : VFN(ssbump_normal)(t);
      diffuse = VFN(ssbump_blend)(t, l0, l1, l2);
    }
  }
  const V3v base_rgb = VFN(xyz)(base);
  V3v color;
  if (v->envmap) {
    color = VFN(mul3)(base_rgb, VFN(mul3)(diffuse, VFN(xyz)(tint_scale)));
    const V4v env_tint = TSV_REC(in, WL_SLOT_ENV_TINT, pix);
    const V4v env_params = TSV_REC(in, WL_SLOT_ENV_PARAMS, pix);
    V3v N = VFN(xyz)(TSV_REC(in, WL_SLOT_NORMAL, pix));
    if (v->bumpmap != WL_BUMP_NONE) {
      const V3v T = VFN(xyz)(TSV_REC(in, WL_SLOT_TANGENT, pix)), B = VFN(xyz)(TSV_REC(in, WL_SLOT_BINORMAL, pix));
      N = VFN(add3)(VFN(add3)(VFN(scale3)(T, n.x), VFN(scale3)(B, n.y)), VFN(scale3)(N, n.z));
    }
    const V3v E = VFN(xyz)(TSV_REC(in, WL_SLOT_EYE, pix));
    const V4v env4 = VFN(textureCube)(tx->envmap, VFN(reflect_unnormalized)(N, E));
    const VF fp16_max = VFN(splat)(65504.0f);
    const V3v env = VFN(scale3)(
        VFN(v3)(VFN(min)(env4.x, fp16_max), VFN(min)(env4.y, fp16_max), VFN(min)(env4.z, fp16_max)), env_tint.w);
    const V3v tint = VFN(xyz)(env_tint);
    V3v spec;
    if (v->envmapmask == WL_MASK_TEXTURE) {
      const V4v m = VFN(tex2d_grad)(tx->envmap_mask, uv.x, uv.y, tx->uv_grad, tx->uv_grad_stride, pix);
      spec = VFN(mul3)(env, VFN(mul3)(VFN(xyz)(m), tint));
    } else if (v->envmapmask == WL_MASK_NORMAL_ALPHA) {
      spec = VFN(mul3)(env, VFN(scale3)(tint, bump.w));
    } else if (v->envmapmask == WL_MASK_INV_BASE_ALPHA) {
      spec = VFN(mul3)(env, VFN(scale3)(tint, 1.0f - base.w));
    } else {
      spec = VFN(mul3)(env, tint);
    }
    /* full = tier != sm3 || contrast != 0 || saturation != 1 || R0 != 1 (per lane, unordered) */
    const VI full = v->tier != TS_TIER_ID_SM3
        ? VFN(spliti)(-1)
        : (env_params.x != 0.0f) | (env_params.y != 1.0f) | (env_params.w != 1.0f);
    V3v s2 = VFN(envmap_saturation)(VFN(envmap_contrast)(spec, env_params.x), env_params.y);
    const VF NdotV = v->tier == TS_TIER_ID_PS20 ? VFN(cosine_between)(N, E)
                                                : VFN(dot3)(VFN(safe_normalize)(N), VFN(safe_normalize)(E));
    s2 = VFN(scale3)(s2, VFN(wl_fresnel)(NdotV, env_params.z, env_params.w));
    spec = VFN(sel3)(full, s2, spec);
    color = VFN(scale3)(VFN(add3)(color, spec), tint_scale.w);
  } else {
    color = VFN(mul3)(VFN(mul3)(base_rgb, diffuse), VFN(scale3)(VFN(xyz)(tint_scale), tint_scale.w));
  }
  if (v->tier != TS_TIER_ID_PS20) {
    const V4v fc = TSV_REC(in, WL_SLOT_FOG_COLOR, pix), fp = TSV_REC(in, WL_SLOT_FOG_PARAMS, pix);
    const VF f = VFN(saturate)(VFN(min)(fc.w, lm_offset.z * fp.x - fp.y));
    const VF m = VFN(splat)(65504.0f);
    color = VFN(v3)(VFN(min)(color.x, m), VFN(min)(color.y, m), VFN(min)(color.z, m));
    color = VFN(add3)(color, VFN(scale3)(VFN(sub3)(VFN(xyz)(fc), color), f * f));
  }
  return VFN(rgba)(VFN(output_linear)(color), one);
}

TSV_BATCH(wl_batch, wl_block, wl_variant, wl_batch_input, wl_textures)

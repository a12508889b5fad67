/* tiershade twins: generic body of the world_lighting twin; mirrors
 * shaders/world_lighting.fs statement by statement. Instantiated by world_lighting.c through twin_instances.h; gives world_lighting_f / world_lighting_d, and
 * world_lighting_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes
 * through ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_output.h"
#include "common/common_rnm.h"
#include "common/common_lightmap.h"
#include "common/common_envmap.h"
#include "common/common_fog.h"

static V3 FN(wl_lightmap)(const wl_variant *v, const ts_tex2d *lm, V2 uv, V2 offset, TS_REAL k) {
  V4 t = M(texture2D)(lm, FN(lightmap_uv)(uv, offset, k));
  if (v->tier == TS_TIER_ID_PS20 && v->encoding == WL_LM_LDR)
    return FN(lightmap_ldr_to_linear_fast)(M(v3)(t.x, t.y, t.z));
  return FN(lightmap_decode)(t, v->encoding);
}

V4 FN(world_lighting)(const wl_variant *v, const ts_vec4f rec[WL_SLOTS], const wl_textures *tx) {
  V4 uv = FN(vec4_in)(rec[WL_SLOT_UV]);
  V4 lm_offset = FN(vec4_in)(rec[WL_SLOT_LM_OFFSET]);
  V4 tint_scale = FN(vec4_in)(rec[WL_SLOT_TINT_SCALE]);
  V2 base_uv = M(v2)(uv.x, uv.y), lm_uv = M(v2)(uv.z, uv.w), off = M(v2)(lm_offset.x, lm_offset.y);
  V4 base = M(texture2D_grad)(tx->base, base_uv, tx->uv_grad);

  V3 diffuse, n = M(v3)(K(0.0), K(0.0), K(1.0));
  V4 bump = M(v4)(K(0.0), K(0.0), K(0.0), K(0.0));
  if (v->bumpmap == WL_BUMP_NONE) {
    diffuse = FN(wl_lightmap)(v, tx->lightmap, lm_uv, off, K(0.0));
  } else {
    bump = M(texture2D_grad)(tx->normalmap, base_uv, tx->uv_grad);
    V3 l0 = FN(wl_lightmap)(v, tx->lightmap, lm_uv, off, K(1.0));
    V3 l1 = FN(wl_lightmap)(v, tx->lightmap, lm_uv, off, K(2.0));
    V3 l2 = FN(wl_lightmap)(v, tx->lightmap, lm_uv, off, K(3.0));
    V3 t = M(v3)(bump.x, bump.y, bump.z);
    if (v->bumpmap == WL_BUMP_RNM) {
      n = M(sub3)(M(scale3)(t, K(2.0)), M(v3)(K(1.0), K(1.0), K(1.0)));
      diffuse = FN(rnm_blend)(FN(rnm_weights)(n), l0, l1, l2);
    } else {
      n = v->tier == TS_TIER_ID_PS20 ? FN(ssbump_direction)(t) : FN(ssbump_normal)(t);
      diffuse = FN(ssbump_blend)(t, l0, l1, l2);
    }
  }
  V3 base_rgb = M(v3)(base.x, base.y, base.z), color;
  if (v->envmap) {
    color = M(mul3)(base_rgb, M(mul3)(diffuse, FN(xyz4)(tint_scale)));
    V4 env_tint = FN(vec4_in)(rec[WL_SLOT_ENV_TINT]);
    V4 env_params = FN(vec4_in)(rec[WL_SLOT_ENV_PARAMS]);
    V3 N = FN(xyz)(rec[WL_SLOT_NORMAL]);
    if (v->bumpmap != WL_BUMP_NONE) {
      V3 T = FN(xyz)(rec[WL_SLOT_TANGENT]), B = FN(xyz)(rec[WL_SLOT_BINORMAL]);
      N = M(add3)(M(add3)(M(scale3)(T, n.x), M(scale3)(B, n.y)), M(scale3)(N, n.z));
    }
    V3 E = FN(xyz)(rec[WL_SLOT_EYE]);
    V4 env4 = M(textureCube)(tx->envmap, FN(reflect_unnormalized)(N, E));
    V3 env = M(scale3)(M(v3)(M(min)(env4.x, K(65504.0)), M(min)(env4.y, K(65504.0)), M(min)(env4.z, K(65504.0))),
                       env_tint.w);
    V3 tint = FN(xyz4)(env_tint), spec;
    if (v->envmapmask == WL_MASK_TEXTURE) {
      V4 m = M(texture2D_grad)(tx->envmap_mask, base_uv, tx->uv_grad);
      spec = M(mul3)(env, M(mul3)(M(v3)(m.x, m.y, m.z), tint));
    } else if (v->envmapmask == WL_MASK_NORMAL_ALPHA) {
      spec = M(mul3)(env, M(scale3)(tint, bump.w));
    } else if (v->envmapmask == WL_MASK_INV_BASE_ALPHA) {
      spec = M(mul3)(env, M(scale3)(tint, SUB(K(1.0), base.w)));
    } else {
      spec = M(mul3)(env, tint);
    }
    int full = OR(OR(OR(v->tier != TS_TIER_ID_SM3, NE(env_params.x, K(0.0))), NE(env_params.y, K(1.0))),
                  NE(env_params.w, K(1.0)));
    if (full) { /* may be true (either, in the interval instance: the identity joins the full form) */
      V3 s2 = FN(envmap_saturation)(FN(envmap_contrast)(spec, env_params.x), env_params.y);
      TS_REAL NdotV =
          v->tier == TS_TIER_ID_PS20 ? FN(cosine_between)(N, E) : M(dot3)(FN(safe_normalize)(N), FN(safe_normalize)(E));
      s2 = M(scale3)(s2, FN(fresnel)(NdotV, env_params.z, env_params.w));
      spec = SEL3(full, s2, spec);
    }
    color = M(scale3)(M(add3)(color, spec), tint_scale.w);
  } else {
    color = M(mul3)(M(mul3)(base_rgb, diffuse), M(scale3)(FN(xyz4)(tint_scale), tint_scale.w));
  }

  if (v->tier != TS_TIER_ID_PS20)
    color =
        FN(range_fog)(M(v3)(M(min)(color.x, K(65504.0)), M(min)(color.y, K(65504.0)), M(min)(color.z, K(65504.0))),
                      lm_offset.z, FN(vec4_in)(rec[WL_SLOT_FOG_COLOR]), FN(vec4_in)(rec[WL_SLOT_FOG_PARAMS]));
  /* Not FN(final_output): Source's range fog sits between its scale and its clamp. */
  (void)FN(final_output);
  V3 c = FN(output_linear)(color);
  return M(v4)(c.x, c.y, c.z, K(1.0));
}

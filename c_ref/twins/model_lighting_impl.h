/* tiershade twins: generic body of the model_lighting twin; mirrors
 * shaders/model_lighting.fs statement by statement. Instantiated by model_lighting.c through twin_instances.h; gives model_lighting_f / model_lighting_d, and
 * model_lighting_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes
 * through ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_ambient_cube.h"
#include "common/common_lights.h"
#include "common/common_phong.h"
#include "common/common_output.h"

static V3 FN(ml_ambient)(V3 n, const ts_vec4f rec[ML_SLOTS]) {
  V3 cube[6];
  for (int k = 0; k < 6; ++k) cube[k] = FN(xyz)(rec[ML_SLOT_AMBIENT + k]);
  return FN(ambient_cube)(n, cube);
}

V4 FN(model_lighting)(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ml_textures *tex) {
  V3 P = FN(xyz)(rec[ML_SLOT_POSITION]);
  V4 uvw = FN(vec4_in)(rec[ML_SLOT_UV]);
  V4 params = FN(vec4_in)(rec[ML_SLOT_PARAMS]);
  V4 base = v->albedo_texture ? M(texture2D_grad)(tex->albedo, M(v2)(uvw.x, uvw.y), tex->uv_grad) : FN(vec4_in)(rec[ML_SLOT_ALBEDO]);

  V3 N, V = M(v3)(K(0.0), K(0.0), K(0.0)), R = V, spec = V, rim = V;
  V4 nmap = M(v4)(K(0.0), K(0.0), K(0.0), K(0.0)), phong = nmap, rim_params = nmap;
  V4 expmap = M(v4)(K(1.0), K(1.0), K(1.0), K(1.0));
  TS_REAL NdotV = K(0.0), k = K(0.0);
  if (v->phong) {
    nmap = M(texture2D_grad)(tex->normal_map, M(v2)(uvw.x, uvw.y), tex->uv_grad);
    V3 tn = M(sub3)(M(scale3)(FN(xyz4)(nmap), K(2.0)), M(v3)(K(1.0), K(1.0), K(1.0)));
    V3 T = FN(xyz)(rec[ML_SLOT_TANGENT]), B = FN(xyz)(rec[ML_SLOT_BITANGENT]), Ng = FN(xyz)(rec[ML_SLOT_NORMAL]);
    N = FN(safe_normalize)(M(add3)(M(add3)(M(scale3)(T, tn.x), M(scale3)(B, tn.y)), M(scale3)(Ng, tn.z)));
    V = FN(safe_normalize)(M(sub3)(FN(xyz)(rec[ML_SLOT_EYE]), P));
    NdotV = M(dot3)(N, V);
    R = M(sub3)(M(scale3)(N, MUL(K(2.0), NdotV)), V);
    phong = FN(vec4_in)(rec[ML_SLOT_PHONG]);
    if (v->exponent_map) {
      expmap = M(texture2D_grad)(tex->exponent_map, M(v2)(uvw.x, uvw.y), tex->uv_grad);
      k = ADD(K(1.0), MUL(phong.y, expmap.x));
    } else {
      k = phong.x;
    }
    if (v->rim_light) rim_params = FN(vec4_in)(rec[ML_SLOT_RIM]);
  } else {
    N = FN(safe_normalize)(FN(xyz)(rec[ML_SLOT_NORMAL]));
  }

  V3 diffuse = FN(ml_ambient)(N, rec);

  int loop = v->num_lights;
  if (v->tier == TS_TIER_ID_SM3) loop = TOINT(M(clamp)(params.y, K(0.0), FROMF(ML_MAX_LIGHTS)));
  for (int i = 0; i < loop && i < ML_MAX_LIGHTS; ++i) {
    V4 l[5];
    for (int j = 0; j < 5; ++j) l[j] = FN(vec4_in)(rec[ML_SLOT_LIGHT0 + 5 * i + j]);
    V3 L;
    TS_REAL att;
    if (v->tier == TS_TIER_ID_PS20) {
      L = FN(light_direction)(l, P);
      att = i == 0 ? FROMF(rec[ML_SLOT_VERTEX_ATTEN].x) : FROMF(rec[ML_SLOT_VERTEX_ATTEN].y);
    } else {
      att = FN(light_attenuation)(l, P, &L);
    }
    TS_REAL NdotL = M(dot3)(N, L);
    if (v->light_warp) {
      V4 w = M(texture2D)(tex->light_warp, M(v2)(M(saturate)(ADD(MUL(K(0.5), NdotL), K(0.5))), K(0.5)));
      diffuse = M(add3)(diffuse, M(scale3)(M(mul3)(FN(xyz4)(l[0]), M(scale3)(FN(xyz4)(w), K(2.0))), att));
    } else {
      TS_REAL term = v->half_lambert ? FN(half_lambert)(NdotL) : FN(lambert)(NdotL);
      diffuse = M(add3)(diffuse, M(scale3)(FN(xyz4)(l[0]), MUL(att, term)));
    }
    if (v->phong) {
      TS_REAL RdotL = M(max)(M(saturate)(M(dot3)(R, L)), K(TS_POW_TINY_C));
      V3 lit = M(scale3)(FN(xyz4)(l[0]), MUL(M(saturate)(NdotL), att));
      spec = M(add3)(spec, M(scale3)(lit, M(pow)(RdotL, k)));
      if (v->rim_light) rim = M(add3)(rim, M(scale3)(lit, M(pow)(RdotL, rim_params.x)));
    }
  }

  V3 color;
  /* With no local lights in the variant (NUM_LIGHTS = 0 below sm3) the shader's spec
   * and rim sums are the constant 0, and NIR folds 0 * x to 0 even when x is NaN or
   * Inf (platform notes section 4): mirror the folding, not IEEE. */
  const int spec_const_zero = v->tier != TS_TIER_ID_SM3 && v->num_lights == 0;
  if (v->phong) {
    V4 fr = FN(vec4_in)(rec[ML_SLOT_FRESNEL]);
    TS_REAL F = FN(fresnel_ranges)(NdotV, FN(xyz4)(fr));
    TS_REAL mask = SEL(GT(phong.w, K(0.5)), base.w, nmap.w);
    mask = SEL(GT(fr.w, K(0.5)), SUB(K(1.0), mask), mask);
    TS_REAL spec_mask = MUL(mask, F);
    if (!spec_const_zero) spec = M(scale3)(spec, MUL(spec_mask, phong.z));
    V4 tint = FN(vec4_in)(rec[ML_SLOT_PHONG_TINT]);
    V3 spec_tint = FN(xyz4)(tint);
    if (v->exponent_map) spec_tint = SEL3(GT(tint.w, K(0.5)), FN(lerp3_from_one)(FN(xyz4)(base), expmap.y), spec_tint);
    if (v->rim_light) {
      TS_REAL fresnel4 = FN(fresnel4)(NdotV);
      TS_REAL rim_mask = FN(lerp_from_one)(expmap.w, rim_params.z);
      if (!spec_const_zero) {
        rim = M(scale3)(rim, MUL(rim_mask, fresnel4));
        spec = M(max3)(spec, rim);
      }
      spec = M(add3)(spec, M(scale3)(FN(ml_ambient)(V, rec), MUL(rim_params.y, M(saturate)(MUL(MUL(rim_mask, fresnel4), N.y)))));
    }
    color = spec_const_zero && !v->rim_light ? spec : M(mul3)(spec, spec_tint);
    if (v->envmap) {
      V4 env = FN(vec4_in)(rec[ML_SLOT_ENVMAP]);
      TS_REAL env_mask = SEL(GT(env.z, K(0.5)), mask, SEL(GT(fr.w, K(0.5)), SUB(K(1.0), base.w), base.w));
      TS_REAL env_scale = MUL(MUL(env.x, FN(lerp_from_one)(F, env.y)), env_mask);
      V4 e = M(textureCube)(tex->envmap, R);
      color = M(add3)(color, M(mul3)(M(scale3)(FN(xyz4)(e), env_scale), FN(xyz)(rec[ML_SLOT_ENVMAP_TINT])));
    }
    V4 si = FN(vec4_in)(rec[ML_SLOT_SELF_ILLUM]);
    color = M(add3)(color, M(mul3)(FN(xyz4)(base), FN(lerp3)(diffuse, FN(xyz4)(si), MUL(base.w, si.w))));
  } else {
    color = M(mul3)(FN(xyz4)(base), diffuse);
  }
  V3 c = FN(final_output)(color, params.x, v->output_mode);
  /* an unsure light count (a NaN params.y): the interval instance admits anything */
  return ANY_IF(loop == TS_IV_UNSURE_INT, M(v4)(c.x, c.y, c.z, K(1.0)));
}

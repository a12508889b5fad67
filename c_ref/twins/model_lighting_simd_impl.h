/* tiershade twins: the model_lighting twin (c_ref/twins/model_lighting_impl.h, float32) on TSV_W pixels at once, in
 * SoA: the same statements in the same order, so every lane gives the scalar twin's bits.
 * Variant switches (combos) stay scalar `if`s; everything read from the record is per lane,
 * including what a production frame passes as uniforms (conformance records vary it per
 * pixel): the shader's data-dependent choices become selects, and sm3's light loop runs to the
 * largest count of the block with the lanes past their own count masked off.
 * Included by c_ref/twins/model_lighting_batch.c after ts_simd.h and ts_simd_sampler.h. */

#include "twins/simd_common.h"

/* Slot k of the block's pixels as a 3-vector (pix[j] = pixel index of lane j). */
TSV_INL V3v VFN(ml_rec3)(const ml_batch_input *in, int k, const size_t *pix) { return VFN(xyz)(TSV_REC(in, k, pix)); }

/* common_ambient_cube.h, with the cube read from slots ML_SLOT_AMBIENT.. */
static V3v VFN(ml_ambient)(V3v n, const ml_batch_input *in, const size_t *pix) {
  const V3v n2 = VFN(mul3)(n, n);
  const VF z = VFN(splat)(0.0f);
  const V3v cx =
      VFN(sel3)(n.x >= z, VFN(ml_rec3)(in, ML_SLOT_AMBIENT + 0, pix), VFN(ml_rec3)(in, ML_SLOT_AMBIENT + 1, pix));
  const V3v cy =
      VFN(sel3)(n.y >= z, VFN(ml_rec3)(in, ML_SLOT_AMBIENT + 2, pix), VFN(ml_rec3)(in, ML_SLOT_AMBIENT + 3, pix));
  const V3v cz =
      VFN(sel3)(n.z >= z, VFN(ml_rec3)(in, ML_SLOT_AMBIENT + 4, pix), VFN(ml_rec3)(in, ML_SLOT_AMBIENT + 5, pix));
  return VFN(add3)(VFN(add3)(VFN(scale3)(cx, n2.x), VFN(scale3)(cy, n2.y)), VFN(scale3)(cz, n2.z));
}

/* common_lights.h light_attenuation */
TSV_INL VF VFN(light_attenuation)(const V4v l[5], V3v P, V3v *L) {
  const V3v Lv = VFN(sub3)(VFN(xyz)(l[2]), P);
  /* TS_MIN_LENGTH2, TS_MAX_LIGHT_DISTANCE: not fp16 numbers (shaders/common_lights.glsl) */
  const VF d2 = VFN(max)(VFN(dot3)(Lv, Lv), VFN(splat)(1.0e-30f));
  const VF rinv = VFN(inversesqrt)(d2);
  const VF d = VFN(min)(d2 * rinv, VFN(splat)(1.0e18f));
  const VI directional = l[0].w > 0.5f;
  *L = VFN(sel3)(directional, VFN(neg3)(VFN(xyz)(l[1])), VFN(scale3)(Lv, rinv));
  VF dist_att = 1.0f / VFN(max)((l[4].x + l[4].y * d) + l[4].z * (d * d), VFN(splat)(1.0e-30f));
  dist_att = VFN(sel)(directional, VFN(splat)(1.0f), dist_att);
  const VF cos_a = VFN(dot3)(VFN(neg3)(*L), VFN(xyz)(l[1]));
  VF spot = VFN(saturate)(VFN(pow)(VFN(max)(VFN(splat)(1.0e-4f), (cos_a - l[3].z) * l[3].w), l[3].x));
  spot = VFN(sel)(l[1].w > 0.5f, spot, VFN(splat)(1.0f));
  return dist_att * spot;
}

/* common_lights.h light_direction (ps20) */
TSV_INL V3v VFN(light_direction)(const V4v l[5], V3v P) {
  const V3v Lv = VFN(sub3)(VFN(xyz)(l[2]), P);
  const VF rinv = VFN(inversesqrt)(VFN(max)(VFN(dot3)(Lv, Lv), VFN(splat)(1.0e-30f))); /* 0 in fp16 */
  return VFN(sel3)(l[0].w > 0.5f, VFN(neg3)(VFN(xyz)(l[1])), VFN(scale3)(Lv, rinv));
}

/* common_phong.h */
TSV_INL VF VFN(lerp_from_one)(VF b, VF t) { return (1.0f - t) + b * t; }
static V4v VFN(ml_block)(const ml_variant *v, const ml_batch_input *in, const ml_textures *tex, const size_t *pix) {
  const VF zero = VFN(splat)(0.0f), one = VFN(splat)(1.0f);
  const V3v P = VFN(ml_rec3)(in, ML_SLOT_POSITION, pix);
  const V4v uvw = TSV_REC(in, ML_SLOT_UV, pix);
  const V4v params = TSV_REC(in, ML_SLOT_PARAMS, pix);
  const V4v base = v->albedo_texture ? VFN(tex2d_grad)(tex->albedo, uvw.x, uvw.y, tex->uv_grad, tex->uv_grad_stride, pix) : TSV_REC(in, ML_SLOT_ALBEDO, pix);

  V3v N, V = VFN(v3)(zero, zero, zero), R = V, spec = V, rim = V;
  V4v nmap = {zero, zero, zero, zero}, phong = nmap, rim_params = nmap;
  V4v expmap = {one, one, one, one};
  VF NdotV = zero, k = zero;
  if (v->phong) {
    nmap = VFN(tex2d_grad)(tex->normal_map, uvw.x, uvw.y, tex->uv_grad, tex->uv_grad_stride, pix);
    const V3v tn = VFN(sub3)(VFN(scale3)(VFN(xyz)(nmap), VFN(splat)(2.0f)), VFN(v3)(one, one, one));
    const V3v T = VFN(ml_rec3)(in, ML_SLOT_TANGENT, pix), B = VFN(ml_rec3)(in, ML_SLOT_BITANGENT, pix);
    const V3v Ng = VFN(ml_rec3)(in, ML_SLOT_NORMAL, pix);
    N = VFN(safe_normalize)(VFN(add3)(VFN(add3)(VFN(scale3)(T, tn.x), VFN(scale3)(B, tn.y)), VFN(scale3)(Ng, tn.z)));
    V = VFN(safe_normalize)(VFN(sub3)(VFN(ml_rec3)(in, ML_SLOT_EYE, pix), P));
    NdotV = VFN(dot3)(N, V);
    R = VFN(sub3)(VFN(scale3)(N, 2.0f * NdotV), V);
    phong = TSV_REC(in, ML_SLOT_PHONG, pix);
    if (v->exponent_map) {
      expmap = VFN(tex2d_grad)(tex->exponent_map, uvw.x, uvw.y, tex->uv_grad, tex->uv_grad_stride, pix);
      k = 1.0f + phong.y * expmap.x;
    } else {
      k = phong.x;
    }
    if (v->rim_light) rim_params = TSV_REC(in, ML_SLOT_RIM, pix);
  } else {
    N = VFN(safe_normalize)(VFN(ml_rec3)(in, ML_SLOT_NORMAL, pix));
  }

  V3v diffuse = VFN(ml_ambient)(N, in, pix);

  /* sm3: the count is per lane; other tiers: the variant's NUM_LIGHTS for every lane. */
  int loop = v->num_lights;
  VI count = VFN(spliti)(loop);
  if (v->tier == TS_TIER_ID_SM3) {
    count = VFN(itrunc)(VFN(clamp)(params.y, zero, VFN(splat)((float)ML_MAX_LIGHTS)));
    loop = 0;
    for (int j = 0; j < TSV_W; ++j) loop = count[j] > loop ? count[j] : loop;
  }
  const V4v vatt = v->tier == TS_TIER_ID_PS20 ? TSV_REC(in, ML_SLOT_VERTEX_ATTEN, pix) : nmap;
  for (int i = 0; i < loop && i < ML_MAX_LIGHTS; ++i) {
    const VI active = VFN(spliti)(i) < count;
    V4v l[5];
    for (int j = 0; j < 5; ++j) l[j] = TSV_REC(in, ML_SLOT_LIGHT0 + 5 * i + j, pix);
    V3v L;
    VF att;
    if (v->tier == TS_TIER_ID_PS20) {
      L = VFN(light_direction)(l, P);
      att = i == 0 ? vatt.x : vatt.y;
    } else {
      att = VFN(light_attenuation)(l, P, &L);
    }
    const VF NdotL = VFN(dot3)(N, L);
    V3v d2;
    if (v->light_warp) {
      const V4v w = VFN(texture2D)(tex->light_warp, VFN(saturate)(0.5f * NdotL + 0.5f), VFN(splat)(0.5f));
      d2 = VFN(add3)(diffuse, VFN(scale3)(VFN(mul3)(VFN(xyz)(l[0]), VFN(scale3)(VFN(xyz)(w), VFN(splat)(2.0f))), att));
    } else {
      VF term;
      if (v->half_lambert) {
        const VF h = VFN(saturate)(0.5f * NdotL + 0.5f);
        term = h * h;
      } else {
        term = VFN(saturate)(NdotL);
      }
      d2 = VFN(add3)(diffuse, VFN(scale3)(VFN(xyz)(l[0]), att * term));
    }
    diffuse = VFN(sel3)(active, d2, diffuse);
    if (v->phong) {
      const VF RdotL = VFN(max)(VFN(saturate)(VFN(dot3)(R, L)), VFN(splat)(TS_POW_TINY_F));
      const V3v lit = VFN(scale3)(VFN(xyz)(l[0]), VFN(saturate)(NdotL) * att);
      spec = VFN(sel3)(active, VFN(add3)(spec, VFN(scale3)(lit, VFN(pow)(RdotL, k))), spec);
      if (v->rim_light) rim = VFN(sel3)(active, VFN(add3)(rim, VFN(scale3)(lit, VFN(pow)(RdotL, rim_params.x))), rim);
    }
  }

  V3v color;
  const int spec_const_zero = v->tier != TS_TIER_ID_SM3 && v->num_lights == 0;
  if (v->phong) {
    const V4v fr = TSV_REC(in, ML_SLOT_FRESNEL, pix);
    VF F;
    {
      VF f = VFN(saturate)(1.0f - NdotV);
      f = f * f;
      F = fr.y + (f - 0.5f) * VFN(sel)(f >= 0.5f, fr.z, fr.x);
    }
    const VI fr_inv = fr.w > 0.5f;
    VF mask = VFN(sel)(phong.w > 0.5f, base.w, nmap.w);
    mask = VFN(sel)(fr_inv, 1.0f - mask, mask);
    const VF spec_mask = mask * F;
    if (!spec_const_zero) spec = VFN(scale3)(spec, spec_mask * phong.z);
    const V4v tint = TSV_REC(in, ML_SLOT_PHONG_TINT, pix);
    V3v spec_tint = VFN(xyz)(tint);
    if (v->exponent_map) {
      const VF u = 1.0f - expmap.y;
      const V3v from_one = VFN(v3)(u + base.x * expmap.y, u + base.y * expmap.y, u + base.z * expmap.y);
      spec_tint = VFN(sel3)(tint.w > 0.5f, from_one, spec_tint);
    }
    if (v->rim_light) {
      VF fresnel4 = VFN(saturate)(1.0f - NdotV);
      fresnel4 = fresnel4 * fresnel4;
      fresnel4 = fresnel4 * fresnel4;
      const VF rim_mask = VFN(lerp_from_one)(expmap.w, rim_params.z);
      if (!spec_const_zero) {
        rim = VFN(scale3)(rim, rim_mask * fresnel4);
        spec = VFN(max3)(spec, rim);
      }
      spec = VFN(add3)(
          spec, VFN(scale3)(VFN(ml_ambient)(V, in, pix), rim_params.y * VFN(saturate)(rim_mask * fresnel4 * N.y)));
    }
    color = spec_const_zero && !v->rim_light ? spec : VFN(mul3)(spec, spec_tint);
    if (v->envmap) {
      const V4v env = TSV_REC(in, ML_SLOT_ENVMAP, pix);
      const VF env_mask = VFN(sel)(env.z > 0.5f, mask, VFN(sel)(fr_inv, 1.0f - base.w, base.w));
      const VF env_scale = env.x * VFN(lerp_from_one)(F, env.y) * env_mask;
      const V4v e = VFN(textureCube)(tex->envmap, R);
      color =
          VFN(add3)(color, VFN(mul3)(VFN(scale3)(VFN(xyz)(e), env_scale), VFN(ml_rec3)(in, ML_SLOT_ENVMAP_TINT, pix)));
    }
    const V4v si = TSV_REC(in, ML_SLOT_SELF_ILLUM, pix);
    color = VFN(add3)(color, VFN(mul3)(VFN(xyz)(base), VFN(lerp3)(diffuse, VFN(xyz)(si), base.w * si.w)));
  } else {
    color = VFN(mul3)(VFN(xyz)(base), diffuse);
  }
  /* common_output.h final_output */
  return VFN(rgba)(VFN(output)(VFN(scale3)(color, params.x), v->output_mode), VFN(splat)(1.0f));
}

TSV_BATCH(ml_batch, ml_block, ml_variant, ml_batch_input, ml_textures)

//------------------------------------------------------------------------------
// world_lighting.fs: Source's world (brush) shading, LightmappedGeneric (talk:
// "Radiosity Normal Mapping", "World specular"; fact sheet sections 1, 2, 6, 7):
//   diffuse = lightmap (flat), or the RNM / ssbump blend of the three bumped
//             lightmaps (common_rnm.glsl), decoded (common_lightmap.glsl), x c12
//   spec    = envmap term x Fresnel (common_envmap.glsl), masked
//   out     = FinalOutput(base * diffuse + spec): tone-map scale, range fog, linear
// Tiers: ps20 (64 + 32 slots: no pixel fog, LDR lightmaps decoded as (2t)^2, N.V
// with one shared inversesqrt, ssbump normal not renormalised), ps2b and sm3 (everything; sm3 skips the contrast/saturation/
// Fresnel work with a uniform branch when they are at their defaults, Source's
// FASTPATH). Variants: world_lighting.variants. C twin: c_ref/twins/world_lighting.c.
// Inputs (slots): c_ref/twins/world_lighting.h and world_lighting_slots.glsl.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_output.glsl"
#include "common_rnm.glsl"
#include "common_lightmap.glsl"
#include "common_envmap.glsl"
#include "common_fog.glsl"
#include "world_lighting_slots.glsl"
#include "world_lighting_varyings.glsl"

uniform vec4 u_tint_scale;       // rgb c12 (tint x lightmap scale), w tone-map scale
uniform vec4 u_envmap_tint;      // rgb tint, w ENV_MAP_SCALE
uniform vec4 u_envmap_params;    // contrast, saturation, 1 - R0, R0
uniform vec4 u_fog_color;        // rgb, w max density
uniform vec4 u_fog_params;       // 1 / range, start / range
uniform sampler2D u_base;        // rgb albedo, a: inverted envmap mask (ENVMAPMASK 3)
uniform sampler2D u_normalmap;   // rgb normal (or ssbump weights), a: envmap mask (ENVMAPMASK 2)
uniform sampler2D u_lightmap;    // the lightmap page
uniform sampler2D u_envmap_mask; // rgb envmap mask (ENVMAPMASK 1)
uniform samplerCube u_envmap;

TS_DECLARE_FRAG_COLOR

vec3 wl_lightmap(vec2 uv, vec2 offset, float k) {
    vec4 t = TS_TEX2D(u_lightmap, ts_lightmap_uv(uv, offset, k));
#if defined(TS_TIER_PS20) && LIGHTMAP_ENCODING == TS_LIGHTMAP_LDR
    return ts_lightmap_ldr_to_linear_fast(t.rgb);  // ps20: (2t)^2, 7 slots less per sample
#else
    return ts_lightmap_decode(t, LIGHTMAP_ENCODING);
#endif
}

void main() {
    vec4 uv = TS_PIXEL_INPUT(WL_SLOT_UV, v_uv);
    vec4 lm_offset = TS_PIXEL_INPUT(WL_SLOT_LM_OFFSET, v_lm_offset);
    vec4 tint_scale = TS_UNIFORM_INPUT(WL_SLOT_TINT_SCALE, u_tint_scale);
    vec4 base = TS_TEX2D(u_base, uv.xy);

#if BUMPMAP == 0
    vec3 diffuse = wl_lightmap(uv.zw, lm_offset.xy, 0.0);
#else
    vec4 bump = TS_TEX2D(u_normalmap, uv.xy);
    vec3 l0 = wl_lightmap(uv.zw, lm_offset.xy, 1.0);
    vec3 l1 = wl_lightmap(uv.zw, lm_offset.xy, 2.0);
    vec3 l2 = wl_lightmap(uv.zw, lm_offset.xy, 3.0);
#if BUMPMAP == 1
    vec3 n = bump.rgb * 2.0 - 1.0;
    vec3 diffuse = ts_rnm_blend(ts_rnm_weights(n), l0, l1, l2);
#elif defined(TS_TIER_PS20)
    // ps20: the ssbump normal is not renormalised; the reflection vector and N.V below
    // do not depend on N's length.
    vec3 n = ts_ssbump_direction(bump.rgb);
    vec3 diffuse = ts_ssbump_blend(bump.rgb, l0, l1, l2);
#else
    vec3 n = ts_ssbump_normal(bump.rgb);
    vec3 diffuse = ts_ssbump_blend(bump.rgb, l0, l1, l2);
#endif
#endif
    // Products of four factors are written balanced, (a b)(c d): Mesa's GLSL compiler
    // rebalances chains of three or more multiplies into that shape (opt_rebalance_tree),
    // and the C twin has to multiply in the order llvmpipe does.
#if ENVMAP
    vec3 color = base.rgb * (diffuse * tint_scale.rgb);
    vec4 env_tint = TS_UNIFORM_INPUT(WL_SLOT_ENV_TINT, u_envmap_tint);
    vec4 env_params = TS_UNIFORM_INPUT(WL_SLOT_ENV_PARAMS, u_envmap_params);
    vec3 N = TS_PIXEL_INPUT(WL_SLOT_NORMAL, v_normal).xyz;
#if BUMPMAP
    N = n.x * TS_PIXEL_INPUT(WL_SLOT_TANGENT, v_tangent).xyz
      + n.y * TS_PIXEL_INPUT(WL_SLOT_BINORMAL, v_binormal).xyz + n.z * N;
#endif
    vec3 E = TS_PIXEL_INPUT(WL_SLOT_EYE, v_eye).xyz;
    // The texel clamped to the fp16 range: an Inf texel gives 65504 on every tier (the sm3 fast
    // path and the full contrast/saturation/Fresnel path agree; before, Inf * (1 + Inf * 0) made the
    // full path NaN, 0 after the output clamp, against 65504 on the fast path).
    vec3 env = min(TS_TEXCUBE(u_envmap, ts_reflect_unnormalized(N, E)).rgb, TS_FP16_MAX);
#if ENVMAPMASK == 1
    vec3 spec = (env * env_tint.w) * (TS_TEX2D(u_envmap_mask, uv.xy).rgb * env_tint.rgb);
#elif ENVMAPMASK == 2
    vec3 spec = (env * env_tint.w) * (bump.a * env_tint.rgb);
#elif ENVMAPMASK == 3
    vec3 spec = (env * env_tint.w) * ((1.0 - base.a) * env_tint.rgb);
#else
    vec3 spec = (env * env_tint.w) * env_tint.rgb;
#endif
#ifdef TS_TIER_SM3
    // FASTPATH: contrast 0, saturation 1 and R0 1 leave spec unchanged.
    if (env_params.x != 0.0 || env_params.y != 1.0 || env_params.w != 1.0) {
#endif
        spec = ts_envmap_saturation(ts_envmap_contrast(spec, env_params.x), env_params.y);
#ifdef TS_TIER_PS20
        // ps20: one inversesqrt for both lengths, reusing the reflection's dot products.
        float NdotV = ts_cosine_between(N, E);
#else
        float NdotV = dot(ts_safe_normalize(N), ts_safe_normalize(E));
#endif
        spec *= ts_fresnel(NdotV, env_params.z, env_params.w);
#ifdef TS_TIER_SM3
    }
#endif
    color = (color + spec) * tint_scale.w;
#else
    vec3 color = (base.rgb * diffuse) * (tint_scale.rgb * tint_scale.w);
#endif
#ifndef TS_TIER_PS20
    // Clamped before the fog: an overflowed (Inf) colour would make c + (fog - c) f^2 NaN.
    color = ts_range_fog(min(color, TS_FP16_MAX), lm_offset.z, TS_UNIFORM_INPUT(WL_SLOT_FOG_COLOR, u_fog_color),
                         TS_UNIFORM_INPUT(WL_SLOT_FOG_PARAMS, u_fog_params));
#endif
    TS_FRAG_COLOR = vec4(ts_output_linear(color), 1.0);
}

//------------------------------------------------------------------------------
// model_lighting.fs: Source model lighting.
// Half-Life 2 (talk: "Model lighting": irradiance volume ambient cube,
// half-Lambert, local lights):
//   diffuse = ambientCube(N) + sum_i color_i * atten_i * D(N.L_i)
//   out     = FinalOutput(albedo * diffuse)        D = half-Lambert or Lambert
// Episode One Phong (talk: "Phong terms"; fact sheet section 5; PHONG = 1, ps2b
// and sm3 only): normal map, per-light Phong specular with an exponent map,
// masks, Fresnel ranges, rim light, light-warp ramp, envmap and self-illumination:
//   out = FinalOutput(spec * tint + envmap + selfillum(albedo * diffuse))
// Tiers: ps20 (<= 2 lights, attenuation per vertex, linear output, no Phong),
// ps2b (<= 4 lights, all per pixel), sm3 (a dynamic loop over a uniform light
// count). Lights beyond a tier's limit are folded into the ambient cube on the
// CPU (docs/light_folding.md).
// Variants: model_lighting.variants. C twin: c_ref/twins/model_lighting.c.
// Inputs (slots): c_ref/twins/model_lighting.h and model_lighting_slots.glsl.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_ambient_cube.glsl"
#include "common_lights.glsl"
#include "common_phong.glsl"
#include "common_output.glsl"
#include "model_lighting_slots.glsl"
#include "model_lighting_varyings.glsl"

#ifdef TS_TIER_SM3
#define ML_LOOP_LIGHTS ML_MAX_LIGHTS
#else
#define ML_LOOP_LIGHTS NUM_LIGHTS
#endif

uniform vec4 u_ambient_cube[6];  // +X -X +Y -Y +Z -Z
#if defined(TS_TIER_PS20) || defined(TS_TIER_PS2B)
// ps20 and ps2b: the lights packed in 4 vec4 each (ts_light_unpack, common_lights.glsl), as many
// as the tier has (ps20 2, ps2b 4): 6 + 8 + 2 = 16 ps20 fragment uniform vectors (WebGL 1's
// minimum), 6 + 16 + 1 + 8 Phong = 31 ps2b constant registers (ps_2_b: 32; docs/tiers.md).
#ifdef TS_TIER_PS20
#define ML_PACK_LIGHTS 2
#else
#define ML_PACK_LIGHTS 4
#endif
uniform vec4 u_light_pack[4 * ML_PACK_LIGHTS];
#if defined(TS_CONFORM)
#define ML_LIGHT_PACKED 0
#else
#define ML_LIGHT_PACKED 1
#endif
#else
uniform vec4 u_lights[5 * ML_MAX_LIGHTS];
#define ML_LIGHT_PACKED 0
#endif
uniform vec4 u_params;           // x: tone-map scale, y: light count (sm3)
uniform vec4 u_albedo_color;
uniform sampler2D u_albedo;      // rgb albedo, a: spec mask / envmap mask / self-illum mask (Phong)
#if PHONG
uniform vec4 u_eye;
uniform vec4 u_phong;            // see model_lighting_slots.glsl for these
uniform vec4 u_fresnel_ranges;
uniform vec4 u_phong_tint;
uniform vec4 u_rim;
uniform vec4 u_envmap_params;
uniform vec4 u_envmap_tint;
uniform vec4 u_self_illum;
uniform sampler2D u_normal_map;  // rgb tangent normal (2x - 1), a: spec mask
#if PHONG_EXPONENT_MAP
uniform sampler2D u_exponent_map; // r exponent, g albedo-tint mask, a rim mask
#endif
#if LIGHT_WARP
uniform sampler2D u_light_warp;  // 1D ramp indexed by the unsquared half-Lambert term
#endif
#if ENVMAP
uniform samplerCube u_envmap;
#endif
#endif

TS_DECLARE_FRAG_COLOR

vec3 ml_ambient_cube(vec3 n) {
    return ts_ambient_cube(n,
        TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 0, u_ambient_cube[0]).rgb, TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 1, u_ambient_cube[1]).rgb,
        TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 2, u_ambient_cube[2]).rgb, TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 3, u_ambient_cube[3]).rgb,
        TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 4, u_ambient_cube[4]).rgb, TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 5, u_ambient_cube[5]).rgb);
}

// The diffuse of one local light, by variant (fact sheet section 4): the light-warp ramp
// indexed by the unsquared half-Lambert term, times 2; else half-Lambert or Lambert.
// It takes the light, not its colour: given a vec3 colour parameter Mesa regrouped
// color * (2 warp) * att as (color * 2) * (warp * att), 1 ULP off the C twin (measured).
vec3 ml_light_diffuse(TsLight l, float att, float NdotL) {
#if LIGHT_WARP
    vec3 warp = TS_TEX2D(u_light_warp, vec2(saturate(0.5 * NdotL + 0.5), 0.5)).rgb;
    return l.color.rgb * (2.0 * warp) * att;
#elif HALF_LAMBERT
    return l.color.rgb * (att * ts_half_lambert(NdotL));
#else
    return l.color.rgb * (att * ts_lambert(NdotL));
#endif
}

void main() {
    vec3 P = TS_PIXEL_INPUT(ML_SLOT_POSITION, vec4(v_position, 1.0)).xyz;
    vec2 uv = TS_PIXEL_INPUT(ML_SLOT_UV, vec4(v_uv, 0.0, 0.0)).xy;
    vec4 params = TS_UNIFORM_INPUT(ML_SLOT_PARAMS, u_params);
#ifdef TS_TIER_PS20
    vec4 vertex_atten = TS_PIXEL_INPUT(ML_SLOT_VERTEX_ATTEN, v_light_atten);
#endif
#if ALBEDO_TEXTURE
    vec4 base = TS_TEX2D(u_albedo, uv);
#else
    vec4 base = TS_UNIFORM_INPUT(ML_SLOT_ALBEDO, u_albedo_color);
#endif

#if PHONG
    // Tangent-space normal map, not renormalised before the frame (fact sheet section 5).
    vec4 nmap = TS_TEX2D(u_normal_map, uv);
    vec3 tn = nmap.rgb * 2.0 - 1.0;
    vec3 T = TS_PIXEL_INPUT(ML_SLOT_TANGENT, vec4(v_tangent, 0.0)).xyz;
    vec3 B = TS_PIXEL_INPUT(ML_SLOT_BITANGENT, vec4(v_bitangent, 0.0)).xyz;
    vec3 Ng = TS_PIXEL_INPUT(ML_SLOT_NORMAL, vec4(v_normal, 0.0)).xyz;
    vec3 N = ts_safe_normalize(T * tn.x + B * tn.y + Ng * tn.z);
    vec3 V = ts_safe_normalize(TS_UNIFORM_INPUT(ML_SLOT_EYE, u_eye).xyz - P);
    float NdotV = dot(N, V);
    vec3 R = N * (2.0 * NdotV) - V;
    vec4 phong = TS_UNIFORM_INPUT(ML_SLOT_PHONG, u_phong);
#if PHONG_EXPONENT_MAP
    vec4 expmap = TS_TEX2D(u_exponent_map, uv);
    float k = 1.0 + phong.y * expmap.r;   // 1 + 149 r by default: [1, 150]
#else
    vec4 expmap = vec4(1.0);
    float k = phong.x;
#endif
    vec3 spec = vec3(0.0);
#if RIM_LIGHT
    vec4 rim_params = TS_UNIFORM_INPUT(ML_SLOT_RIM, u_rim);
    vec3 rim = vec3(0.0);
#endif
#else
    vec3 N = ts_safe_normalize(TS_PIXEL_INPUT(ML_SLOT_NORMAL, vec4(v_normal, 0.0)).xyz);
#endif

    vec3 diffuse = ml_ambient_cube(N);

#ifdef TS_TIER_SM3
    int light_count = int(clamp(params.y, 0.0, float(ML_MAX_LIGHTS)));
#endif
    for (int i = 0; i < ML_LOOP_LIGHTS; ++i) {
#ifdef TS_TIER_SM3
        if (i >= light_count) break;
#endif
        TsLight l;
#if ML_LIGHT_PACKED
        // Indexed in the loop, not in a function: ESSL 1.00 fragment shaders index uniform arrays
        // with constant-index expressions only (appendix A), and a loop index is one.
        l = ts_light_unpack(u_light_pack[4 * i + 0], u_light_pack[4 * i + 1], u_light_pack[4 * i + 2],
                            u_light_pack[4 * i + 3]);
#else
        // sm3, and every tier's conformance record (5 slots per light, unpacked: TS_CONFORM reads
        // the slot and drops the production expression, so ps20/ps2b need no u_lights here).
        l.color = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 0, u_lights[5 * i + 0]);
        l.dir   = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 1, u_lights[5 * i + 1]);
        l.pos   = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 2, u_lights[5 * i + 2]);
        l.spot  = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 3, u_lights[5 * i + 3]);
        l.atten = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 4, u_lights[5 * i + 4]);
#endif
#ifdef TS_TIER_PS20
        // ps_2_0 budget: distance and cone attenuation come from the vertex shader.
        vec3 L = ts_light_direction(l, P);
        float att = i == 0 ? vertex_atten.x : vertex_atten.y;
#else
        vec3 L;
        float att = ts_light_attenuation(l, P, L);
#endif
        float NdotL = dot(N, L);
        diffuse += ml_light_diffuse(l, att, NdotL);
#if PHONG
        // Base kept >= TS_POW_TINY (common_math.glsl): pow(0, k) is undefined in GLSL ES (issue 14).
        float RdotL = max(saturate(dot(R, L)), TS_POW_TINY);
        vec3 lit = l.color.rgb * (saturate(NdotL) * att);
        spec += lit * pow(RdotL, k);
#if RIM_LIGHT
        rim += lit * pow(RdotL, rim_params.x);
#endif
#endif
    }

#if PHONG
    // Masks, Fresnel ranges, boost and tint (fact sheet section 5).
    vec4 fr = TS_UNIFORM_INPUT(ML_SLOT_FRESNEL, u_fresnel_ranges);
    float F = ts_fresnel_ranges(NdotV, fr.xyz);
    float mask = phong.w > 0.5 ? base.a : nmap.a;
    mask = fr.w > 0.5 ? 1.0 - mask : mask;
    float spec_mask = mask * F;
    spec = spec * (spec_mask * phong.z);
    vec4 tint = TS_UNIFORM_INPUT(ML_SLOT_PHONG_TINT, u_phong_tint);
#if PHONG_EXPONENT_MAP
    vec3 spec_tint = tint.w > 0.5 ? ts_lerp3_from_one(base.rgb, expmap.g) : tint.rgb;
#else
    vec3 spec_tint = tint.rgb;
#endif
#if RIM_LIGHT
    // Rim: masked by Fresnel4, never added twice (max), plus the ambient cube seen
    // along V on up-facing normals (+Y up here; Source's world is Z-up).
    float fresnel4 = ts_fresnel4(NdotV);
    float rim_mask = ts_lerp_from_one(expmap.a, rim_params.z);
    rim = rim * (rim_mask * fresnel4);
    spec = max(spec, rim);
    spec += ml_ambient_cube(V) * (rim_params.y * saturate(rim_mask * fresnel4 * N.y));
#endif
    vec3 color = spec * spec_tint;
#if ENVMAP
    // Envmap on models: scale * lerp(1, F, envmapfresnel) * mask * texCUBE(R) * tint.
    vec4 env = TS_UNIFORM_INPUT(ML_SLOT_ENVMAP, u_envmap_params);
    float env_mask = env.z > 0.5 ? mask : (fr.w > 0.5 ? 1.0 - base.a : base.a);
    float env_scale = env.x * ts_lerp_from_one(F, env.y) * env_mask;
    color += TS_TEXCUBE(u_envmap, R).rgb * env_scale * TS_UNIFORM_INPUT(ML_SLOT_ENVMAP_TINT, u_envmap_tint).rgb;
#endif
    // Self-illumination lerps the lit albedo toward tint * albedo by base alpha:
    // mix(albedo * diffuse, albedo * tint, t), written with the albedo factored out
    // because NIR rewrites flrp(a*c, b*c, t) into c * flrp(a, b, t) anyway.
    vec4 si = TS_UNIFORM_INPUT(ML_SLOT_SELF_ILLUM, u_self_illum);
    color += base.rgb * ts_lerp3(diffuse, si.rgb, base.a * si.w);
#else
    vec3 color = base.rgb * diffuse;
#endif
    TS_FRAG_COLOR = vec4(ts_final_output(color, params.x, OUTPUT_MODE), 1.0);
}

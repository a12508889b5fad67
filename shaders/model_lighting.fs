//------------------------------------------------------------------------------
// model_lighting.fs: Half-Life 2 model lighting (talk: "Model lighting":
// irradiance volume ambient cube, half-Lambert, local lights).
//   diffuse = ambientCube(N) + sum_i color_i * atten_i * D(N.L_i)
//   out     = FinalOutput(albedo * diffuse)        D = half-Lambert or Lambert
// Tiers: ps20 (<= 2 lights, attenuation per vertex, linear output), ps2b (<= 4
// lights, all per pixel), sm3 (a dynamic loop over a uniform light count). Lights beyond a tier's limit are folded into
// the ambient cube on the CPU (docs/light_folding.md).
// Variants: model_lighting.variants. C twin: c_ref/model_lighting.c.
// Inputs (slots): c_ref/model_lighting.h and model_lighting_slots.glsl.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_ambient_cube.glsl"
#include "common_lights.glsl"
#include "common_output.glsl"
#include "model_lighting_slots.glsl"

#ifdef TS_TIER_SM3
#define ML_LOOP_LIGHTS ML_MAX_LIGHTS
#else
#define ML_LOOP_LIGHTS NUM_LIGHTS
#endif

TS_VARYING_IN vec3 v_normal;     // world-space normal, as interpolated (not unit length)
TS_VARYING_IN vec3 v_position;   // world-space position
TS_VARYING_IN vec2 v_uv;
#ifdef TS_TIER_PS20
TS_VARYING_IN vec4 v_light_atten;  // per-vertex attenuation of lights 0..3 (model_lighting.vs)
#endif

uniform vec4 u_ambient_cube[6];  // +X -X +Y -Y +Z -Z
uniform vec4 u_lights[5 * ML_MAX_LIGHTS];
uniform vec4 u_params;           // x: tone-map scale, y: light count (sm3)
uniform vec4 u_albedo_color;
uniform sampler2D u_albedo;

TS_DECLARE_FRAG_COLOR

void main() {
    vec3 N = ts_safe_normalize(TS_PIXEL_INPUT(ML_SLOT_NORMAL, vec4(v_normal, 0.0)).xyz);
    vec3 P = TS_PIXEL_INPUT(ML_SLOT_POSITION, vec4(v_position, 1.0)).xyz;
    vec2 uv = TS_PIXEL_INPUT(ML_SLOT_UV, vec4(v_uv, 0.0, 0.0)).xy;
    vec4 params = TS_UNIFORM_INPUT(ML_SLOT_PARAMS, u_params);
#ifdef TS_TIER_PS20
    vec4 vertex_atten = TS_PIXEL_INPUT(ML_SLOT_VERTEX_ATTEN, v_light_atten);
#endif

    vec3 diffuse = ts_ambient_cube(N,
        TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 0, u_ambient_cube[0]).rgb, TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 1, u_ambient_cube[1]).rgb,
        TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 2, u_ambient_cube[2]).rgb, TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 3, u_ambient_cube[3]).rgb,
        TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 4, u_ambient_cube[4]).rgb, TS_UNIFORM_INPUT(ML_SLOT_AMBIENT + 5, u_ambient_cube[5]).rgb);

#ifdef TS_TIER_SM3
    int light_count = int(clamp(params.y, 0.0, float(ML_MAX_LIGHTS)));
#endif
    for (int i = 0; i < ML_LOOP_LIGHTS; ++i) {
#ifdef TS_TIER_SM3
        if (i >= light_count) break;
#endif
        TsLight l;
        l.color = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 0, u_lights[5 * i + 0]);
        l.dir   = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 1, u_lights[5 * i + 1]);
        l.pos   = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 2, u_lights[5 * i + 2]);
        l.spot  = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 3, u_lights[5 * i + 3]);
        l.atten = TS_UNIFORM_INPUT(ML_SLOT_LIGHT0 + 5 * i + 4, u_lights[5 * i + 4]);
#ifdef TS_TIER_PS20
        // ps_2_0 budget: distance and cone attenuation come from the vertex shader.
        vec3 L = ts_light_direction(l, P);
        float att = i == 0 ? vertex_atten.x : vertex_atten.y;
#else
        vec3 L;
        float att = ts_light_attenuation(l, P, L);
#endif
        float NdotL = dot(N, L);
#if HALF_LAMBERT
        float term = ts_half_lambert(NdotL);
#else
        float term = ts_lambert(NdotL);
#endif
        diffuse += l.color.rgb * (att * term);
    }

#if ALBEDO_TEXTURE
    vec3 albedo = TS_TEX2D(u_albedo, uv).rgb;
#else
    vec3 albedo = TS_UNIFORM_INPUT(ML_SLOT_ALBEDO, u_albedo_color).rgb;
#endif
    TS_FRAG_COLOR = vec4(ts_final_output(albedo * diffuse, params.x, OUTPUT_MODE), 1.0);
}

//------------------------------------------------------------------------------
// common_lights.glsl: local lights (point, spot, directional) and diffuse terms.
// Fact sheet section 4 (VertexAttenInternal): a light is 5 vec4
//   color (rgb, w = 1: directional), dir (xyz unit spot/sun direction, w = 1: spot),
//   pos (xyz), spot (x exponent, z cos outer cone, w 1/(cos inner - cos outer)),
//   atten (x constant, y linear, z quadratic).
// Distance attenuation 1/(c + l d + q d^2); spot s = saturate(pow(max(1e-4, (cos - spot.z) spot.w), spot.x));
// a directional light shines along dir (L = -dir) with attenuation 1.
// Half-Lambert (talk "Half Lambert"; fact sheet section 4): saturate(0.5 N.L + 0.5)^2.
// C twin: c_ref/common/common_lights.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_LIGHTS_GLSL
#define TS_COMMON_LIGHTS_GLSL

// Keeps d*d below FLT_MAX, so a zero coefficient times d*d is 0, never 0*inf = NaN.
// fp16: NOT a half-float number (above the largest, 65504): in fp16 (mediump on llvmpipe's
// GLES) it is +Inf and the min() clamps nothing; d*d overflows to Inf from d = 256 on, so a
// zero coefficient gives 0 * Inf = NaN again. Mediump variants keep lights within 256 units.
#define TS_MAX_LIGHT_DISTANCE 1.0e18

struct TsLight {
    vec4 color;
    vec4 dir;
    vec4 pos;
    vec4 spot;
    vec4 atten;
};

// Returns the light's attenuation (distance x spot cone) at P and its unit
// direction L (0 when the light sits exactly on P, so N.L = 0 there).
float ts_light_attenuation(TsLight l, vec3 P, out vec3 L) {
    vec3 Lv = l.pos.xyz - P;
    float d2 = max(dot(Lv, Lv), TS_MIN_LENGTH2);
    float rinv = inversesqrt(d2);
    float d = min(d2 * rinv, TS_MAX_LIGHT_DISTANCE);
    bool directional = l.color.w > 0.5;
    L = directional ? -l.dir.xyz : Lv * rinv;
    // Written out, not dot(atten, vec3(1, d, d*d)): NIR reorders a dot with a constant 1.0 lane.
    // The denominator is kept >= TS_MIN_LENGTH2: all-zero coefficients give 1e30, not 1/0 = Inf,
    // whose product with a zero N.L term would be NaN (issue 14: no NaN from finite inputs).
    float dist_att = 1.0 / max(l.atten.x + l.atten.y * d + l.atten.z * (d * d), TS_MIN_LENGTH2);
    dist_att = directional ? 1.0 : dist_att;
    float cos_a = dot(-L, l.dir.xyz);
    float spot = saturate(pow(max(1.0e-4, (cos_a - l.spot.z) * l.spot.w), l.spot.x));
    spot = l.dir.w > 0.5 ? spot : 1.0;
    return dist_att * spot;
}

// Direction only, for ps20: there the attenuation (distance and cone) is computed per
// vertex and interpolated, as in Source's ps_2_0 vertexlit shaders (fact sheet section 4:
// "per-light attenuation is computed per vertex and interpolated; N.L is computed per pixel").
// Same bits as the L of ts_light_attenuation.
vec3 ts_light_direction(TsLight l, vec3 P) {
    vec3 Lv = l.pos.xyz - P;
    float rinv = inversesqrt(max(dot(Lv, Lv), TS_MIN_LENGTH2));
    return l.color.w > 0.5 ? -l.dir.xyz : Lv * rinv;
}

float ts_half_lambert(float NdotL) {
    float h = saturate(0.5 * NdotL + 0.5);
    return h * h;
}

float ts_lambert(float NdotL) {
    return saturate(NdotL);
}

#endif

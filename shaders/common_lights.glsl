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

// The packed light of ps20 and ps2b fragment programs (u_light_pack, issue 14): the 17 values a
// light's shading reads in 4 vec4 instead of 5, so that 4 ps2b lights fit ps_2_b's 32 constant
// registers beside the Phong block and 2 ps20 lights WebGL 1's 16 fragment uniform vectors
// (docs/tiers.md; fact sheet section 4: Source, too, packs light data into .w components):
//   p0 = (color.rgb, atten.x)   p1 = (dir.xyz, flags)   p2 = (pos.xyz, atten.y)
//   p3 = (spot.x, atten.z, spot.z, spot.w)
// flags = (directional ? 1 : -1) * (spot ? 2 : 1), directional = color.w > 0.5 and spot =
// dir.w > 0.5 of the unpacked light (the host packer: ml_pack_lights,
// glue/families/model_lighting.cpp). Unpacked, color.w = flags (> 0.5 exactly when directional)
// and dir.w = |flags| - 1 (1 for a spot, else 0), and every other field the shading reads has the
// bits it had unpacked (moves only; pos.w, spot.y and atten.w are read by nothing), so each test
// and value is the unpacked one and the C twin, which reads the unpacked record, stays bit-exact.
// No constant lanes, so the moves fold away (the ps_2_0 slot count stays). The host keeps NaN out
// of uniforms (docs/conformance.md).
TsLight ts_light_unpack(vec4 p0, vec4 p1, vec4 p2, vec4 p3) {
    TsLight l;
    l.color = vec4(p0.rgb, p1.w);
    l.dir = vec4(p1.xyz, abs(p1.w) - 1.0);
    l.pos = p2;
    l.spot = p3;
    l.atten = vec4(p0.w, p2.w, p3.y, p3.y);
    return l;
}

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

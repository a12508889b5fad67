//------------------------------------------------------------------------------
// common_phong.glsl: the Episode One Phong terms of model lighting.
// Talk: "Phong terms" (Half-Life 2: Episode One); fact sheet section 5 (skin shader):
//   R = 2 N (N.V) - V (reflected view, not Blinn)
//   spec_i = saturate(R.L)^k * saturate(N.L) * color_i * atten_i
//   Fresnel ranges: f = saturate(1 - N.V)^2, piecewise linear through (0, min),
//     (0.5, mid), (1, max); uploaded as ((mid-min)*2, mid, (max-mid)*2)
//   rim_i = saturate(R.L)^rimexp * saturate(N.L) * color_i * atten_i, times
//     rimMask * Fresnel4, Fresnel4 = saturate(1 - N.V)^4; spec = max(spec, rim)
// Lerps are mix(). llvmpipe lowers NIR's flrp (lower_flrp32, nir_lower_flrp.c), and
// the form depends on the operands; measured on Mesa 22.3:
//   mix(a, b, t), nothing constant  ->  a + (b - a) * t
//   mix(1.0, b, t)                  ->  (1 - t) + b * t
// Both unfused. A written-out a + (b - a) * t is NOT safe: in some contexts it came
// out fused (1 ULP apart, measured), so the twin could not mirror it.
// C twin: c_ref/common/common_phong.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_PHONG_GLSL
#define TS_COMMON_PHONG_GLSL

float ts_fresnel_ranges(float NdotV, vec3 ranges) {
    float f = saturate(1.0 - NdotV);
    f = f * f;
    return ranges.y + (f - 0.5) * (f >= 0.5 ? ranges.z : ranges.x);
}

// saturate(1 - N.V)^4 (fact sheet section 5: Source's Fresnel4 saturates f like Fresnel): at most
// 1, so a back-facing shading normal (N.V = -1) cannot make the rim 16 times brighter.
float ts_fresnel4(float NdotV) {
    float f = saturate(1.0 - NdotV);
    f = f * f;
    return f * f;
}

vec3 ts_lerp3(vec3 a, vec3 b, float t) {
    return mix(a, b, t);
}

float ts_lerp_from_one(float b, float t) {
    return mix(1.0, b, t);
}

vec3 ts_lerp3_from_one(vec3 b, float t) {
    return mix(vec3(1.0), b, t);
}

#endif

//------------------------------------------------------------------------------
// common_envmap.glsl: world specular from a cube map (fact sheet section 6;
// talk: "World specular ... cube maps").
//   R = 2 (N.E) N - (N.N) E, unnormalised (CalcReflectionVectorUnnormalized)
//   s = ENV_MAP_SCALE * texCUBE(R) * mask * tint
//   s = lerp(s, s^2, contrast); s = lerp(luma(s), s, saturation), luma weights
//       (0.299, 0.587, 0.114)
//   F = (1 - N.V)^5 (1 - R0) + R0, with N.V saturated (a back-facing or grazing
//       normal gives F = 1, never above it)
// The lerps are mix(), like every lerp in the library (docs/conformance.md). Mesa rewrites
// mix(s, s*s, c) to s * mix(1, s, c) = s * ((1 - c) + s*c), and mix(luma, s, t), whose a and t
// are the same in all three lanes, to luma*(1 - t) + s*t (measured, unfused); the C twin
// mirrors both forms.
// C twin: c_ref/common/common_envmap.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_ENVMAP_GLSL
#define TS_COMMON_ENVMAP_GLSL

vec3 ts_reflect_unnormalized(vec3 N, vec3 E) {
    return 2.0 * dot(N, E) * N - dot(N, N) * E;
}

vec3 ts_envmap_contrast(vec3 s, float contrast) {
    return mix(s, s * s, contrast);
}

vec3 ts_envmap_saturation(vec3 s, float saturation) {
    float luma = dot(s, vec3(0.299, 0.587, 0.114));
    return mix(vec3(luma), s, saturation);
}

// cos(N, E) = N.E / sqrt((N.N)(E.E)) with one inversesqrt (ps20's normalization
// trick; the reflection vector already computed N.E and N.N). The product is clamped
// to TS_MIN_LENGTH2, so a zero vector gives 0, not NaN.
float ts_cosine_between(vec3 N, vec3 E) {
    return dot(N, E) * inversesqrt(max(dot(N, N) * dot(E, E), TS_MIN_LENGTH2));
}

// one_minus_r0 and r0 as Source uploads them (c4 = [0, 0, 1 - R0, R0]).
float ts_fresnel(float NdotV, float one_minus_r0, float r0) {
    float x = 1.0 - saturate(NdotV);
    float x2 = x * x;
    return (x2 * x2) * (x * one_minus_r0) + r0;  // balanced: see world_lighting.fs
}

#endif

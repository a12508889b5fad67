//------------------------------------------------------------------------------
// common_output.glsl: the end of every lit shader, after Source's FinalOutput.
// Fact sheet section 7: rgb *= LINEAR_LIGHT_SCALE (the tone-map scale), then the
// output encoding: linear (HDR float target, or an sRGB render target doing the
// encoding in hardware, as ps_2_0 relies on), gamma 2.2 (LinearToGamma = pow 1/2.2),
// or the exact sRGB curve (fact sheet section 2: <= 0.0031308 -> 12.92 x, else
// 1.055 x^(1/2.4) - 0.055). Every path clamps, so no NaN or Inf leaves a shader:
// llvmpipe's clamp returns the lower bound for NaN (platform notes section 4).
// C twin: c_ref/common/common_output.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_OUTPUT_GLSL
#define TS_COMMON_OUTPUT_GLSL

#define TS_OUTPUT_LINEAR 0
#define TS_OUTPUT_GAMMA22 1
#define TS_OUTPUT_SRGB 2

// Linear HDR output: [0, 65504], NaN -> 0, +Inf -> 65504.
vec3 ts_output_linear(vec3 c) {
    return clamp(c, 0.0, TS_FP16_MAX);
}

vec3 ts_output_gamma22(vec3 c) {
    // pow's base >= TS_POW_TINY: black gives 2^(-60/2.2) = 6.2e-9, not the undefined pow(0, y)
    // (common_math.glsl; an RGBA8 or fp16 target stores 0 for both).
    return saturate(pow(max(saturate(c), TS_POW_TINY), vec3(1.0 / 2.2)));
}

float ts_srgb_encode(float x) {
    // The max() changes no selected value (the pow side is taken above 0.0031308); it keeps the
    // pow defined where the error bounds take both sides of the comparison.
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(max(x, TS_POW_TINY), 1.0 / 2.4) - 0.055;
}

vec3 ts_output_srgb(vec3 c) {
    vec3 s = saturate(c);
    return saturate(vec3(ts_srgb_encode(s.r), ts_srgb_encode(s.g), ts_srgb_encode(s.b)));
}

vec3 ts_final_output(vec3 c, float tone_map_scale, int mode) {
    c = c * tone_map_scale;
    if (mode == TS_OUTPUT_GAMMA22) return ts_output_gamma22(c);
    if (mode == TS_OUTPUT_SRGB) return ts_output_srgb(c);
    return ts_output_linear(c);
}

#endif

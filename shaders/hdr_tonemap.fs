//------------------------------------------------------------------------------
// hdr_tonemap.fs: the last pass of the float HDR path (talk: "Implemented Multiple
// HDR Paths: Floating point"; fact sheet section 7, HDRFinal_Float and
// floattoscreen_combine): the linear fp16 frame is tone-mapped and the bloom,
// built from the pre-tone-map data, is added:
//   b   = min(bloom * sqrt(scale), 1)            (bloom pre-scaled, clamped to 1)
//   out = scale * fb + amount * lum(b)^exp * b
// then Source's output encoding (common_output.glsl: linear, gamma 2.2 or exact sRGB).
// The bloom texture is the quarter-size blurred bloom, upsampled by bilinear filtering.
// The vignette of floatcombine is not reproduced (docs/hdr.md).
// Variants: hdr_tonemap.variants. C twin: c_ref/twins/hdr_tonemap.c.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_hdr.glsl"
#include "common_output.glsl"
#include "hdr_tonemap_slots.glsl"

uniform sampler2D u_frame;     // linear HDR frame (fp16), NEAREST, the size of the target
uniform sampler2D u_bloom;     // quarter-size bloom, LINEAR, CLAMP_TO_EDGE
uniform vec4 u_frame_size;     // xy size in pixels, zw 1 / size
uniform vec4 u_params;         // x tone-map scale, y bloom amount, z bloom exponent

TS_DECLARE_FRAG_COLOR

void main() {
    vec2 pos = TS_PIXEL_INPUT(HT_SLOT_POS, vec4(gl_FragCoord.xy, 0.0, 0.0)).xy;
    vec4 size = TS_UNIFORM_INPUT(HT_SLOT_SIZE, u_frame_size);
    vec3 fb = TS_PIXEL_INPUT(HT_SLOT_FRAME, ts_frame_texel(u_frame, gl_FragCoord.xy, u_frame_size)).rgb;
    vec4 params = TS_UNIFORM_INPUT(HT_SLOT_PARAMS, u_params);
    vec3 bloom = TS_TEX2D(u_bloom, pos * size.zw).rgb;
    // max(): a negative tone-map scale gives sqrt(0), not sqrt(-x) = NaN, whose min() with 1 is 1 on
    // llvmpipe and NaN where min returns its first operand (issue 14).
    bloom = min(bloom * sqrt(max(params.x, 0.0)), 1.0);
    // pow's base >= TS_POW_TINY (common_math.glsl): no bloom gives amount * tiny^exp * 0 = 0.
    vec3 c = fb * params.x + (params.y * pow(max(ts_luminance(bloom), TS_POW_TINY), params.z)) * bloom;
#if OUTPUT_MODE == TS_OUTPUT_GAMMA22
    c = ts_output_gamma22(c);
#elif OUTPUT_MODE == TS_OUTPUT_SRGB
    c = ts_output_srgb(c);
#else
    c = ts_output_linear(c);
#endif
    TS_FRAG_COLOR = vec4(c, 1.0);
}

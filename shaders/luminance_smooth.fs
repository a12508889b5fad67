//------------------------------------------------------------------------------
// luminance_smooth.fs: a temporal prefilter of the luminance the auto-exposure
// histogram measures (docs/hdr.md, "Flicker"). The running histogram samples each
// bucket once every 17 frames (talk: "Auto Exposure: update one bucket per frame"),
// so a light flickering with a period near a divisor of that revisit time aliases
// into a slow drift of the histogram, which the exposure then follows. Counting the
// buckets on an exponentially smoothed luminance image removes that:
//   L = dot(fb, (0.2125, 0.7154, 0.0721)) * tscale     (fact sheet section 8)
//   S = S_prev + alpha * (L - S_prev)
// alpha = 1 gives Source's histogram of the current frame. Output: (S, S, S, 1) in
// [0, 65504] for an fp16 target; luminance_compare reads it with INPUT_ENCODING 2.
// INPUT_ENCODING as in luminance_compare: 0 linear HDR frame, 1 sRGB-encoded RGBA8 frame.
// Variants: luminance_smooth.variants. C twin: c_ref/twins/luminance_smooth.c.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_hdr.glsl"
#include "common_output.glsl"
#include "luminance_smooth_slots.glsl"

uniform sampler2D u_frame;     // the tone-mapped (integer) or linear (float) frame
uniform sampler2D u_history;   // the previous smoothed luminance (fp16), the size of the target
uniform vec4 u_frame_size;     // xy size in pixels, zw 1 / size
uniform vec4 u_params;         // x alpha, y tone-map scale

TS_DECLARE_FRAG_COLOR

void main() {
    vec3 c = TS_PIXEL_INPUT(LS_SLOT_COLOR, ts_frame_texel(u_frame, gl_FragCoord.xy, u_frame_size)).rgb;
    float prev = TS_PIXEL_INPUT(LS_SLOT_HISTORY, ts_frame_texel(u_history, gl_FragCoord.xy, u_frame_size)).x;
    vec4 params = TS_UNIFORM_INPUT(LS_SLOT_PARAMS, u_params);
#if INPUT_ENCODING == 1
    c = ts_srgb_decode3(c);
#endif
    float lum = ts_luminance(c) * params.y;
    float s = clamp(prev + params.x * (lum - prev), 0.0, TS_FP16_MAX);
    TS_FRAG_COLOR = vec4(s, s, s, 1.0);
}

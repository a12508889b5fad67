//------------------------------------------------------------------------------
// luminance_compare.fs: the bucket test of the auto-exposure histogram
// (talk: "Auto Exposure": "each frame, we determine which output pixels fall
// within a given range ... use an asynchronous occlusion query to count pixels").
//   lum  = dot(fb * tscale, (0.2125, 0.7154, 0.0721)) = dot(fb, w) * tscale
//   mark = step(min, lum) * step(lum, max)       (fact sheet section 8)
// A marked pixel writes 1; every other pixel is discarded, so that an occlusion
// query counts exactly the marked pixels (glue/hdr/luminance_histogram.cpp).
// INPUT_ENCODING 0: the float path's linear HDR frame, scaled by the tone-map scale;
// 1: the integer path's sRGB-encoded RGBA8 frame, decoded to linear (tscale = 1);
// 2: a luminance image (luminance_smooth.fs), lum = r * tscale (tscale = 1).
// Variants: luminance_compare.variants. C twin: c_ref/twins/luminance_compare.c.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_hdr.glsl"
#include "luminance_compare_slots.glsl"

uniform sampler2D u_frame;     // the frame being measured, the size of the target
uniform vec4 u_frame_size;     // xy size in pixels, zw 1 / size
uniform vec4 u_range;          // x bucket min, y bucket max, z tone-map scale

TS_DECLARE_FRAG_COLOR

void main() {
    vec3 c = TS_PIXEL_INPUT(LC_SLOT_COLOR, ts_frame_texel(u_frame, gl_FragCoord.xy, u_frame_size)).rgb;
    vec4 range = TS_UNIFORM_INPUT(LC_SLOT_RANGE, u_range);
#if INPUT_ENCODING == 2
    float lum = c.r * range.z;
#else
#if INPUT_ENCODING == 1
    c = ts_srgb_decode3(c);
#endif
    // dot(fb * tscale, w) written as dot(fb, w) * tscale: NIR factors the scalar out of
    // the dot product when the product has one use, so this is the form llvmpipe runs.
    float lum = ts_luminance(c) * range.z;
#endif
    float mark = ts_in_bucket(lum, range.x, range.y);
    if (mark < 0.5) discard;
    TS_FRAG_COLOR = vec4(mark);
}

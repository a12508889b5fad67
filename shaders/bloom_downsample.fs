//------------------------------------------------------------------------------
// bloom_downsample.fs: the first bloom pass, a quarter-size copy of the frame.
// Fact sheet section 8 (Generate8BitBloomTexture): 4 bilinear taps, each at the
// centre of a 2x2 texel quad of the pixel's 4x4 source block, i.e. a 4x4 box.
// In GL's convention (texel centres at i + 0.5) the quad centres of the block
// starting at texel 4i are 4i + 1 and 4i + 3, i.e. 4p -+ 1 for the fragment
// position p = i + 0.5.
//   SHAPE 0: the plain box of the linear HDR frame (float path: the bright
//            shaping happens in the final combine, fact sheet section 7);
//   SHAPE 1: each tap shaped as p^exp * dot(p, tint) before averaging.
// Output: linear HDR in [0, 65504] (an fp16 target), NaN -> 0.
// Variants: bloom_downsample.variants. C twin: c_ref/twins/bloom_downsample.c.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_hdr.glsl"
#include "common_output.glsl"
#include "bloom_downsample_slots.glsl"

uniform sampler2D u_source;    // the linear HDR frame: LINEAR, CLAMP_TO_EDGE
uniform vec4 u_source_size;    // xy size in texels, zw 1 / size
uniform vec4 u_shape;          // rgb tint, w exponent

TS_DECLARE_FRAG_COLOR

vec3 bd_tap(vec2 texel, vec4 size, vec4 shape) {
    vec3 p = TS_TEX2D(u_source, texel * size.zw).rgb;
#if SHAPE
    p = ts_bloom_shape(p, shape);
#endif
    return p;
}

void main() {
    vec2 pos = TS_PIXEL_INPUT(BD_SLOT_POS, vec4(gl_FragCoord.xy, 0.0, 0.0)).xy;
    vec4 size = TS_UNIFORM_INPUT(BD_SLOT_SIZE, u_source_size);
    vec4 shape = TS_UNIFORM_INPUT(BD_SLOT_SHAPE, u_shape);
    vec2 c = pos * 4.0;
    vec3 sum = bd_tap(c - 1.0, size, shape);
    // One vector add per tap, not two scalar ones and a construct: the same values (c - 1 and
    // c + -1 are one IEEE operation), 4 ps_2_0 slots less, which pay for the pow guards of
    // ts_bloom_shape (issue 14; 64 + 32 slots on ps20).
    sum += bd_tap(c + vec2(1.0, -1.0), size, shape);
    sum += bd_tap(c + vec2(-1.0, 1.0), size, shape);
    sum += bd_tap(c + 1.0, size, shape);
    TS_FRAG_COLOR = vec4(ts_output_linear(sum * 0.25), 1.0);
}

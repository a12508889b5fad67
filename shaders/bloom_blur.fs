//------------------------------------------------------------------------------
// bloom_blur.fs: one direction of the separable Gaussian bloom blur.
// Fact sheet section 8 (BlurFilter, BlurFilterY): 13 bilinear taps, the centre
// with weight 0.2013 and six pairs at +-offset texels, each pair sampling between
// two texels so that it stands for both:
//   offsets 1.3366 3.4295 5.4264 7.4359 9.4436 11.4401
//   weights 0.2185 0.0821 0.0461 0.0262 0.0162 0.0102   (sum with the centre 0.9999)
// The Y pass multiplies by the bloom amount (u_params.x; 1 in the X pass).
// Output: linear HDR in [0, 65504], NaN -> 0.
// Variants: bloom_blur.variants (DIRECTION 0 = X, 1 = Y). C twin: c_ref/twins/bloom_blur.c.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_output.glsl"
#include "bloom_blur_slots.glsl"

uniform sampler2D u_source;    // LINEAR, CLAMP_TO_EDGE
uniform vec4 u_source_size;    // xy size in texels, zw 1 / size
uniform vec4 u_params;         // x output scale

TS_DECLARE_FRAG_COLOR

// The two taps at pos -+ offset texels along the pass direction. Written as
// (pos + offset) / size, not pos / size + offset / size: NIR factors a*b + a*c
// into a*(b + c), so this is the form llvmpipe runs either way.
vec3 bb_pair(vec2 pos, float offset, vec4 size) {
#if DIRECTION == 0
    float v = pos.y * size.w;
    return TS_TEX2D(u_source, vec2((pos.x + offset) * size.z, v)).rgb +
           TS_TEX2D(u_source, vec2((pos.x - offset) * size.z, v)).rgb;
#else
    float u = pos.x * size.z;
    return TS_TEX2D(u_source, vec2(u, (pos.y + offset) * size.w)).rgb +
           TS_TEX2D(u_source, vec2(u, (pos.y - offset) * size.w)).rgb;
#endif
}

void main() {
    vec2 pos = TS_PIXEL_INPUT(BB_SLOT_POS, vec4(gl_FragCoord.xy, 0.0, 0.0)).xy;
    vec4 size = TS_UNIFORM_INPUT(BB_SLOT_SIZE, u_source_size);
    vec4 params = TS_UNIFORM_INPUT(BB_SLOT_PARAMS, u_params);
    vec3 sum = 0.2013 * TS_TEX2D(u_source, pos * size.zw).rgb;
    sum += 0.2185 * bb_pair(pos, 1.3366, size);
    sum += 0.0821 * bb_pair(pos, 3.4295, size);
    sum += 0.0461 * bb_pair(pos, 5.4264, size);
    sum += 0.0262 * bb_pair(pos, 7.4359, size);
    sum += 0.0162 * bb_pair(pos, 9.4436, size);
    sum += 0.0102 * bb_pair(pos, 11.4401, size);
    TS_FRAG_COLOR = vec4(ts_output_linear(sum * params.x), 1.0);
}

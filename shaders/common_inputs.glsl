//------------------------------------------------------------------------------
// common_inputs.glsl: where a shader's inputs come from.
// In an engine (production) each input is a uniform or a varying. In conformance
// mode (TS_CONFORM) every input comes from a per-pixel record in an RGBA32F
// texture: pixel (x, y) reads slot k at texel (x, y + k * grid height). The same
// entry code runs in both modes; only the source of each value changes.
// Model: piglit's data-driven shader tests and OpenColorIO's GPU tests (docs/conformance.md).
//------------------------------------------------------------------------------
#ifndef TS_COMMON_INPUTS_GLSL
#define TS_COMMON_INPUTS_GLSL

#ifdef TS_CONFORM
uniform sampler2D ts_record;     // RGBA32F, NEAREST, W x (H * slots)
uniform vec2 ts_record_size;     // (W, H * slots), powers of two
uniform float ts_grid_height;    // H

vec4 ts_fetch(int slot) {
#ifdef TS_HAS_TEXEL_FETCH
    return texelFetch(ts_record, ivec2(gl_FragCoord.xy) + ivec2(0, slot * int(ts_grid_height)), 0);
#else
    // GLSL ES 1.00 has no texelFetch: sample the texel centre with NEAREST filtering.
    vec2 p = gl_FragCoord.xy + vec2(0.0, float(slot) * ts_grid_height);
    return texture2D(ts_record, p / ts_record_size);
#endif
}
#define TS_INPUT(slot, production) ts_fetch(slot)
#else
#define TS_INPUT(slot, production) (production)
#endif

#endif

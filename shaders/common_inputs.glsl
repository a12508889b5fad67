//------------------------------------------------------------------------------
// common_inputs.glsl: where a shader's inputs come from.
// Three modes, one entry code; only the source of each value changes:
//  - production (default): per-pixel inputs are varyings, the rest uniforms;
//  - TS_CONFORM: every input comes from a per-pixel record in an RGBA32F texture,
//    pixel (x, y) reading slot k at texel (x, y + k * grid height), so that each
//    pixel of a conformance grid has its own lights, parameters, ...;
//  - TS_DEFERRED: per-pixel inputs come from the record (a G-buffer of the first
//    slots), the rest from the production uniforms (demo and benchmark frames).
// Model: piglit's data-driven shader tests and OpenColorIO's GPU tests (docs/conformance.md).
//------------------------------------------------------------------------------
#ifndef TS_COMMON_INPUTS_GLSL
#define TS_COMMON_INPUTS_GLSL

#if defined(TS_CONFORM) || defined(TS_DEFERRED)
uniform sampler2D ts_record;     // RGBA32F, NEAREST, W x (H * slots)
uniform vec2 ts_record_size;     // (W, H * slots), powers of two
uniform float ts_grid_height;    // H

vec4 ts_fetch(int slot) {
#ifdef TS_HAS_TEXEL_FETCH
    return texelFetch(ts_record, ivec2(gl_FragCoord.xy) + ivec2(0, slot * int(ts_grid_height)), 0);
#else
    // GLSL ES 1.00 has no texelFetch: sample the texel centre with NEAREST filtering.
    vec2 p = gl_FragCoord.xy + vec2(0.0, float(slot) * ts_grid_height);
    return TS_TEX2D(ts_record, p / ts_record_size);
#endif
}
#endif

#if defined(TS_CONFORM)
#define TS_PIXEL_INPUT(slot, production) ts_fetch(slot)
#define TS_UNIFORM_INPUT(slot, production) ts_fetch(slot)
#elif defined(TS_DEFERRED)
#define TS_PIXEL_INPUT(slot, production) ts_fetch(slot)
#define TS_UNIFORM_INPUT(slot, production) (production)
#else
#define TS_PIXEL_INPUT(slot, production) (production)
#define TS_UNIFORM_INPUT(slot, production) (production)
#endif

#endif

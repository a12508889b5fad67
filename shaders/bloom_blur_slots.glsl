//------------------------------------------------------------------------------
// bloom_blur_slots.glsl: the input record of bloom_blur (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum bb_slot (c_ref/twins/bloom_blur.h), the slot names and
// the uniforms bound in deferred frames (glue/families/bloom_blur.cpp). Row format:
// shaders/ts_slot_table.glsl. Slots below BB_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define BB_PIXEL_SLOTS 1
#define BB_SLOTS 3
// xy: the fragment position (gl_FragCoord.xy); target size = source size
TS_SLOT(BB_SLOT_POS, 0, 1, position, one, gl_FragCoord)
// the source: xy size in texels, zw 1 / size
TS_SLOT(BB_SLOT_SIZE, 1, 1, source_size, one, u_source_size)
// x: output scale (1 for the X pass, the bloom amount for the Y pass)
TS_SLOT(BB_SLOT_PARAMS, 2, 1, params, one, u_params)

//------------------------------------------------------------------------------
// bloom_downsample_slots.glsl: the input record of bloom_downsample (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum bd_slot (c_ref/twins/bloom_downsample.h), the slot names and
// the uniforms bound in deferred frames (glue/families/bloom_downsample.cpp). Row format:
// shaders/ts_slot_table.glsl. Slots below BD_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define BD_PIXEL_SLOTS 1
#define BD_SLOTS 3
// xy: the fragment position in the quarter-size target (gl_FragCoord.xy)
TS_SLOT(BD_SLOT_POS, 0, 1, position, one, gl_FragCoord)
// the source: xy size in texels, zw 1 / size
TS_SLOT(BD_SLOT_SIZE, 1, 1, source_size, one, u_source_size)
// rgb bloom tint, w tint exponent (SHAPE = 1)
TS_SLOT(BD_SLOT_SHAPE, 2, 1, shape, one, u_shape)

//------------------------------------------------------------------------------
// luminance_compare_slots.glsl: the input record of luminance_compare (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum lc_slot (c_ref/twins/luminance_compare.h), the slot names and
// the uniforms bound in deferred frames (glue/families/luminance_compare.cpp). Row format:
// shaders/ts_slot_table.glsl. Slots below LC_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define LC_PIXEL_SLOTS 1
#define LC_SLOTS 2
// the measured frame's texel under the pixel
TS_SLOT(LC_SLOT_COLOR, 0, 1, color, one, u_frame)
// x bucket min, y bucket max, z tone-map scale (float path; 1 otherwise)
TS_SLOT(LC_SLOT_RANGE, 1, 1, range, one, u_range)

//------------------------------------------------------------------------------
// luminance_smooth_slots.glsl: the input record of luminance_smooth (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum ls_slot (c_ref/twins/luminance_smooth.h), the slot names and
// the uniforms bound in deferred frames (glue/families/luminance_smooth.cpp). Row format:
// shaders/ts_slot_table.glsl. Slots below LS_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define LS_PIXEL_SLOTS 2
#define LS_SLOTS 3
// the frame's texel under the pixel
TS_SLOT(LS_SLOT_COLOR, 0, 1, color, one, u_frame)
// x: the smoothed luminance of the previous frame under the pixel
TS_SLOT(LS_SLOT_HISTORY, 1, 1, history, one, u_history)
// x: blend weight alpha of the new frame, y: tone-map scale (1 for the integer path)
TS_SLOT(LS_SLOT_PARAMS, 2, 1, params, one, u_params)

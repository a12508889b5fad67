//------------------------------------------------------------------------------
// color_correction_slots.glsl: the input record of color_correction (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum cc_slot (c_ref/twins/color_correction.h), the slot names and
// the uniforms bound in deferred frames (glue/families/color_correction.cpp). Row format:
// shaders/ts_slot_table.glsl. Slots below CC_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define CC_MAX_LOOKUPS 4
#define CC_PIXEL_SLOTS 1
#define CC_SLOTS 4
// the colour to correct (display-encoded frame value), alpha passes through; the frame of
// TS_DEFERRED frames
TS_SLOT(CC_SLOT_COLOR, 0, 1, color, one, u_frame)
// weights of LUTs 0..3
TS_SLOT(CC_SLOT_WEIGHTS, 1, 1, weights, one, u_cc_weights)
// x: the default weight (of the uncorrected colour)
TS_SLOT(CC_SLOT_PARAMS, 2, 1, params, one, u_cc_params)
// LUT addressing for edge N: x (N-1)/N, y 0.5/N, z N-1, w 1/N
TS_SLOT(CC_SLOT_LUT, 3, 1, lut, one, u_cc_lut)

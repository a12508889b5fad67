//------------------------------------------------------------------------------
// color_correction_slots.glsl: the input record of color_correction (one vec4 per slot).
// Must match enum cc_slot in c_ref/twins/color_correction.h.
//------------------------------------------------------------------------------
#ifndef TS_COLOR_CORRECTION_SLOTS_GLSL
#define TS_COLOR_CORRECTION_SLOTS_GLSL
#define CC_MAX_LOOKUPS 4
#define CC_SLOT_COLOR 0    // the colour to correct (display-encoded frame value), alpha passes through
#define CC_SLOT_WEIGHTS 1  // weights of LUTs 0..3
#define CC_SLOT_PARAMS 2   // x: the default weight (of the uncorrected colour)
#define CC_SLOT_LUT 3      // LUT addressing for edge N: x (N-1)/N, y 0.5/N, z N-1, w 1/N
#define CC_SLOTS 4
#define CC_PIXEL_SLOTS 1   // the colour: the frame of TS_DEFERRED frames
#endif

//------------------------------------------------------------------------------
// luminance_smooth_slots.glsl: the input record of luminance_smooth.
// Must match enum ls_slot in c_ref/twins/luminance_smooth.h.
//------------------------------------------------------------------------------
#ifndef TS_LUMINANCE_SMOOTH_SLOTS_GLSL
#define TS_LUMINANCE_SMOOTH_SLOTS_GLSL
#define LS_SLOT_COLOR 0    // the frame's texel under the pixel
#define LS_SLOT_HISTORY 1  // x: the smoothed luminance of the previous frame under the pixel
#define LS_SLOT_PARAMS 2   // x: blend weight alpha of the new frame, y: tone-map scale (1 for the integer path)
#define LS_SLOTS 3
#define LS_PIXEL_SLOTS 2
#endif

//------------------------------------------------------------------------------
// luminance_compare_slots.glsl: the input record of luminance_compare.
// Must match enum lc_slot in c_ref/twins/luminance_compare.h.
//------------------------------------------------------------------------------
#ifndef TS_LUMINANCE_COMPARE_SLOTS_GLSL
#define TS_LUMINANCE_COMPARE_SLOTS_GLSL
#define LC_SLOT_COLOR 0   // the measured frame's texel under the pixel
#define LC_SLOT_RANGE 1   // x bucket min, y bucket max, z tone-map scale (float path; 1 otherwise)
#define LC_SLOTS 2
#define LC_PIXEL_SLOTS 1
#endif

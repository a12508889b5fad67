//------------------------------------------------------------------------------
// bloom_blur_slots.glsl: the input record of bloom_blur.
// Must match enum bb_slot in c_ref/twins/bloom_blur.h.
//------------------------------------------------------------------------------
#ifndef TS_BLOOM_BLUR_SLOTS_GLSL
#define TS_BLOOM_BLUR_SLOTS_GLSL
#define BB_SLOT_POS 0     // xy: the fragment position (gl_FragCoord.xy); target size = source size
#define BB_SLOT_SIZE 1    // the source: xy size in texels, zw 1 / size
#define BB_SLOT_PARAMS 2  // x: output scale (1 for the X pass, the bloom amount for the Y pass)
#define BB_SLOTS 3
#define BB_PIXEL_SLOTS 1
#endif

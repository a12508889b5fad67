//------------------------------------------------------------------------------
// bloom_downsample_slots.glsl: the input record of bloom_downsample.
// Must match enum bd_slot in c_ref/twins/bloom_downsample.h.
//------------------------------------------------------------------------------
#ifndef TS_BLOOM_DOWNSAMPLE_SLOTS_GLSL
#define TS_BLOOM_DOWNSAMPLE_SLOTS_GLSL
#define BD_SLOT_POS 0     // xy: the fragment position in the quarter-size target (gl_FragCoord.xy)
#define BD_SLOT_SIZE 1    // the source: xy size in texels, zw 1 / size
#define BD_SLOT_SHAPE 2   // rgb bloom tint, w tint exponent (SHAPE = 1)
#define BD_SLOTS 3
#define BD_PIXEL_SLOTS 1
#endif

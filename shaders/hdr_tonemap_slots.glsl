//------------------------------------------------------------------------------
// hdr_tonemap_slots.glsl: the input record of hdr_tonemap.
// Must match enum ht_slot in c_ref/twins/hdr_tonemap.h.
//------------------------------------------------------------------------------
#ifndef TS_HDR_TONEMAP_SLOTS_GLSL
#define TS_HDR_TONEMAP_SLOTS_GLSL
#define HT_SLOT_POS 0     // xy: the fragment position (gl_FragCoord.xy)
#define HT_SLOT_FRAME 1   // rgb: the linear HDR frame's texel under the pixel
#define HT_SLOT_SIZE 2    // the frame: xy size in pixels, zw 1 / size
#define HT_SLOT_PARAMS 3  // x tone-map scale, y bloom amount, z bloom exponent
#define HT_SLOTS 4
#define HT_PIXEL_SLOTS 2
#endif

//------------------------------------------------------------------------------
// hdr_tonemap_slots.glsl: the input record of hdr_tonemap (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum ht_slot (c_ref/twins/hdr_tonemap.h), the slot names and
// the uniforms bound in deferred frames (glue/families/hdr_tonemap.cpp). Row format:
// shaders/ts_slot_table.glsl. Slots below HT_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define HT_PIXEL_SLOTS 2
#define HT_SLOTS 4
// xy: the fragment position (gl_FragCoord.xy)
TS_SLOT(HT_SLOT_POS, 0, 1, position, one, gl_FragCoord)
// rgb: the linear HDR frame's texel under the pixel
TS_SLOT(HT_SLOT_FRAME, 1, 1, frame, one, u_frame)
// the frame: xy size in pixels, zw 1 / size
TS_SLOT(HT_SLOT_SIZE, 2, 1, frame_size, one, u_frame_size)
// x tone-map scale, y bloom amount, z bloom exponent
TS_SLOT(HT_SLOT_PARAMS, 3, 1, params, one, u_params)

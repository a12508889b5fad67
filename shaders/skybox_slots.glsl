//------------------------------------------------------------------------------
// skybox_slots.glsl: the input record of skybox (one vec4 per slot), the one source of its layout:
// the shader's slot constants, enum sb_slot (c_ref/twins/skybox.h), the slot names and the
// uniforms bound in scene frames (glue/families/skybox.cpp, glue/scene/skybox_pass.cpp). Row
// format: shaders/ts_slot_table.glsl. Slots below SB_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define SB_PIXEL_SLOTS 1
#define SB_SLOTS 6
// xy: the fragment position (gl_FragCoord.xy)
TS_SLOT(SB_SLOT_POS, 0, 1, position, one, gl_FragCoord)
// the frame: xy size in pixels, zw 1 / size
TS_SLOT(SB_SLOT_SIZE, 1, 1, frame_size, one, u_frame_size)
// xyz: the view direction through the frame's centre (ndc 0, 0), world space, any length
TS_SLOT(SB_SLOT_FORWARD, 2, 1, forward, one, u_sky_forward)
// xyz: what one unit of ndc x adds to the direction
TS_SLOT(SB_SLOT_RIGHT, 3, 1, right, one, u_sky_right)
// xyz: what one unit of ndc y adds to the direction
TS_SLOT(SB_SLOT_UP, 4, 1, up, one, u_sky_up)
// rgb: the sky's radiance scale (extras.tiershade.sky.scale; Source's $color), w: the tone-map scale
TS_SLOT(SB_SLOT_COLOR, 5, 1, color, one, u_sky_color)

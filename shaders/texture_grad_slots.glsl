//------------------------------------------------------------------------------
// texture_grad_slots.glsl: the input record of texture_grad (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum tg_slot (c_ref/twins/texture_grad.h), the slot names and
// the uniforms bound in deferred frames (glue/families/texture_grad.cpp). Row format:
// shaders/ts_slot_table.glsl. Both slots are per pixel.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define TG_PIXEL_SLOTS 2
#define TG_SLOTS 2
// xy: the texture coordinate (production: gl_FragCoord.xy * u_uv_scale.xy)
TS_SLOT(TG_SLOT_UV, 0, 1, uv, one, gl_FragCoord)
// (dPdx.s, dPdx.t, dPdy.s, dPdy.t): the explicit derivatives (production: u_uv_scale.x, 0, 0, u_uv_scale.y)
TS_SLOT(TG_SLOT_GRAD, 1, 1, grad, one, u_uv_scale)

//------------------------------------------------------------------------------
// world_lighting_slots.glsl: the input record of world_lighting (one vec4 per slot), the one source of its
// layout: the shader's slot constants, enum wl_slot (c_ref/twins/world_lighting.h), the slot names and
// the uniforms bound in deferred frames (glue/families/world_lighting.cpp). Row format:
// shaders/ts_slot_table.glsl. Slots below WL_PIXEL_SLOTS are per pixel; the others uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define WL_PIXEL_SLOTS 6
#define WL_SLOTS 11
// xy base-texture uv, zw lightmap uv (flat lightmap of the face)
TS_SLOT(WL_SLOT_UV, 0, 1, uv, one, v_uv)
// xy offset to the next lightmap of the face, z fog depth
TS_SLOT(WL_SLOT_LM_OFFSET, 1, 1, lm_offset, one, v_lm_offset)
// world-space tangent frame, as interpolated
TS_SLOT(WL_SLOT_NORMAL, 2, 1, normal, one, v_normal)
TS_SLOT(WL_SLOT_TANGENT, 3, 1, tangent, one, v_tangent)
TS_SLOT(WL_SLOT_BINORMAL, 4, 1, binormal, one, v_binormal)
// world-space vector from the surface point to the eye
TS_SLOT(WL_SLOT_EYE, 5, 1, eye, one, v_eye)
// rgb modulation x lightmap scale (c12), w tone-map scale
TS_SLOT(WL_SLOT_TINT_SCALE, 6, 1, tint_scale, one, u_tint_scale)
// rgb envmap tint, w envmap scale (ENV_MAP_SCALE)
TS_SLOT(WL_SLOT_ENV_TINT, 7, 1, env_tint, one, u_envmap_tint)
// x contrast, y saturation, z 1 - R0, w R0
TS_SLOT(WL_SLOT_ENV_PARAMS, 8, 1, env_params, one, u_envmap_params)
// rgb fog colour, w max density
TS_SLOT(WL_SLOT_FOG_COLOR, 9, 1, fog_color, one, u_fog_color)
// x 1 / range, y start / range
TS_SLOT(WL_SLOT_FOG_PARAMS, 10, 1, fog_params, one, u_fog_params)

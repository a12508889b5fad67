//------------------------------------------------------------------------------
// model_lighting_slots.glsl: the input record of model_lighting (one vec4 per slot), the one
// source of its layout: the shader's slot constants, enum ml_slot (c_ref/twins/model_lighting.h),
// the slot names and the uniforms bound in deferred frames (glue/families/model_lighting.cpp).
// Row format: shaders/ts_slot_table.glsl. Slots below ML_PIXEL_SLOTS are per pixel
// (varyings, the G-buffer of TS_DEFERRED frames); the others are uniforms.
//------------------------------------------------------------------------------
#include "ts_slot_table.glsl"
#define ML_MAX_LIGHTS 4
#define ML_PIXEL_SLOTS 6
#define ML_SLOTS 42
TS_SLOT(ML_SLOT_NORMAL, 0, 1, normal, one, v_normal)
TS_SLOT(ML_SLOT_POSITION, 1, 1, position, one, v_position)
TS_SLOT(ML_SLOT_UV, 2, 1, uv, one, v_uv)
// ps20: attenuation of lights 0..3, interpolated from the vertex shader
TS_SLOT(ML_SLOT_VERTEX_ATTEN, 3, 1, vertex_atten, one, v_light_atten)
// Phong: world tangent and bitangent (normal-map x and y axes)
TS_SLOT(ML_SLOT_TANGENT, 4, 1, tangent, one, v_tangent)
TS_SLOT(ML_SLOT_BITANGENT, 5, 1, bitangent, one, v_bitangent)
// 6 slots: +X -X +Y -Y +Z -Z
TS_SLOT(ML_SLOT_AMBIENT, 6, 6, ambient, cube_faces, u_ambient_cube)
// x tone-map scale, y light count (sm3)
TS_SLOT(ML_SLOT_PARAMS, 12, 1, params, one, u_params)
TS_SLOT(ML_SLOT_ALBEDO, 13, 1, albedo, one, u_albedo_color)
// 5 slots per light: color, dir, pos, spot, atten (TsLight, common_lights.glsl)
TS_SLOT(ML_SLOT_LIGHT0, 14, 20, light, light_parts, u_lights)
// xyz eye position (Phong, rim, envmap)
TS_SLOT(ML_SLOT_EYE, 34, 1, eye, one, u_eye)
// x constant exponent, y exponent factor (k = 1 + y r), z boost, w mask from base alpha
TS_SLOT(ML_SLOT_PHONG, 35, 1, phong, one, u_phong)
// Fresnel ranges as uploaded: ((mid-min)*2, mid, (max-mid)*2), w invert the mask
TS_SLOT(ML_SLOT_FRESNEL, 36, 1, fresnel_ranges, one, u_fresnel_ranges)
// rgb tint, w > 0.5: tint = lerp(1, albedo, exponent-map g)
TS_SLOT(ML_SLOT_PHONG_TINT, 37, 1, phong_tint, one, u_phong_tint)
// x rim exponent, y rim boost, z rim-mask amount ($rimmask)
TS_SLOT(ML_SLOT_RIM, 38, 1, rim, one, u_rim)
// x envmap scale, y envmap Fresnel amount, z > 0.5: mask = spec mask (else base alpha)
TS_SLOT(ML_SLOT_ENVMAP, 39, 1, envmap, one, u_envmap_params)
// rgb envmap tint
TS_SLOT(ML_SLOT_ENVMAP_TINT, 40, 1, envmap_tint, one, u_envmap_tint)
// rgb tint, w amount (0: off); mask = base alpha
TS_SLOT(ML_SLOT_SELF_ILLUM, 41, 1, self_illum, one, u_self_illum)

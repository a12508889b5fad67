//------------------------------------------------------------------------------
// scene_gbuffer.fs: one slot of the per-pixel input record of a scene draw, taken from
// the varyings of the family's production vertex shader exactly as its production
// fragment shader receives them (model_lighting.fs / world_lighting.fs build the same
// vec4s with TS_PIXEL_INPUT), or the draw's index. The C twin shades these records and
// must give the GL forward frame bit for bit (tiershade render --check, docs/scenes.md).
// GBUFFER_FAMILY 0: model_lighting (model_lighting_slots.glsl), 1: world_lighting
// (world_lighting_slots.glsl). GBUFFER_SLOT k: slot k; -1: vec4(u_draw_index, 0, 0, 1).
//------------------------------------------------------------------------------
uniform float u_draw_index;
// The assembler expands all includes; the #if keeps one family's declarations. gbuffer_slot(k):
// pixel slot k as the family's fragment shader reads it (its TS_PIXEL_INPUT values); a slot the
// variant does not have (no Phong, not ps20) is vec4(0).
#if GBUFFER_FAMILY == 0
#include "model_lighting_slots.glsl"
#include "model_lighting_varyings.glsl"
vec4 gbuffer_slot(int k) {
    if (k == ML_SLOT_NORMAL) return vec4(v_normal, 0.0);
    if (k == ML_SLOT_POSITION) return vec4(v_position, 1.0);
    if (k == ML_SLOT_UV) return vec4(v_uv, 0.0, 0.0);
#ifdef TS_TIER_PS20
    if (k == ML_SLOT_VERTEX_ATTEN) return v_light_atten;
#endif
#if PHONG
    if (k == ML_SLOT_TANGENT) return vec4(v_tangent, 0.0);
    if (k == ML_SLOT_BITANGENT) return vec4(v_bitangent, 0.0);
#endif
    return vec4(0.0);
}
#else
#include "world_lighting_slots.glsl"
#include "world_lighting_varyings.glsl"
vec4 gbuffer_slot(int k) {
    if (k == WL_SLOT_UV) return v_uv;
    if (k == WL_SLOT_LM_OFFSET) return v_lm_offset;
    if (k == WL_SLOT_NORMAL) return v_normal;
    if (k == WL_SLOT_TANGENT) return v_tangent;
    if (k == WL_SLOT_BINORMAL) return v_binormal;
    if (k == WL_SLOT_EYE) return v_eye;
    return vec4(0.0);
}
#endif

TS_DECLARE_FRAG_COLOR

void main() {
#if GBUFFER_SLOT < 0
    TS_FRAG_COLOR = vec4(u_draw_index, 0.0, 0.0, 1.0);
#else
    TS_FRAG_COLOR = gbuffer_slot(GBUFFER_SLOT);
#endif
}

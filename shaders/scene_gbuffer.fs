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
// The assembler expands both includes; the #if keeps one family's declarations.
#if GBUFFER_FAMILY == 0
#include "model_lighting_varyings.glsl"
#else
#include "world_lighting_varyings.glsl"
#endif

TS_DECLARE_FRAG_COLOR

void main() {
    vec4 r = vec4(0.0);
#if GBUFFER_SLOT < 0
    r = vec4(u_draw_index, 0.0, 0.0, 1.0);
#elif GBUFFER_FAMILY == 0
#if GBUFFER_SLOT == 0
    r = vec4(v_normal, 0.0);
#elif GBUFFER_SLOT == 1
    r = vec4(v_position, 1.0);
#elif GBUFFER_SLOT == 2
    r = vec4(v_uv, 0.0, 0.0);
#elif GBUFFER_SLOT == 3
#ifdef TS_TIER_PS20
    r = v_light_atten;
#endif
#elif GBUFFER_SLOT == 4
#if PHONG
    r = vec4(v_tangent, 0.0);
#endif
#elif GBUFFER_SLOT == 5
#if PHONG
    r = vec4(v_bitangent, 0.0);
#endif
#endif
#else
#if GBUFFER_SLOT == 0
    r = v_uv;
#elif GBUFFER_SLOT == 1
    r = v_lm_offset;
#elif GBUFFER_SLOT == 2
    r = v_normal;
#elif GBUFFER_SLOT == 3
    r = v_tangent;
#elif GBUFFER_SLOT == 4
    r = v_binormal;
#elif GBUFFER_SLOT == 5
    r = v_eye;
#endif
#endif
    TS_FRAG_COLOR = r;
}

//------------------------------------------------------------------------------
// scene_gbuffer.fs: one slot of the per-pixel input record of a scene draw, taken from
// the varyings of the family's production vertex shader exactly as its production
// fragment shader receives them (model_lighting.fs / world_lighting.fs build the same
// vec4s with TS_PIXEL_INPUT), or the draw's index. The C twin shades these records and
// must give the GL forward frame bit for bit (tiershade render --check, docs/scenes.md).
// GBUFFER_FAMILY 0: model_lighting (model_lighting_slots.glsl), 1: world_lighting
// (world_lighting_slots.glsl). GBUFFER_SLOT k: slot k; -1: vec4(u_draw_index, 0, 0, 1);
// 6: the uv's derivatives as the sampler takes them for a mipmapped texture (below).
//------------------------------------------------------------------------------
// dFdx / dFdy on GLSL ES 1.00 (core in ES 3.00 and GLSL 3.30, where the line only warns).
#extension GL_OES_standard_derivatives : enable
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

// The 2x2 quad's derivatives of the uv that llvmpipe's sampler computes for every pixel of the
// quad (lp_bld_quad.c lp_build_packed_ddx_ddy_twocoord): (ds/dx, ds/dy, dt/dx, dt/dy) with d/dx =
// top-right minus top-left and d/dy = bottom-left minus top-left ("top": the even row). GLSL's
// dFdx is per row and dFdy per column (lp_build_ddx / lp_build_ddy), so the top row's dFdx is
// carried down its column by dFdy(top ? -dx : 0) = 0 - (-dx_top), and the left column's dFdy
// across its row by dFdx(left ? -dy : 0): both exact. The C fallback computes the same from the
// triangle's planes (glue/scene/cpu_renderer.cpp uv_grad_run).
vec4 gbuffer_uv_grad() {
#if GBUFFER_FAMILY == 0
    vec2 uv = v_uv;
#else
    vec2 uv = v_uv.xy;
#endif
    bool right = mod(floor(gl_FragCoord.x), 2.0) == 1.0;
    bool bottom = mod(floor(gl_FragCoord.y), 2.0) == 1.0;
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    vec2 dx_top = dFdy(bottom ? vec2(0.0) : -dx);
    vec2 dy_left = dFdx(right ? vec2(0.0) : -dy);
    return vec4(dx_top.x, dy_left.x, dx_top.y, dy_left.y);
}

void main() {
#if GBUFFER_SLOT < 0
    TS_FRAG_COLOR = vec4(u_draw_index, 0.0, 0.0, 1.0);
#elif GBUFFER_SLOT == 6
    TS_FRAG_COLOR = gbuffer_uv_grad();
#else
    TS_FRAG_COLOR = gbuffer_slot(GBUFFER_SLOT);
#endif
}

//------------------------------------------------------------------------------
// color_correction.fs: Source's colour-correction post-process (talk: "Color
// Correction"; fact sheet section 9): up to four LUTs blended with weights plus
// the default weight of the uncorrected colour,
//   out = c * w_default + sum_{i < NUM_LOOKUPS} w_i * LUT_i(c * (N-1)/N + 0.5/N).
// It runs after tone mapping on display-encoded [0, 1] frame values (fact sheet
// section 8, Engine_Post), so the input is saturated and so is the output (what an
// 8-bit render target does).
// Tiers: ps20 (ES2/WebGL1: 2D atlas only), ps2b (3D texture or atlas). Either tier:
// hardware or shader trilinear filtering (common_color_correction.glsl).
// Variants: color_correction.variants. C twin: c_ref/twins/color_correction.c.
// Inputs (slots): c_ref/twins/color_correction.h and color_correction_slots.glsl.
//------------------------------------------------------------------------------
// ESSL 1.00 has 3D textures only through OES_texture_3D (docs/color_correction.md). The
// assembler puts this line right after #version; `enable` is a warning where it is unknown.
#extension GL_OES_texture_3D : enable
#if !LUT_ATLAS
TS_SAMPLER3D_PRECISION  // ts_portability.glsl: highp on ES (llvmpipe returns fp16 texels for lowp)
#endif
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_color_correction.glsl"
#include "color_correction_slots.glsl"

TS_VARYING vec2 v_uv;
uniform sampler2D u_frame;  // the tone-mapped, display-encoded frame
uniform vec4 u_cc_weights;  // weights of LUTs 0..3
uniform vec4 u_cc_params;   // x: default weight
uniform vec4 u_cc_lut;      // ((N-1)/N, 0.5/N, N-1, 1/N) for LUT edge N
#if LUT_ATLAS
uniform sampler2D u_lut_atlas0;
uniform sampler2D u_lut_atlas1;
uniform sampler2D u_lut_atlas2;
uniform sampler2D u_lut_atlas3;
#define CC_LUT0 u_lut_atlas0
#define CC_LUT1 u_lut_atlas1
#define CC_LUT2 u_lut_atlas2
#define CC_LUT3 u_lut_atlas3
#else
uniform sampler3D u_lut0;
uniform sampler3D u_lut1;
uniform sampler3D u_lut2;
uniform sampler3D u_lut3;
#define CC_LUT0 u_lut0
#define CC_LUT1 u_lut1
#define CC_LUT2 u_lut2
#define CC_LUT3 u_lut3
#endif

TS_DECLARE_FRAG_COLOR

void main() {
    vec4 color = TS_PIXEL_INPUT(CC_SLOT_COLOR, TS_TEX2D(u_frame, v_uv));
    vec4 weights = TS_UNIFORM_INPUT(CC_SLOT_WEIGHTS, u_cc_weights);
    vec4 params = TS_UNIFORM_INPUT(CC_SLOT_PARAMS, u_cc_params);
    vec4 lut = TS_UNIFORM_INPUT(CC_SLOT_LUT, u_cc_lut);
    vec3 c = saturate(color.rgb);
    vec3 result = c * params.x;
#if NUM_LOOKUPS > 0
#if SHADER_TRILINEAR
    vec3 i0;
    vec3 i1;
    vec3 f;
    ts_cc_cell(c, lut, i0, i1, f);
    vec3 c0 = ts_cc_centre(i0, lut);
    vec3 c1 = ts_cc_centre(i1, lut);
#if LUT_ATLAS
    vec4 u = vec4(c0.x + i0.z, c1.x + i0.z, c0.x + i1.z, c1.x + i1.z) * lut.w;
    vec2 v = vec2(c0.y, c1.y);
#define CC_LOOKUP(s) ts_cc_atlas_shader(s, u, v, f)
#else
#define CC_LOOKUP(s) ts_cc_volume_shader(s, c0, c1, f)
#endif
#else
    vec3 uvw = ts_cc_uvw(c, lut);
#if LUT_ATLAS
    // The blue slices around c.b and the fraction between them.
    float pz = c.b * lut.z;
    float z0 = floor(pz);
    float fz = pz - z0;
    float z1 = min(z0 + 1.0, lut.z);
    vec2 uv0 = vec2((uvw.x + z0) * lut.w, uvw.y);
    vec2 uv1 = vec2((uvw.x + z1) * lut.w, uvw.y);
#define CC_LOOKUP(s) ts_cc_atlas_hw(s, uv0, uv1, fz)
#else
#define CC_LOOKUP(s) ts_cc_volume_hw(s, uvw)
#endif
#endif
    result += weights.x * CC_LOOKUP(CC_LUT0);
#endif
#if NUM_LOOKUPS > 1
    result += weights.y * CC_LOOKUP(CC_LUT1);
#endif
#if NUM_LOOKUPS > 2
    result += weights.z * CC_LOOKUP(CC_LUT2);
#endif
#if NUM_LOOKUPS > 3
    result += weights.w * CC_LOOKUP(CC_LUT3);
#endif
    TS_FRAG_COLOR = vec4(saturate(result), saturate(color.a));
}

//------------------------------------------------------------------------------
// texture_grad.fs: one lookup of a mip-mapped RGBA32F texture with explicit derivatives
// (textureGrad; ESSL 1.00: texture2DGradEXT). Not a Source shader: the conformance probe of the
// level of detail (docs/conformance.md, "Explicit derivatives"), so that the C sampler's LOD
// (c_ref/math/ts_sampler_grad.c) is checked per pixel against llvmpipe, and every other
// implementation against the GLES 3.0 LOD rules (ts_texture2DGradiv).
// Output: the filtered texel, as it is (texels in [0, 64]).
// Variants: texture_grad.variants. C twin: c_ref/twins/texture_grad.c.
//------------------------------------------------------------------------------
// ESSL 1.00 has gradient lookups only through EXT_shader_texture_lod; the assembler puts this
// line right after #version; `enable` is a warning where it is unknown.
#extension GL_EXT_shader_texture_lod : enable
#include "common_inputs.glsl"
#include "texture_grad_slots.glsl"

uniform sampler2D u_mips_linear;   // 32 x 16, LINEAR_MIPMAP_LINEAR, REPEAT
uniform sampler2D u_mips_nearest;  // 16 x 32, LINEAR_MIPMAP_NEAREST, CLAMP_TO_EDGE
uniform vec4 u_uv_scale;           // production: xy uv per pixel

TS_DECLARE_FRAG_COLOR

void main() {
    vec4 uv = TS_PIXEL_INPUT(TG_SLOT_UV, vec4(gl_FragCoord.xy * u_uv_scale.xy, 0.0, 0.0));
    vec4 d = TS_PIXEL_INPUT(TG_SLOT_GRAD, vec4(u_uv_scale.x, 0.0, 0.0, u_uv_scale.y));
#if MIP_NEAREST
    TS_FRAG_COLOR = TS_TEX2D_GRAD(u_mips_nearest, uv.xy, d.xy, d.zw);
#else
    TS_FRAG_COLOR = TS_TEX2D_GRAD(u_mips_linear, uv.xy, d.xy, d.zw);
#endif
}

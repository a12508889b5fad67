//------------------------------------------------------------------------------
// ts_portability.glsl: the language differences between the three targets (GLSL ES 1.00,
// GLSL ES 3.00, GLSL 3.30 core), in one shim header; the model is bgfx's bgfx_shader.sh.
// The assembler (glue/shaderlib/assembler.cpp) writes #version, the entry file's #extension
// lines and the defines that select the target, the stage and the float precision:
//   TS_ESSL100 | TS_ESSL300 | TS_GLSL330, TS_VERTEX | TS_FRAGMENT, TS_FLOAT_PRECISION
// then the variant's #defines, then this file, then the entry file. Library code writes only
// the macros below, never the target's own words (texture2D/texture, varying/in/out,
// gl_FragColor, texture3D):
//   TS_ATTRIBUTE (vertex), TS_FRAG_COLOR, TS_DECLARE_FRAG_COLOR (fragment), TS_VARYING
//   (out in the vertex shader, in in the fragment shader, so that one varyings file serves
//   both: model_lighting_varyings.glsl), TS_TEX2D, TS_TEXCUBE, TS_TEX3D, TS_TEX2D_GRAD
//   (explicit derivatives; ESSL 1.00: EXT_shader_texture_lod, which the entry file enables),
//   TS_SAMPLER3D_PRECISION, TS_HAS_TEXEL_FETCH (texelFetch exists).
//------------------------------------------------------------------------------

// Floats are highp unless an accuracy study asks for mediump, so GLES results can be compared
// with C float32 (llvmpipe computes mediump in fp16: ../shared/docs/platform_notes.md section 3).
precision TS_FLOAT_PRECISION float;
precision highp int;
#if defined(TS_ESSL100) || defined(TS_ESSL300)
// Samplers default to lowp in ES fragment shaders, and llvmpipe really returns fp16 texels
// for them: every compared value must be highp.
precision highp sampler2D;
precision highp samplerCube;
// ES has no default precision for sampler3D at all: a shader that declares one writes
// TS_SAMPLER3D_PRECISION first (ESSL 1.00 has sampler3D only with GL_OES_texture_3D enabled).
#define TS_SAMPLER3D_PRECISION precision highp sampler3D;
#else
#define TS_SAMPLER3D_PRECISION
#endif

#ifdef TS_ESSL100
#ifdef TS_VERTEX
#define TS_ATTRIBUTE attribute
#define TS_VARYING varying
#else
#define TS_VARYING varying
#define TS_FRAG_COLOR gl_FragColor
#define TS_DECLARE_FRAG_COLOR
#endif
#define TS_TEX2D(s, uv) texture2D(s, uv)
#define TS_TEXCUBE(s, d) textureCube(s, d)
#define TS_TEX3D(s, p) texture3D(s, p)  // GL_OES_texture_3D
#define TS_TEX2D_GRAD(s, uv, dx, dy) texture2DGradEXT(s, uv, dx, dy)  // GL_EXT_shader_texture_lod
#else
#define TS_HAS_TEXEL_FETCH 1
#ifdef TS_VERTEX
#define TS_ATTRIBUTE in
#define TS_VARYING out
#else
#define TS_VARYING in
#define TS_FRAG_COLOR ts_FragColor
#define TS_DECLARE_FRAG_COLOR out vec4 ts_FragColor;
#endif
#define TS_TEX2D(s, uv) texture(s, uv)
#define TS_TEXCUBE(s, d) texture(s, d)
#define TS_TEX3D(s, p) texture(s, p)
#define TS_TEX2D_GRAD(s, uv, dx, dy) textureGrad(s, uv, dx, dy)
#endif

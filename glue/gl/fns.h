// tiershade gl: the table of GL entry points, resolved per backend.
// Every GL call goes through a GlFns table filled by OSMesaGetProcAddress or
// eglGetProcAddress, so the binary does not depend on link order between
// libOSMesa and libEGL (see ../shared/docs/platform_notes.md, addendum).
#pragma once
#include <GL/glcorearb.h>

// X(name, PFN type suffix). Functions marked optional may be missing (ES2).
#define TS_GL_FUNCTIONS(X)                                                   \
  X(GetString, PFNGLGETSTRINGPROC)                                           \
  X(GetError, PFNGLGETERRORPROC)                                             \
  X(GetIntegerv, PFNGLGETINTEGERVPROC)                                       \
  X(Finish, PFNGLFINISHPROC)                                                 \
  X(Flush, PFNGLFLUSHPROC)                                                   \
  X(CreateShader, PFNGLCREATESHADERPROC)                                     \
  X(ShaderSource, PFNGLSHADERSOURCEPROC)                                     \
  X(CompileShader, PFNGLCOMPILESHADERPROC)                                   \
  X(GetShaderiv, PFNGLGETSHADERIVPROC)                                       \
  X(GetShaderInfoLog, PFNGLGETSHADERINFOLOGPROC)                             \
  X(DeleteShader, PFNGLDELETESHADERPROC)                                     \
  X(CreateProgram, PFNGLCREATEPROGRAMPROC)                                   \
  X(AttachShader, PFNGLATTACHSHADERPROC)                                     \
  X(BindAttribLocation, PFNGLBINDATTRIBLOCATIONPROC)                         \
  X(LinkProgram, PFNGLLINKPROGRAMPROC)                                       \
  X(GetProgramiv, PFNGLGETPROGRAMIVPROC)                                     \
  X(GetProgramInfoLog, PFNGLGETPROGRAMINFOLOGPROC)                           \
  X(DeleteProgram, PFNGLDELETEPROGRAMPROC)                                   \
  X(UseProgram, PFNGLUSEPROGRAMPROC)                                         \
  X(GetUniformLocation, PFNGLGETUNIFORMLOCATIONPROC)                         \
  X(GetActiveUniform, PFNGLGETACTIVEUNIFORMPROC)                             \
  X(GetActiveAttrib, PFNGLGETACTIVEATTRIBPROC)                               \
  X(GetUniformfv, PFNGLGETUNIFORMFVPROC)                                     \
  X(GetUniformiv, PFNGLGETUNIFORMIVPROC)                                     \
  X(Uniform1i, PFNGLUNIFORM1IPROC)                                           \
  X(Uniform1f, PFNGLUNIFORM1FPROC)                                           \
  X(Uniform2f, PFNGLUNIFORM2FPROC)                                           \
  X(Uniform1fv, PFNGLUNIFORM1FVPROC)                                         \
  X(Uniform3fv, PFNGLUNIFORM3FVPROC)                                         \
  X(Uniform4fv, PFNGLUNIFORM4FVPROC)                                         \
  X(GenTextures, PFNGLGENTEXTURESPROC)                                       \
  X(BindTexture, PFNGLBINDTEXTUREPROC)                                       \
  X(ActiveTexture, PFNGLACTIVETEXTUREPROC)                                   \
  X(TexImage2D, PFNGLTEXIMAGE2DPROC)                                         \
  X(TexParameteri, PFNGLTEXPARAMETERIPROC)                                   \
  X(DeleteTextures, PFNGLDELETETEXTURESPROC)                                 \
  X(PixelStorei, PFNGLPIXELSTOREIPROC)                                       \
  X(GenFramebuffers, PFNGLGENFRAMEBUFFERSPROC)                               \
  X(BindFramebuffer, PFNGLBINDFRAMEBUFFERPROC)                               \
  X(FramebufferTexture2D, PFNGLFRAMEBUFFERTEXTURE2DPROC)                     \
  X(CheckFramebufferStatus, PFNGLCHECKFRAMEBUFFERSTATUSPROC)                 \
  X(DeleteFramebuffers, PFNGLDELETEFRAMEBUFFERSPROC)                         \
  X(GenBuffers, PFNGLGENBUFFERSPROC)                                         \
  X(BindBuffer, PFNGLBINDBUFFERPROC)                                         \
  X(BufferData, PFNGLBUFFERDATAPROC)                                         \
  X(DeleteBuffers, PFNGLDELETEBUFFERSPROC)                                   \
  X(VertexAttribPointer, PFNGLVERTEXATTRIBPOINTERPROC)                       \
  X(EnableVertexAttribArray, PFNGLENABLEVERTEXATTRIBARRAYPROC)               \
  X(GenVertexArrays, PFNGLGENVERTEXARRAYSPROC)                               \
  X(BindVertexArray, PFNGLBINDVERTEXARRAYPROC)                               \
  X(DeleteVertexArrays, PFNGLDELETEVERTEXARRAYSPROC)                         \
  X(Viewport, PFNGLVIEWPORTPROC)                                             \
  X(Disable, PFNGLDISABLEPROC)                                               \
  X(ClearColor, PFNGLCLEARCOLORPROC)                                         \
  X(Clear, PFNGLCLEARPROC)                                                   \
  X(DrawArrays, PFNGLDRAWARRAYSPROC)                                         \
  X(ReadPixels, PFNGLREADPIXELSPROC)                                         \
  X(Enable, PFNGLENABLEPROC)                                                 \
  X(BlendFunc, PFNGLBLENDFUNCPROC)                                           \
  X(BlendEquation, PFNGLBLENDEQUATIONPROC)                                   \
  X(Scissor, PFNGLSCISSORPROC)                                               \
  X(ColorMask, PFNGLCOLORMASKPROC)                                           \
  X(DepthMask, PFNGLDEPTHMASKPROC)                                           \
  X(DepthFunc, PFNGLDEPTHFUNCPROC)                                           \
  X(StencilFunc, PFNGLSTENCILFUNCPROC)                                       \
  X(StencilOp, PFNGLSTENCILOPPROC)                                           \
  X(TexImage3D, PFNGLTEXIMAGE3DPROC)                                         \
  X(TexSubImage2D, PFNGLTEXSUBIMAGE2DPROC)                                   \
  X(GenerateMipmap, PFNGLGENERATEMIPMAPPROC)                                 \
  X(GenQueries, PFNGLGENQUERIESPROC)                                         \
  X(DeleteQueries, PFNGLDELETEQUERIESPROC)                                   \
  X(BeginQuery, PFNGLBEGINQUERYPROC)                                         \
  X(EndQuery, PFNGLENDQUERYPROC)                                             \
  X(GetQueryObjectuiv, PFNGLGETQUERYOBJECTUIVPROC)                           \
  X(Uniform2fv, PFNGLUNIFORM2FVPROC)                                         \
  X(Uniform3f, PFNGLUNIFORM3FPROC)                                           \
  X(Uniform4f, PFNGLUNIFORM4FPROC)                                           \
  X(Uniform1iv, PFNGLUNIFORM1IVPROC)                                         \
  X(UniformMatrix4fv, PFNGLUNIFORMMATRIX4FVPROC)                             \
  X(GenRenderbuffers, PFNGLGENRENDERBUFFERSPROC)                             \
  X(DeleteRenderbuffers, PFNGLDELETERENDERBUFFERSPROC)                       \
  X(BindRenderbuffer, PFNGLBINDRENDERBUFFERPROC)                             \
  X(RenderbufferStorage, PFNGLRENDERBUFFERSTORAGEPROC)                       \
  X(RenderbufferStorageMultisample, PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC) \
  X(FramebufferRenderbuffer, PFNGLFRAMEBUFFERRENDERBUFFERPROC)               \
  X(BlitFramebuffer, PFNGLBLITFRAMEBUFFERPROC)                               \
  X(GetRenderbufferParameteriv, PFNGLGETRENDERBUFFERPARAMETERIVPROC)         \
  X(SampleCoverage, PFNGLSAMPLECOVERAGEPROC)                                 \
  X(DrawElements, PFNGLDRAWELEMENTSPROC)                                     \
  X(DrawBuffers, PFNGLDRAWBUFFERSPROC)                                       \
  X(ReadBuffer, PFNGLREADBUFFERPROC)                                         \
  X(GetAttribLocation, PFNGLGETATTRIBLOCATIONPROC)

struct GlFns {
#define TS_GL_DECLARE(name, type) type name = nullptr;
  TS_GL_FUNCTIONS(TS_GL_DECLARE)
#undef TS_GL_DECLARE
};

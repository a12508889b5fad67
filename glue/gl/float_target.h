// tiershade gl: programs, RGBA32F textures, and full-screen draws into an
// RGBA32F framebuffer with float readback, on any GlContext.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "shaderlib/assembler.h"
#include "gl/context.h"
#include "base/image.h"
#include "base/noncopyable.h"

enum class TexKind { Tex2D, Cube, Tex3D };

struct TextureDesc {
  std::string sampler;  // uniform name
  TexKind kind = TexKind::Tex2D;
  int w = 0, h = 0, d = 1;  // Tex3D: depth d; Cube: 6 faces of w x w (h == w)
  // RGBA32F, row 0 first (GL order). Tex3D: slice after slice. Cube: faces +X -X +Y -Y +Z -Z
  // one after another, each w*w texels.
  std::vector<float> rgba;
  bool linear = false;  // GL_LINEAR (else GL_NEAREST)
  bool repeat = false;  // GL_REPEAT (else GL_CLAMP_TO_EDGE; cube maps always clamp, seamless off)
  // 2D only: a mip chain (glue/gl/mipmaps.h): levels 1 .. mips.size() of max(1, w >> k) x
  // max(1, h >> k), and the minification filter's mipmap part (TS_MIP_NEAREST / TS_MIP_LINEAR of
  // c_ref/math/ts_sampler.h; 0: none). The image filter (linear) is both min and mag filter's.
  std::vector<std::vector<float>> mips;
  int mip_filter = 0;
};

// An uninitialised w x h 2D texture (RGBA, NEAREST) for a framebuffer's colour attachment,
// left bound to GL_TEXTURE_2D.
GLuint new_target_texture(const GlFns &g, GLenum internal_format, GLenum type, int w, int h);

class GlRenderer : NonCopyable {
 public:
  explicit GlRenderer(GlContext &ctx);
  ~GlRenderer();

  const GlFns &gl() const { return ctx_.gl(); }
  // Compiles and links; on failure *err holds the log mapped to shaders/<file>:<line>.
  GLuint build_program(const Assembled &vs, const Assembled &fs, std::string *err);
  void delete_program(GLuint p);
  GLuint upload_texture(const TextureDesc &t);
  void delete_texture(GLuint t);
  // Binds textures to units 0..n-1 and their samplers, draws one full-screen
  // triangle into a w x h RGBA32F target, and reads it back.
  // *draw_ms (optional) receives the time of the draw alone, glFinish included.
  bool draw(GLuint program, const std::vector<std::pair<std::string, GLuint>> &textures, int w, int h, ImageF *out,
            std::string *err, double *draw_ms = nullptr);
  // Binds the full-screen triangle (attribute 0 = a_corner: (-1,-1), (3,-1), (-1,3)), the one
  // every full-screen pass draws (hdr/gl_passes.h draws it too).
  void bind_fullscreen_triangle() const;

 private:
  bool ensure_target(int w, int h, std::string *err);
  GLenum kind_of(GLuint texture) const;  // the GL target a texture was created with
  std::map<GLuint, GLenum> kinds_;
  GlContext &ctx_;
  GLuint vao_ = 0, vbo_ = 0, fbo_ = 0, color_ = 0;
  int tw_ = 0, th_ = 0;
};

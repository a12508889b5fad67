// tiershade gl: program building and full-screen RGBA32F draws (see gl_render.h).
#include "gl/float_target.h"

#include <algorithm>

#include "gl/errors.h"

#include <chrono>

GlRenderer::GlRenderer(GlContext &ctx) : ctx_(ctx) {
  const GlFns &g = gl();
  const float corners[6] = {-1.f, -1.f, 3.f, -1.f, -1.f, 3.f};
  g.GenVertexArrays(1, &vao_);
  g.BindVertexArray(vao_);
  g.GenBuffers(1, &vbo_);
  g.BindBuffer(GL_ARRAY_BUFFER, vbo_);
  g.BufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  g.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  g.EnableVertexAttribArray(0);
}

void GlRenderer::bind_fullscreen_triangle() const { gl().BindVertexArray(vao_); }

GlRenderer::~GlRenderer() {
  const GlFns &g = gl();
  if (color_) g.DeleteTextures(1, &color_);
  if (fbo_) g.DeleteFramebuffers(1, &fbo_);
  if (vbo_) g.DeleteBuffers(1, &vbo_);
  if (vao_) g.DeleteVertexArrays(1, &vao_);
}

static bool compile(const GlFns &g, GLenum type, const Assembled &src, GLuint *out, std::string *err) {
  GLuint s = g.CreateShader(type);
  const char *text = src.text.c_str();
  g.ShaderSource(s, 1, &text, nullptr);
  g.CompileShader(s);
  GLint ok = 0;
  g.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    *err = std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader failed to compile:\n" +
        map_compile_log(gl_info_log(g, s, false).c_str(), src);
    g.DeleteShader(s);
    return false;
  }
  *out = s;
  return true;
}

GLuint GlRenderer::build_program(const Assembled &vs, const Assembled &fs, std::string *err) {
  const GlFns &g = gl();
  GLuint v = 0, f = 0;
  if (!compile(g, GL_VERTEX_SHADER, vs, &v, err)) return 0;
  if (!compile(g, GL_FRAGMENT_SHADER, fs, &f, err)) {
    g.DeleteShader(v);
    return 0;
  }
  GLuint p = g.CreateProgram();
  g.AttachShader(p, v);
  g.AttachShader(p, f);
  g.BindAttribLocation(p, 0, "a_corner");
  g.LinkProgram(p);
  g.DeleteShader(v);
  g.DeleteShader(f);
  GLint ok = 0;
  g.GetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    *err = "program failed to link:\n" + gl_info_log(g, p, true);
    g.DeleteProgram(p);
    return 0;
  }
  return p;
}

void GlRenderer::delete_program(GLuint p) {
  if (p) gl().DeleteProgram(p);
}

GLenum texture_target(TexKind k) {
  return k == TexKind::Cube ? GL_TEXTURE_CUBE_MAP : k == TexKind::Tex3D ? GL_TEXTURE_3D : GL_TEXTURE_2D;
}

GLuint GlRenderer::upload_texture(const TextureDesc &t) {
  const GlFns &g = gl();
  const GLenum target = texture_target(t.kind);
  GLuint id = 0;
  g.GenTextures(1, &id);
  g.BindTexture(target, id);
  g.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (t.kind == TexKind::Tex2D) {
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, t.w, t.h, 0, GL_RGBA, GL_FLOAT, t.rgba.data());
    for (size_t k = 0; k < t.mips.size(); ++k) {  // the complete chain tiershade built (mipmaps.h)
      const int l = static_cast<int>(k) + 1;
      g.TexImage2D(GL_TEXTURE_2D, l, GL_RGBA32F, std::max(1, t.w >> l), std::max(1, t.h >> l), 0, GL_RGBA, GL_FLOAT,
                   t.mips[k].data());
    }
  } else if (t.kind == TexKind::Tex3D) {
    g.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, t.w, t.h, t.d, 0, GL_RGBA, GL_FLOAT, t.rgba.data());
  } else {
    const size_t face = static_cast<size_t>(t.w) * t.w * 4;
    for (int f = 0; f < 6; ++f)
      g.TexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA32F, t.w, t.w, 0, GL_RGBA, GL_FLOAT,
                   t.rgba.data() + f * face);
  }
  const GLint filter = t.linear ? GL_LINEAR : GL_NEAREST;
  const GLint wrap = t.repeat && t.kind != TexKind::Cube ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  GLint min_filter = filter;
  if (t.kind == TexKind::Tex2D && !t.mips.empty() && t.mip_filter == 1)
    min_filter = t.linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
  else if (t.kind == TexKind::Tex2D && !t.mips.empty() && t.mip_filter == 2)
    min_filter = t.linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
  g.TexParameteri(target, GL_TEXTURE_MIN_FILTER, min_filter);
  g.TexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  g.TexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
  g.TexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
  if (t.kind != TexKind::Tex2D) g.TexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
  // Seamless cube filtering is not reproducible per pixel (llvmpipe_bitexact.md): off on
  // desktop GL. GLES 3 has no switch (its cube maps are seamless by definition).
  if (t.kind == TexKind::Cube && ctx_.api() == Api::GL33) g.Disable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  kinds_[id] = target;
  return id;
}

void GlRenderer::delete_texture(GLuint t) {
  if (t) gl().DeleteTextures(1, &t);
  kinds_.erase(t);
}

GLenum GlRenderer::kind_of(GLuint t) const {
  auto it = kinds_.find(t);
  return it == kinds_.end() ? GL_TEXTURE_2D : it->second;
}

GLuint new_target_texture(const GlFns &g, GLenum internal_format, GLenum type, int w, int h) {
  GLuint t = 0;
  g.GenTextures(1, &t);
  g.BindTexture(GL_TEXTURE_2D, t);
  g.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), w, h, 0, GL_RGBA, type, nullptr);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

bool GlRenderer::ensure_target(int w, int h, std::string *err) {
  const GlFns &g = gl();
  if (fbo_ && tw_ == w && th_ == h) return true;
  if (color_) g.DeleteTextures(1, &color_);
  if (!fbo_) g.GenFramebuffers(1, &fbo_);
  color_ = new_target_texture(g, GL_RGBA32F, GL_FLOAT, w, h);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  if (!gl_framebuffer_complete(g, "RGBA32F framebuffer", err)) return false;
  tw_ = w;
  th_ = h;
  return true;
}

bool GlRenderer::draw(GLuint program, const std::vector<std::pair<std::string, GLuint>> &textures, int w, int h,
                      ImageF *out, std::string *err, double *draw_ms) {
  const GlFns &g = gl();
  if (!ensure_target(w, h, err)) return false;
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  g.Viewport(0, 0, w, h);
  g.Disable(GL_BLEND);
  g.Disable(GL_DEPTH_TEST);
  g.UseProgram(program);
  for (size_t i = 0; i < textures.size(); ++i) {
    g.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(i));
    g.BindTexture(kind_of(textures[i].second), textures[i].second);
    const GLint loc = g.GetUniformLocation(program, textures[i].first.c_str());
    if (loc >= 0) g.Uniform1i(loc, static_cast<GLint>(i));
  }
  g.BindVertexArray(vao_);
  g.ClearColor(0, 0, 0, 0);
  g.Clear(GL_COLOR_BUFFER_BIT);
  const auto t0 = std::chrono::steady_clock::now();
  g.DrawArrays(GL_TRIANGLES, 0, 3);
  if (draw_ms) {
    g.Finish();
    *draw_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  out->w = w;
  out->h = h;
  out->rgba.assign(static_cast<size_t>(w) * h * 4, 0.f);
  g.PixelStorei(GL_PACK_ALIGNMENT, 4);
  g.ReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, out->rgba.data());
  return gl_no_error(g, "after the draw", err);
}

// tiershade hdr: render targets, full-screen passes and readbacks of the HDR passes
// (see hdr_gl.h).
#include "hdr/gl_passes.h"

#include <EGL/egl.h>

#include <cstdio>

#include "base/enum_names.h"
#include "conform/conform.h"
#include "families/family.h"
#include "gl/errors.h"
#include "gl/osmesa_loader.h"

static const EnumName<TargetFormat> kTargetFormatNames[] = {
    {TargetFormat::RGBA8, "RGBA8"}, {TargetFormat::RGBA16F, "RGBA16F"}, {TargetFormat::RGBA32F, "RGBA32F"}};

const char *target_format_name(TargetFormat f) { return enum_name(kTargetFormatNames, f); }

int target_bytes_per_pixel(TargetFormat f) {
  return f == TargetFormat::RGBA8 ? 4 : f == TargetFormat::RGBA16F ? 8 : 16;
}

bool make_target(const GlFns &g, TargetFormat f, int w, int h, GlTarget *t, std::string *err) {
  *t = GlTarget();
  t->w = w;
  t->h = h;
  t->fmt = f;
  t->tex = f == TargetFormat::RGBA8     ? new_target_texture(g, GL_RGBA8, GL_UNSIGNED_BYTE, w, h)
           : f == TargetFormat::RGBA16F ? new_target_texture(g, GL_RGBA16F, GL_HALF_FLOAT, w, h)
                                        : new_target_texture(g, GL_RGBA32F, GL_FLOAT, w, h);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  g.GenFramebuffers(1, &t->fbo);
  g.BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->tex, 0);
  if (!gl_framebuffer_complete(
          g, std::string(target_format_name(f)) + " " + std::to_string(w) + "x" + std::to_string(h) + " framebuffer",
          err)) {
    free_target(g, t);
    return false;
  }
  return true;
}

void free_target(const GlFns &g, GlTarget *t) {
  if (t->fbo) g.DeleteFramebuffers(1, &t->fbo);
  if (t->tex) g.DeleteTextures(1, &t->tex);
  t->fbo = t->tex = 0;
}

PassRunner::PassRunner(GlRenderer &r) : r_(r) {}

PassRunner::~PassRunner() {
  for (auto &p : programs_) r_.delete_program(p.second);
}

GLuint PassRunner::program(Api api, const std::string &shader, const std::string &variant, std::string *err) {
  const std::string key = shader + "|" + variant;
  for (auto &p : programs_)
    if (p.first == key) return p.second;
  if (decls_.empty() && !load_shader_decls(&decls_, err)) return 0;
  Variant v;
  if (!find_variant(decls_, shader, variant, &v, err)) return 0;
  const GLuint p = build_production_program(r_, api, v, err);
  if (!p) {
    *err = shader + " " + variant + ": " + *err;
    return 0;
  }
  programs_.push_back({key, p});
  return p;
}

void PassRunner::set_vec4(GLuint program, const char *name, const float v[4]) {
  const GlFns &g = gl();
  g.UseProgram(program);
  const GLint loc = g.GetUniformLocation(program, name);
  if (loc >= 0) g.Uniform4fv(loc, 1, v);
}

bool PassRunner::draw(GLuint program, const GlTarget &t, const std::vector<PassTexture> &textures,
                      const ae_window *scissor, std::string *err) {
  const GlFns &g = gl();
  g.BindFramebuffer(GL_FRAMEBUFFER, t.fbo);
  g.Viewport(0, 0, t.w, t.h);
  g.Disable(GL_BLEND);
  g.Disable(GL_DEPTH_TEST);
  if (scissor) {
    g.Enable(GL_SCISSOR_TEST);
    g.Scissor(scissor->x0, scissor->y0, scissor->w, scissor->h);
  } else {
    g.Disable(GL_SCISSOR_TEST);
  }
  g.UseProgram(program);
  for (size_t i = 0; i < textures.size(); ++i) {
    g.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(i));
    g.BindTexture(GL_TEXTURE_2D, textures[i].tex);
    const GLint f = textures[i].linear ? GL_LINEAR : GL_NEAREST;
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
    const GLint loc = g.GetUniformLocation(program, textures[i].sampler.c_str());
    if (loc >= 0) g.Uniform1i(loc, static_cast<GLint>(i));
  }
  r_.bind_fullscreen_triangle();
  g.DrawArrays(GL_TRIANGLES, 0, 3);
  g.Disable(GL_SCISSOR_TEST);
  return gl_no_error(g, std::string("in a pass into a ") + target_format_name(t.fmt) + " target", err);
}

static GLuint upload(const GlFns &g, int w, int h, GLenum ifmt, GLenum type, const void *data) {
  GLuint t = 0;
  g.GenTextures(1, &t);
  g.BindTexture(GL_TEXTURE_2D, t);
  g.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  g.TexImage2D(GL_TEXTURE_2D, 0, ifmt, w, h, 0, GL_RGBA, type, data);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

GLuint upload_rgba16f(const GlFns &g, int w, int h, const std::vector<uint16_t> &halves) {
  return upload(g, w, h, GL_RGBA16F, GL_HALF_FLOAT, halves.data());
}

GLuint upload_rgba8(const GlFns &g, int w, int h, const std::vector<uint8_t> &codes) {
  return upload(g, w, h, GL_RGBA8, GL_UNSIGNED_BYTE, codes.data());
}

// The whole target as `type` values, 4 per pixel.
template <class T>
static bool read_target(const GlFns &g, const GlTarget &t, GLenum type, std::vector<T> *out, const std::string &doing,
                        std::string *err) {
  out->assign(static_cast<size_t>(t.w) * t.h * 4, T(0));
  g.BindFramebuffer(GL_FRAMEBUFFER, t.fbo);
  g.PixelStorei(GL_PACK_ALIGNMENT, 4);
  g.ReadPixels(0, 0, t.w, t.h, GL_RGBA, type, out->data());
  return gl_no_error(g, doing, err);
}

bool read_rgba8(const GlFns &g, const GlTarget &t, std::vector<uint8_t> *out, std::string *err) {
  return read_target(g, t, GL_UNSIGNED_BYTE, out, "reading an RGBA8 target", err);
}

bool read_float(const GlFns &g, const GlTarget &t, std::vector<float> *out, std::string *err) {
  return read_target(g, t, GL_FLOAT, out, std::string("reading a ") + target_format_name(t.fmt) + " target as float",
                     err);
}

bool load_sync_fns(Backend b, GlSyncFns *f, std::string *err) {
  auto get = [&](const char *name) -> void * {
    if (b == Backend::OSMesa) {
      const OsmesaApi *os = osmesa_api(nullptr);
      return os ? reinterpret_cast<void *>(os->GetProcAddress(name)) : nullptr;
    }
    return reinterpret_cast<void *>(eglGetProcAddress(name));
  };
  f->MapBufferRange = reinterpret_cast<PFNGLMAPBUFFERRANGEPROC>(get("glMapBufferRange"));
  f->UnmapBuffer = reinterpret_cast<PFNGLUNMAPBUFFERPROC>(get("glUnmapBuffer"));
  f->FenceSync = reinterpret_cast<PFNGLFENCESYNCPROC>(get("glFenceSync"));
  f->GetSynciv = reinterpret_cast<PFNGLGETSYNCIVPROC>(get("glGetSynciv"));
  f->ClientWaitSync = reinterpret_cast<PFNGLCLIENTWAITSYNCPROC>(get("glClientWaitSync"));
  f->DeleteSync = reinterpret_cast<PFNGLDELETESYNCPROC>(get("glDeleteSync"));
  if (!f->MapBufferRange || !f->UnmapBuffer || !f->FenceSync || !f->GetSynciv || !f->ClientWaitSync || !f->DeleteSync) {
    *err = "glMapBufferRange, glUnmapBuffer or the fence-sync entry points are missing";
    return false;
  }
  return true;
}

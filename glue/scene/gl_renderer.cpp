// tiershade scene: scene frames on GL (glue/scene/gl_renderer.h).
#include "scene/gl_renderer.h"

#include <chrono>
#include <cstring>
#include <map>

#include "shaderlib/assembler.h"
#include "conform/conform.h"
#include "families/family.h"
#include "gl/errors.h"
#include "scene/finite_check.h"

namespace {
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }
const char *kAttr[5] = {"a_position", "a_normal", "a_uv", "a_tangent", "a_lightmap"};
const int kAttrSize[5] = {3, 3, 2, 4, 4};
}  // namespace

SceneGl::SceneGl(GlRenderer &r, Api api) : r_(r), api_(api) {}

SceneGl::~SceneGl() {
  const GlFns &g = gl();
  for (GLuint p : programs_) r_.delete_program(p);
  for (auto &v : gb_programs_)
    for (GLuint p : v) r_.delete_program(p);
  for (GLuint t : textures_) r_.delete_texture(t);
  for (Buffers &b : buffers_) {
    g.DeleteBuffers(5, b.vbo);
    g.DeleteBuffers(1, &b.ibo);
  }
  if (vao_) g.DeleteVertexArrays(1, &vao_);
  if (fbo_) g.DeleteFramebuffers(1, &fbo_);
  if (color_) g.DeleteTextures(1, &color_);
  if (depth_) g.DeleteRenderbuffers(1, &depth_);
  if (ms_fbo_) g.DeleteFramebuffers(1, &ms_fbo_);
  if (rs_fbo_) g.DeleteFramebuffers(1, &rs_fbo_);
  if (ms_color_) g.DeleteRenderbuffers(1, &ms_color_);
  if (ms_depth_) g.DeleteRenderbuffers(1, &ms_depth_);
  if (rs_color_) g.DeleteTextures(1, &rs_color_);
  if (gbm_fbo_) g.DeleteFramebuffers(1, &gbm_fbo_);
  if (gbm_color_) g.DeleteRenderbuffers(1, &gbm_color_);
  if (gbm_depth_) g.DeleteRenderbuffers(1, &gbm_depth_);
}

bool SceneGl::init(const PreparedScene &p, std::string *err, double *compile_ms, int target_w, int target_h) {
  p_ = &p;
  tw_ = target_w > 0 ? target_w : p.w;
  th_ = target_h > 0 ? target_h : p.h;
  const GlFns &g = gl();
  const auto t0 = Clock::now();
  for (const PreparedDraw &d : p.draws) {
    const std::string name = d.variant->shader->name + "|" + d.variant->name();
    size_t k = 0;
    while (k < variant_names_.size() && variant_names_[k] != name) ++k;
    if (k == variant_names_.size()) {
      const GLuint prog = build_production_program(r_, api_, *d.variant, err);
      if (!prog) {
        *err = d.variant->shader->name + " " + d.variant->name() + ": " + *err;
        return false;
      }
      variant_names_.push_back(name);
      programs_.push_back(prog);
    }
    prog_of_draw_.push_back(static_cast<int>(k));
  }
  if (p.sky.present()) {
    sky_.reset(new SkyboxGl(r_, api_));
    if (!sky_->init(p.sky, err)) return false;
  }
  g.Finish();
  if (compile_ms) *compile_ms = ms_since(t0);
  g.GenVertexArrays(1, &vao_);
  g.BindVertexArray(vao_);
  for (const TextureDesc &t : p.textures) textures_.push_back(r_.upload_texture(t));
  // One set of buffers per DrawGeometry: the draws of a shared mesh bind the same ones.
  std::map<const DrawGeometry *, int> buffer_index;
  for (const PreparedDraw &d : p.draws) {
    auto it = buffer_index.find(d.geo.get());
    if (it != buffer_index.end()) {
      buf_of_draw_.push_back(it->second);
      continue;
    }
    const DrawGeometry &geo = *d.geo;
    Buffers b;
    const std::vector<float> *arrays[5] = {&geo.position, &geo.normal, &geo.uv, &geo.tangent, &geo.lightmap};
    g.GenBuffers(5, b.vbo);
    for (int a = 0; a < 5; ++a) {
      g.BindBuffer(GL_ARRAY_BUFFER, b.vbo[a]);
      g.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(arrays[a]->size() * sizeof(float)),
                   arrays[a]->empty() ? nullptr : arrays[a]->data(), GL_STATIC_DRAW);
    }
    g.GenBuffers(1, &b.ibo);
    g.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ibo);
    g.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(geo.indices.size() * sizeof(uint32_t)),
                 geo.indices.data(), GL_STATIC_DRAW);
    b.count = static_cast<GLsizei>(geo.indices.size());
    buffer_index[d.geo.get()] = static_cast<int>(buffers_.size());
    buf_of_draw_.push_back(static_cast<int>(buffers_.size()));
    buffers_.push_back(b);
  }
  // Target: RGBA32F colour and a depth renderbuffer.
  g.GenFramebuffers(1, &fbo_);
  color_ = new_target_texture(g, GL_RGBA32F, GL_FLOAT, tw_, th_);
  g.GenRenderbuffers(1, &depth_);
  g.BindRenderbuffer(GL_RENDERBUFFER, depth_);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, tw_, th_);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (!gl_framebuffer_complete(g, "scene framebuffer", err)) return false;
  if (msaa_ > 1 && !init_msaa(err)) return false;
  return gl_no_error(g, "while uploading the scene", err);
}

// The multisampled target (see set_msaa). GL_MAX_SAMPLES bounds the count a context offers
// (llvmpipe: 4, its one multisample mode, lp_sample_pos_4x); a count it lacks is rounded up to
// the next one it has (GL ES 3.0 section 4.4.2.1), which GL_RENDERBUFFER_SAMPLES reports.
bool SceneGl::init_msaa(std::string *err) {
  const GlFns &g = gl();
  if (api_ == Api::GLES2) {
    *err = "MSAA needs multisampled framebuffers (GLES 3.0 or GL 3.3; GLES 2.0 has none)";
    return false;
  }
  GLint max_samples = 0;
  g.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (max_samples < msaa_) {
    *err = "--msaa " + std::to_string(msaa_) + ": this context offers at most " + std::to_string(max_samples) +
        " samples per pixel (GL_MAX_SAMPLES)";
    return false;
  }
  g.GenRenderbuffers(1, &ms_color_);
  g.BindRenderbuffer(GL_RENDERBUFFER, ms_color_);
  g.RenderbufferStorageMultisample(GL_RENDERBUFFER, msaa_, GL_RGBA8, tw_, th_);
  g.GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &msaa_got_);
  g.GenRenderbuffers(1, &ms_depth_);
  g.BindRenderbuffer(GL_RENDERBUFFER, ms_depth_);
  g.RenderbufferStorageMultisample(GL_RENDERBUFFER, msaa_, GL_DEPTH_COMPONENT24, tw_, th_);
  g.GenFramebuffers(1, &ms_fbo_);
  g.BindFramebuffer(GL_FRAMEBUFFER, ms_fbo_);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ms_color_);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ms_depth_);
  if (!gl_framebuffer_complete(g, "multisampled scene framebuffer", err)) return false;
  rs_color_ = new_target_texture(g, GL_RGBA8, GL_UNSIGNED_BYTE, tw_, th_);
  g.GenFramebuffers(1, &rs_fbo_);
  g.BindFramebuffer(GL_FRAMEBUFFER, rs_fbo_);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rs_color_, 0);
  if (!gl_framebuffer_complete(g, "MSAA resolve framebuffer", err)) return false;
  return gl_no_error(g, "while allocating the multisampled target", err);
}

bool SceneGl::frame_msaa(std::vector<uint8_t> *rgba8, std::string *err, double *draw_ms,
                         const std::function<void(int, GLuint)> &before_draw) {
  const GlFns &g = gl();
  if (!ms_fbo_) {
    *err = "frame_msaa without a multisampled target (set_msaa before init)";
    return false;
  }
  const auto t0 = Clock::now();
  ms_pass_ = true;
  const bool ok = draw_all(programs_, true, 0, err, before_draw);
  ms_pass_ = false;
  if (!ok) return false;
  // The resolve: a blit from the multisampled framebuffer to the one-sample one, same size.
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo_);
  g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, rs_fbo_);
  g.BlitFramebuffer(0, 0, tw_, th_, 0, 0, tw_, th_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  g.Finish();
  if (draw_ms) *draw_ms = ms_since(t0);
  rgba8->assign(static_cast<size_t>(p_->w) * p_->h * 4, 0);
  g.BindFramebuffer(GL_FRAMEBUFFER, rs_fbo_);
  g.PixelStorei(GL_PACK_ALIGNMENT, 4);
  g.ReadPixels(0, 0, p_->w, p_->h, GL_RGBA, GL_UNSIGNED_BYTE, rgba8->data());
  return gl_no_error(g, "while resolving the multisampled frame", err);
}

bool SceneGl::bind_draw(size_t i, GLuint program, bool production, std::string *err) {
  const GlFns &g = gl();
  const PreparedDraw &d = p_->draws[i];
  g.UseProgram(program);
  auto mat = [&](const char *name, const float *m) {
    const GLint loc = g.GetUniformLocation(program, name);
    if (loc >= 0) g.UniformMatrix4fv(loc, 1, GL_FALSE, m);
  };
  mat("u_model", d.model);
  mat("u_view_proj", p_->view_proj);
  const GLint eye = g.GetUniformLocation(program, "u_eye_position");
  if (eye >= 0) g.Uniform4f(eye, p_->eye[0], p_->eye[1], p_->eye[2], 1.f);
  const ShaderFamily *f = find_family(d.variant->shader->name);
  if (!f) {
    *err = "no family " + d.variant->shader->name;
    return false;
  }
  // The host contract (scene/finite_check.h): no NaN or Inf reaches a shader's uniforms.
  if (!check_finite(&d.shared.data()->x, d.shared.size() * 4, "draw " + std::to_string(i) + " (" + d.variant->name() + ") uniforms", err))
    return false;
  f->bind_uniforms(g, program, d.shared);
  if (production) {
    for (size_t t = 0; t < d.tex.size(); ++t) {
      const TextureDesc &td = p_->textures.at(d.tex[t]);
      g.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(t));
      g.BindTexture(td.kind == TexKind::Cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D, textures_.at(d.tex[t]));
      const GLint loc = g.GetUniformLocation(program, td.sampler.c_str());
      if (loc >= 0) g.Uniform1i(loc, static_cast<GLint>(t));
    }
  }
  const Buffers &b = buffers_[static_cast<size_t>(buf_of_draw_[i])];
  for (int a = 0; a < 5; ++a) {
    const GLint loc = g.GetAttribLocation(program, kAttr[a]);
    if (loc < 0) continue;
    g.BindBuffer(GL_ARRAY_BUFFER, b.vbo[a]);
    g.EnableVertexAttribArray(static_cast<GLuint>(loc));
    g.VertexAttribPointer(static_cast<GLuint>(loc), kAttrSize[a], GL_FLOAT, GL_FALSE, 0, nullptr);
  }
  g.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ibo);
  return true;
}

// The state of every scene pass: the target, no blending or culling, depth test LESS (as an
// engine draws opaque geometry; the draw dump documents the same state, docs/bundles.md).
void SceneGl::begin_pass() {
  const GlFns &g = gl();
  g.BindFramebuffer(GL_FRAMEBUFFER, gbm_pass_ ? gbm_fbo_ : ms_pass_ ? ms_fbo_ : fbo_);
  g.BindVertexArray(vao_);
  // The frame's size within the target (a probe's cube face of a smaller edge than the largest one's
  // target, glue/scene/probe_render.h); warm-up contexts draw a larger frame squeezed into their small one.
  g.Viewport(0, 0, p_->w < tw_ ? p_->w : tw_, p_->h < th_ ? p_->h : th_);
  g.Disable(GL_BLEND);
  g.Disable(GL_CULL_FACE);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LESS);
  g.DepthMask(GL_TRUE);
}

bool SceneGl::draw_all(const std::vector<GLuint> &progs, bool production, int gb_slot, std::string *err,
                       const std::function<void(int, GLuint)> &before_draw) {
  const GlFns &g = gl();
  begin_pass();
  g.ClearColor(0.f, 0.f, 0.f, 0.f);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (gbm_pass_) {
    g.Enable(GL_SAMPLE_COVERAGE);
    g.SampleCoverage(1.f / static_cast<float>(msaa_got_), GL_FALSE);
  }
  // The skybox first, over every pixel; the geometry overwrites what it covers (skybox_pass.h).
  if (production && sky_) {
    if (!sky_->draw(p_->sky, err)) return false;
    g.BindVertexArray(vao_);
  }
  bind_ms_ = 0;
  for (size_t i = 0; i < p_->draws.size(); ++i) {
    const GLuint prog = progs.at(prog_of_draw_[i]);
    const auto tb = Clock::now();
    if (!bind_draw(i, prog, production, err)) return false;
    bind_ms_ += ms_since(tb);
    if (gb_slot == -1) {
      const GLint loc = g.GetUniformLocation(prog, "u_draw_index");
      if (loc >= 0) g.Uniform1f(loc, static_cast<float>(i));
    }
    if (progress_) progress_->store(static_cast<int>(i));
    if (before_draw) before_draw(static_cast<int>(i), prog);
    const auto td = Clock::now();
    g.DrawElements(GL_TRIANGLES, buffers_[static_cast<size_t>(buf_of_draw_[i])].count, GL_UNSIGNED_INT, nullptr);
    if (getenv("TS_DRAW_MS")) {
      g.Finish();
      fprintf(stderr, "draw %zu %s: %.1f ms\n", i, p_->draws[i].variant->name().c_str(), ms_since(td));
    }
  }
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_SAMPLE_COVERAGE);
  return gl_no_error(g, "while drawing the scene", err);
}

void SceneGl::warm(const std::atomic<int> *main_next) {
  const GlFns &g = gl();
  ms_pass_ = ms_fbo_ != 0;  // MSAA: the multisampled target's shader variants
  begin_pass();
  ms_pass_ = false;
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  std::vector<bool> done(programs_.size(), false);
  std::string err;
  for (int i = static_cast<int>(p_->draws.size()) - 1; i >= 0; --i) {
    if (main_next->load() >= i) break;
    const int k = prog_of_draw_[static_cast<size_t>(i)];
    if (done[static_cast<size_t>(k)]) continue;
    done[static_cast<size_t>(k)] = true;
    if (!bind_draw(static_cast<size_t>(i), programs_[static_cast<size_t>(k)], true, &err)) break;
    g.DrawElements(GL_TRIANGLES, buffers_[static_cast<size_t>(buf_of_draw_[static_cast<size_t>(i)])].count, GL_UNSIGNED_INT,
                   nullptr);
    g.Finish();
  }
}

bool SceneGl::read(std::vector<float> *rgba) {
  const GlFns &g = gl();
  rgba->assign(static_cast<size_t>(p_->w) * p_->h * 4, 0.f);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  g.PixelStorei(GL_PACK_ALIGNMENT, 4);
  g.ReadPixels(0, 0, p_->w, p_->h, GL_RGBA, GL_FLOAT, rgba->data());
  return g.GetError() == GL_NO_ERROR;
}

bool SceneGl::frame(ImageF *out, std::string *err, double *draw_ms,
                    const std::function<void(int, GLuint)> &before_draw) {
  const auto t0 = Clock::now();
  if (!draw_all(programs_, true, 0, err, before_draw)) return false;
  gl().Finish();
  if (draw_ms) *draw_ms = ms_since(t0);
  out->w = p_->w;
  out->h = p_->h;
  if (!read(&out->rgba)) {
    *err = "reading the scene frame back failed";
    return false;
  }
  return true;
}

bool SceneGl::gbuffer_msaa(std::vector<int> *draw, std::vector<float> *slots, std::string *err,
                           std::vector<float> *grads) {
  const GlFns &g = gl();
  if (!ms_fbo_) {
    *err = "gbuffer_msaa without a multisampled target (set_msaa before init)";
    return false;
  }
  if (!gbm_fbo_) {
    g.GenRenderbuffers(1, &gbm_color_);
    g.BindRenderbuffer(GL_RENDERBUFFER, gbm_color_);
    g.RenderbufferStorageMultisample(GL_RENDERBUFFER, msaa_got_, GL_RGBA32F, tw_, th_);
    g.GenRenderbuffers(1, &gbm_depth_);
    g.BindRenderbuffer(GL_RENDERBUFFER, gbm_depth_);
    g.RenderbufferStorageMultisample(GL_RENDERBUFFER, msaa_got_, GL_DEPTH_COMPONENT24, tw_, th_);
    g.GenFramebuffers(1, &gbm_fbo_);
    g.BindFramebuffer(GL_FRAMEBUFFER, gbm_fbo_);
    g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, gbm_color_);
    g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, gbm_depth_);
    if (!gl_framebuffer_complete(g, "multisampled G-buffer framebuffer", err)) return false;
  }
  // Each pass resolved into the one-sample RGBA32F target (fbo_), which read() reads.
  gbm_pass_ = true;
  const bool ok = gbuffer_passes(draw, slots, err, [&] {
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, gbm_fbo_);
    g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
    g.BlitFramebuffer(0, 0, tw_, th_, 0, 0, tw_, th_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }, static_cast<float>(msaa_got_), grads);
  gbm_pass_ = false;
  return ok;
}

bool SceneGl::gbuffer(std::vector<int> *draw, std::vector<float> *slots, std::string *err, std::vector<float> *grads) {
  return gbuffer_passes(draw, slots, err, nullptr, 1.f, grads);
}

bool SceneGl::gbuffer_passes(std::vector<int> *draw, std::vector<float> *slots, std::string *err,
                             const std::function<void()> &resolve, float scale, std::vector<float> *grads) {
  const size_t n = static_cast<size_t>(p_->w) * p_->h;
  if (gb_programs_.empty()) {
    const Target t = target_for_api(api_);
    gb_programs_.assign(8, {});
    for (int slot = -1; slot < 7; ++slot) {  // slot 6: the uv's quad derivatives
      for (size_t k = 0; k < variant_names_.size(); ++k) {
        size_t di = 0;
        while (prog_of_draw_[di] != static_cast<int>(k)) ++di;
        const Variant &v = *p_->draws[di].variant;
        auto defs = variant_defines(v, InputMode::Production);
        defs.push_back({"GBUFFER_FAMILY", p_->draws[di].world ? "1" : "0"});
        defs.push_back({"GBUFFER_SLOT", std::to_string(slot)});
        Assembled vs, fs;
        if (!assemble(v.shader->vertex, t, Stage::Vertex, defs, &vs, err) ||
            !assemble("scene_gbuffer.fs", t, Stage::Fragment, defs, &fs, err))
          return false;
        const GLuint prog = r_.build_program(vs, fs, err);
        if (!prog) return false;
        gb_programs_[slot + 1].push_back(prog);
      }
    }
  }
  std::vector<float> img;
  draw->assign(n, -1);
  slots->assign(n * 24, 0.f);
  if (grads) grads->assign(n * 4, 0.f);
  for (int slot = -1; slot < (grads ? 7 : 6); ++slot) {
    if (!draw_all(gb_programs_[slot + 1], false, slot, err, nullptr)) return false;
    if (resolve) resolve();
    if (!read(&img)) {
      *err = "reading the G-buffer back failed";
      return false;
    }
    for (size_t i = 0; i < n; ++i) {
      if (scale != 1.f)
        for (int c = 0; c < 4; ++c) img[i * 4 + c] *= scale;
      if (slot < 0) {
        (*draw)[i] = img[i * 4 + 3] > 0.5f ? static_cast<int>(img[i * 4]) : -1;
      } else if (slot == 6) {
        std::memcpy(&(*grads)[i * 4], &img[i * 4], 4 * sizeof(float));
      } else {
        std::memcpy(&(*slots)[i * 24 + slot * 4], &img[i * 4], 4 * sizeof(float));
      }
    }
  }
  return true;
}

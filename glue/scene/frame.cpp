// tiershade scene: a scene frame end to end (glue/scene/frame.h).
#include "scene/frame.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>
#include <cmath>
#include <memory>

#include "families/color_correction_inputs.h"
#include "color/correct_rgba8_cpu.h"
#include "twins/color_correction.h"
#include "families/family.h"
#include "conform/family_frame.h"
#include "math/hdr_formats.h"
#include "twins/hdr_post_batch.h"
#include "hdr/paths.h"
#include "color/ocio_lut_bake.h"
#include "io/lut_files.h"
#include "scene/cpu_renderer.h"
#include "scene/gl_renderer.h"
#include "scene/msaa.h"
#include "scene/prepare.h"
#include "scene/probe_render.h"
#include "hdr/srgb_rgba8_codes.h"
#include "hdr/still_frame_exposure.h"
#include "base/image_diff.h"
#include "base/parallel_rows.h"

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

bool load_luts(const SceneHdr &sh, std::vector<Lut3D> *out, std::string *err) {
  for (const SceneLut &l : sh.luts) {
    Lut3D lut;
    const std::string ext = l.path.size() > 4 ? l.path.substr(l.path.size() - 4) : "";
    if (ext == "cube" || ext == ".raw") {
      if (!read_lut_file(l.path, &lut, err)) return false;
    } else {
      TransformSpec spec;
      spec.file = l.path;
      ColorTransform t;
      if (!t.open(spec, err) || !bake_lut(t, 32, &lut, err)) return false;
    }
    if (!out->empty() && lut.n != out->front().n) {
      *err = l.path + ": LUT edge " + std::to_string(lut.n) + " differs from the first LUT's " +
          std::to_string(out->front().n) + " (blended LUTs share one edge)";
      return false;
    }
    out->push_back(std::move(lut));
  }
  return true;
}

}  // namespace

ImageF display_image(const SceneRenderResult &r) {
  ImageF img;
  img.w = r.w;
  img.h = r.h;
  img.rgba.resize(r.display.size());
  for (size_t i = 0; i < r.display.size(); ++i) img.rgba[i] = r.display[i] / 255.f;
  return img;
}

struct SceneRenderer::Impl {
  const Scene *s = nullptr;
  const SceneSelection *sel = nullptr;
  SceneRenderConfig cfg;
  bool cpu = false, float_path = false;
  PreparedScene p;
  double prepare_ms = 0, compile_ms = 0;
  std::unique_ptr<GlContext> ctx;
  std::unique_ptr<GlRenderer> renderer;
  std::unique_ptr<SceneGl> sgl;
  std::unique_ptr<PassRunner> runner;
  std::unique_ptr<HdrPipelineGl> pipe;
  // Colour correction: the LUTs, the variant and (GL) its program with the LUT textures.
  std::vector<Lut3D> luts;
  std::vector<ShaderDecl> decls;
  SceneVisibility vis;  // the C fallback's visibility buffer, kept across frames
  Variant cc_var;
  const ShaderFamily *cc_family = nullptr;
  FamilyInputs cc_in;  // shared slots and LUT textures (the colour is per pixel)
  GLuint cc_program = 0;
  std::vector<GLuint> cc_lut_tex;
  std::vector<GLenum> cc_lut_kind;
  GlTarget cc_src, cc_dst;
  bool cc_ready = false;
  // Shader warm-up on a second core (see start_warmup).
  std::thread warm;
  std::atomic<int> main_next{-1};
  void join_warmup() {
    if (warm.joinable()) warm.join();
  }
  void start_warmup();
  ~Impl() {
    main_next.store(1 << 30);
    join_warmup();
    if (renderer) {
      for (GLuint t : cc_lut_tex) renderer->delete_texture(t);
      free_target(renderer->gl(), &cc_src);
      free_target(renderer->gl(), &cc_dst);
    }
    pipe.reset();
    runner.reset();
    sgl.reset();
    renderer.reset();
    ctx.reset();
  }
  std::vector<uint8_t> cpu_linear;  // the C fallback's linear pixels (scene_render_cpu), when post needs them
  HdrFrameC post_c;  // the C float path's bloom images and scratch, kept across frames
  // The integer path's display encoding: any pixel linear (ps20 and world draws and the skybox
  // write linear values), and linear pixels beside display-encoded ones (post then needs each
  // pixel's draw, or the C fallback's linear flags).
  bool any_linear() const {
    bool any = p.sky.present();
    for (const PreparedDraw &d : p.draws) any = any || !d.display_encoded;
    return any;
  }
  bool mixed_encoding() const {
    if (float_path) return false;
    const bool any = any_linear();
    for (const PreparedDraw &d : p.draws)
      if (d.display_encoded && any) return true;
    return false;
  }
  bool colour_correct(SceneRenderResult *res, bool on_cpu, std::string *err);
  bool msaa_frame(SceneRenderResult *res, std::string *err);
  bool post(SceneRenderResult *res, bool on_cpu, const std::vector<int> &draw_of_pixel, std::string *err,
            const std::vector<uint8_t> *linear_of_pixel = nullptr);
};

// llvmpipe JIT-compiles a shader variant at its first draw, on the drawing thread. With Mesa's
// shader cache on (MESA_SHADER_CACHE_DISABLE unset), a second context on a second core draws
// the scene's draws from the last one down into a tiny target, so that the variants the main
// thread reaches later come out of the cache; it stops where the main thread has got to.
// Same shaders, same state, same variants: the frame is unchanged (the --check tests run with
// and without it). TIERSHADE_NO_WARMUP=1 turns it off.
void SceneRenderer::Impl::start_warmup() {
  const char *off = getenv("TIERSHADE_NO_WARMUP");
  const char *nocache = getenv("MESA_SHADER_CACHE_DISABLE");
  if ((off && *off && strcmp(off, "0") != 0) || (nocache && (!strcmp(nocache, "true") || !strcmp(nocache, "1"))))
    return;
  if (std::thread::hardware_concurrency() < 2 || p.draws.size() < 2) return;
  main_next.store(-1);
  warm = std::thread([this] {
    std::string e;
    auto c = GlContext::create(cfg.backend, cfg.api, &e);
    if (!c) return;
    GlRenderer r(*c);
    if (float_path) {
      // The post-processing programs first: the main thread needs them last.
      PassRunner run(r);
      HdrPipelineGl pipe(run, cfg.api);
      std::vector<float> black(16 * 16 * 4, 0.f);
      HdrSettings hs;
      hs.bloom_amount = s->hdr.bloom_amount;  // the passes the main thread will run, no others
      if (!pipe.init_post(16, 16, &e, hs.bloom_amount != 0.f) || !pipe.post_float(black, hs, &e)) return;
      c->gl().Finish();
    }
    SceneGl g(r, cfg.api);
    g.set_msaa(cfg.msaa > 1 ? cfg.msaa : 0);  // the same multisample state: the same shader variants
    if (!g.init(p, &e, nullptr, 16, 16)) return;
    g.warm(&main_next);
  });
}

SceneRenderer::SceneRenderer() : impl_(new Impl) {}
SceneRenderer::~SceneRenderer() { delete impl_; }
double SceneRenderer::prepare_ms() const { return impl_->prepare_ms; }
double SceneRenderer::compile_ms() const { return impl_->compile_ms; }

bool SceneRenderer::init(const Scene &s, const SceneSelection &sel, const SceneRenderConfig &cfg, std::string *err) {
  Impl &m = *impl_;
  m.s = &s;
  m.sel = &sel;
  m.cfg = cfg;
  m.cpu = cfg.backend == Backend::CPU;
  m.float_path = sel.hdr_path == "float";
  if (m.float_path && !m.cpu && cfg.api == Api::GLES2) {
    *err = "the float HDR path needs fp16 render targets: GLES 3.0 or GL 3.3 (--api gles3|gl33)";
    return false;
  }
  const bool msaa = cfg.msaa > 1;
  if (msaa) {  // the path and API first (before a bake), then the draws
    *err = msaa_refusal(PreparedScene(), m.float_path, m.cpu, cfg.api, cfg.msaa);
    if (!err->empty()) return false;
  }
  auto t0 = Clock::now();
  const Api cube_api = m.cpu ? Api::GL33 : cfg.api;
  PrepareOptions popt;  // the world probes' cubes: by the frame's renderer (glue/scene/probe_render.h)
  popt.mipmaps = cfg.mipmaps;
  popt.gl_probe_cubes = !m.cpu && cfg.gl_probe_cubes;
  popt.threads = cfg.threads;
  if (!prepare_scene(s, sel, cfg.w, cfg.h, cube_api, s.hdr.tone_map_scale, &m.p, err, popt)) return false;
  if (msaa) {
    *err = msaa_refusal(m.p, m.float_path, m.cpu, cfg.api, cfg.msaa);
    if (!err->empty()) return false;
  }
  if (!s.hdr.luts.empty()) {
    if (!load_luts(s.hdr, &m.luts, err) || !load_shader_decls(&m.decls, err)) return false;
    const bool atlas = !m.cpu && cfg.api == Api::GLES2;
    const std::string vname = std::string("ps2b:LUT_ATLAS=") + (atlas ? "1" : "0") +
        ",SHADER_TRILINEAR=0,NUM_LOOKUPS=" + std::to_string(m.luts.size());
    if (!find_variant(m.decls, "color_correction", vname, &m.cc_var, err)) return false;
    m.cc_family = find_family("color_correction");
  }
  m.prepare_ms = ms_since(t0);
  if (m.cpu) return true;
  m.ctx = GlContext::create(cfg.backend, cfg.api, err);
  if (!m.ctx) return false;
  m.renderer.reset(new GlRenderer(*m.ctx));
  // The probes' cubes first: the warm-up context uploads the textures they are rendered into.
  const std::string gl_name = std::string(backend_name(cfg.backend)) + "/" + api_name(cfg.api);
  if (popt.gl_probe_cubes && !render_probe_cubes_gl(s, &m.p, *m.renderer, cfg.api, gl_name, cfg.check, err))
    return false;
  m.start_warmup();
  m.sgl.reset(new SceneGl(*m.renderer, cfg.api));
  m.sgl->set_msaa(msaa ? cfg.msaa : 0);
  if (!m.sgl->init(m.p, err, &m.compile_ms)) return false;
  m.sgl->set_progress(&m.main_next);
  m.runner.reset(new PassRunner(*m.renderer));
  if (m.float_path) {
    m.pipe.reset(new HdrPipelineGl(*m.runner, cfg.api));
    if (!m.pipe->init_post(cfg.w, cfg.h, err, s.hdr.bloom_amount != 0.f)) return false;
  }
  return true;
}

bool SceneRenderer::Impl::colour_correct(SceneRenderResult *res, bool on_cpu, std::string *err) {
  float weights[4] = {0, 0, 0, 0}, sum = 0;
  for (size_t i = 0; i < luts.size(); ++i) {
    weights[i] = s->hdr.luts[i].weight;
    sum += weights[i];
  }
  // The shared slots (weights, default weight, LUT addressing) and the LUT textures; the
  // colour comes from the display frame itself (u_frame, RGBA8 as the tone map wrote it).
  if (cc_in.textures.empty()) {
    ImageF one;
    one.w = one.h = 1;
    one.rgba = {0, 0, 0, 1};
    cc_frame_inputs(one, weights, std::max(0.f, 1.f - sum), luts[0].n, &cc_in);
    std::vector<const Lut3D *> lp;
    for (const Lut3D &l : luts) lp.push_back(&l);
    cc_set_luts(&cc_in, lp, true);
  }
  const Variant &v = cc_var;
  if (on_cpu) {
    const cc_variant cv = {v.value("LUT_ATLAS"), v.value("SHADER_TRILINEAR"), v.value("NUM_LOOKUPS")};
    cc_luts views;
    cc_luts_of(cc_in, &views);
    cc_apply_rgba8_c(cv, cc_in.shared.data(), views, cfg.w, cfg.h, &res->display, cfg.threads);
    return true;
  }
  const GlFns &g = renderer->gl();
  if (!cc_ready) {
    cc_program = runner->program(cfg.api, "color_correction", v.name(), err);
    if (!cc_program) return false;
    for (const TextureDesc &t : cc_in.textures) {
      cc_lut_tex.push_back(renderer->upload_texture(t));
      cc_lut_kind.push_back(t.kind == TexKind::Tex3D ? GL_TEXTURE_3D : GL_TEXTURE_2D);
    }
    if (!make_target(g, TargetFormat::RGBA8, cfg.w, cfg.h, &cc_dst, err)) return false;
    if (!float_path && !make_target(g, TargetFormat::RGBA8, cfg.w, cfg.h, &cc_src, err)) return false;
    cc_ready = true;
  }
  GLuint frame_tex = 0;
  if (float_path) {
    frame_tex = pipe->display().tex;  // the tone map's RGBA8 output, still on the GPU
  } else {
    g.BindTexture(GL_TEXTURE_2D, cc_src.tex);
    g.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    g.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, cfg.w, cfg.h, GL_RGBA, GL_UNSIGNED_BYTE, res->display.data());
    frame_tex = cc_src.tex;
  }
  g.UseProgram(cc_program);
  cc_family->bind_uniforms(g, cc_program, cc_in.shared);
  for (size_t k = 0; k < cc_lut_tex.size(); ++k) {  // units 1.. (unit 0: u_frame, bound by the pass)
    g.ActiveTexture(GL_TEXTURE1 + static_cast<GLenum>(k));
    g.BindTexture(cc_lut_kind[k], cc_lut_tex[k]);
    const GLint loc = g.GetUniformLocation(cc_program, cc_in.textures[k].sampler.c_str());
    if (loc >= 0) g.Uniform1i(loc, static_cast<GLint>(k + 1));
  }
  if (!runner->draw(cc_program, cc_dst, {{"u_frame", frame_tex, false}}, nullptr, err)) return false;
  return read_rgba8(g, cc_dst, &res->display, err);
}

// The HDR path and colour correction of a lit frame: res->lit -> res->display, on GL or by
// the C twins (on_cpu; also used by --check on GL's own lit frame).
bool SceneRenderer::Impl::post(SceneRenderResult *res, bool on_cpu, const std::vector<int> &draw_of_pixel_in,
                               std::string *err, const std::vector<uint8_t> *linear_of_pixel) {
  std::vector<int> own;  // GL's draw indices, fetched only when needed
  const std::vector<int> *dop = &draw_of_pixel_in;
  const size_t n = static_cast<size_t>(cfg.w) * cfg.h;
  const Scene &s = *this->s;
  if (!float_path && res->msaa_samples > 1) {
    // The resolved multisampled RGBA8 frame is the display frame (every draw encoded in the
    // shader: msaa_refusal); it is opaque as the one-sample frame is.
    res->tone_map_scale = s.hdr.tone_map_scale;
    for (size_t i = 0; i < n; ++i) res->display[i * 4 + 3] = 255;
  } else if (!float_path) {
    res->tone_map_scale = s.hdr.tone_map_scale;
    if (s.hdr.auto_exposure)
      res->notes.push_back("auto exposure runs on the float path; the integer path uses the fixed tone-map scale");
    // Which pixels hold linear values the (sRGB) render target would encode: ps20 and world draws.
    const bool any_linear = this->any_linear(), mixed = mixed_encoding();
    const bool flags = mixed && linear_of_pixel && linear_of_pixel->size() == n;
    if (mixed && !flags && dop->empty()) {
      std::vector<float> slots;
      if (!sgl->gbuffer(&own, &slots, err)) return false;
      dop = &own;
    }
    const std::vector<int> &draw_of_pixel = *dop;
    res->display.resize(n * 4);
    const SrgbCodeTable &codes = srgb_code_table();
    const float *lit = res->lit.rgba.data();
    uint8_t *disp = res->display.data();
    parallel_rows(cfg.h, cfg.threads, [&](int y) {  // rows on every core (pure per pixel)
      for (size_t i = static_cast<size_t>(y) * cfg.w, e = i + cfg.w; i < e; ++i) {
        bool linear = any_linear;
        if (flags)
          linear = (*linear_of_pixel)[i] != 0;
        else if (mixed)
          linear = draw_of_pixel[i] >= 0 ? !p.draws[draw_of_pixel[i]].display_encoded : p.sky.present();
        for (int c = 0; c < 3; ++c) {
          const float v = lit[i * 4 + c];
          disp[i * 4 + c] = linear ? srgb_code_in(codes, v) : ts_unorm8_from_float(v);
        }
        disp[i * 4 + 3] = 255;
      }
    });
  } else {
    // The lit frame as the fp16 target stores it (writes round toward zero; c_ref/math/hdr_formats.h):
    // from here on, and in OUT.exr, the float path's frame is these fp16 values.
    parallel_rows(cfg.h, cfg.threads, [&](int y) {  // per value: rows on every core
      float *row = res->lit.rgba.data() + static_cast<size_t>(y) * cfg.w * 4;
      ts_quantize_half_batch(row, row, static_cast<size_t>(cfg.w) * 4);
    });
    const std::vector<float> &hdr = res->lit.rgba;
    HdrSettings hs;
    hs.tone_map_scale = s.hdr.tone_map_scale;
    hs.bloom_amount = s.hdr.bloom_amount;
    if (hs.bloom_amount == 0.f) res->notes.push_back("bloom 0: the bloom passes are skipped");
    if (s.hdr.auto_exposure) {
      const StaticLuminance lum(hdr.data(), cfg.w, cfg.h);
      hs.tone_map_scale = static_cast<float>(
          run_static_exposure(lum, s.hdr.tone_map_scale, s.hdr.exposure_min, s.hdr.exposure_max, cfg.exposure_frames)
              .scale);
      res->auto_exposure = true;
    }
    res->tone_map_scale = hs.tone_map_scale;
    if (on_cpu) {
      // The caller's display buffer and the bloom images are reused across frames (no page faults).
      post_c.display.swap(res->display);
      hdr_post_float_c(hdr, cfg.w, cfg.h, hs, &post_c, cfg.threads, false);
      res->display.swap(post_c.display);
    } else {
      if (!pipe->post_float(hdr, hs, err) || !read_rgba8(renderer->gl(), pipe->display(), &res->display, err))
        return false;
    }
  }
  if (!luts.empty() && !colour_correct(res, on_cpu, err)) return false;
  return true;
}

// The lit pass multisampled (glue/scene/msaa.h): GL draws into its multisampled RGBA8 target
// and resolves; the C fallback rasterises the same pattern. res->lit is the resolved frame as
// floats (code / 255), res->display its codes. --check compares as msaa_compare says.
bool SceneRenderer::Impl::msaa_frame(SceneRenderResult *res, std::string *err) {
  const auto t0 = Clock::now();
  MsaaFrameC c;
  if (cpu) {
    scene_render_msaa_cpu(p, cfg.msaa, &c, cfg.threads);
    res->display = std::move(c.display);
    res->msaa_samples = cfg.msaa;
    res->lit_ms = ms_since(t0);
  } else {
    std::function<void(int, GLuint)> capture;
    if (cfg.on_draw) capture = [&](int di, GLuint prog) { cfg.on_draw(sgl->gl(), p, p.draws[di], prog); };
    const bool ok = sgl->frame_msaa(&res->display, err, &res->lit_ms, capture);
    main_next.store(1 << 30);
    join_warmup();
    if (!ok) return false;
    res->msaa_samples = sgl->msaa_samples();
    if (res->msaa_samples != cfg.msaa)
      res->notes.push_back("--msaa " + std::to_string(cfg.msaa) + ": GL allocated " +
                           std::to_string(res->msaa_samples) +
                           " samples per pixel (llvmpipe's one multisample mode is 4; a count it lacks rounds up)");
  }
  res->lit.w = cfg.w;
  res->lit.h = cfg.h;
  res->lit.rgba.resize(res->display.size());
  for (size_t i = 0; i < res->display.size(); ++i) res->lit.rgba[i] = ts_unorm8_to_float(res->display[i]);
  if (cfg.on_lit) cfg.on_lit(res->lit);
  if (cfg.check && !cpu) {
    std::vector<int> draw;
    std::vector<float> slots, grads;
    // The records as the multisample shader variant interpolates them (llvmpipe's one-sample
    // variant differs in the last bit on about 1 interior pixel in 2,400-11,000).
    if (!sgl->gbuffer_msaa(&draw, &slots, err, &grads)) return false;
    ImageF twin;
    scene_shade_records(p, draw, slots, &twin, cfg.threads, &grads);
    std::vector<uint8_t> codes(twin.rgba.size());
    for (size_t i = 0; i < codes.size(); ++i) codes[i] = ts_unorm8_from_float(twin.rgba[i]);
    scene_render_msaa_cpu(p, res->msaa_samples, &c, cfg.threads);
    MsaaCheck mc;
    msaa_compare(res->display, codes, c, &mc);
    res->check_mismatched = mc.interior_mismatched;
    res->check_pixels = mc.interior;
    res->check_max_ulp = 0;
    res->check_msaa_interior = mc.interior;
    res->check_msaa_edge = mc.edge;
    res->check_msaa_edge_over_1 = mc.edge_over_1;
    res->check_msaa_edge_over_64 = mc.edge_over_64;
    res->check_msaa_edge_max = mc.edge_max;
    res->check_msaa_interior_max = mc.interior_max;
    res->check_msaa_background = mc.background;
    res->check_msaa_background_mismatched = mc.background_mismatched;
  }
  return true;
}

bool SceneRenderer::frame(SceneRenderResult *out, std::string *err) {
  Impl &m = *impl_;
  const SceneRenderConfig &cfg = m.cfg;
  PreparedScene &p = m.p;
  // Several renderers may take turns on this thread (the bench interleaves them): this one's
  // context first.
  if (m.ctx && !m.ctx->make_current()) {
    *err = "cannot make the scene's GL context current";
    return false;
  }
  const auto t_frame = Clock::now();
  SceneRenderResult res;
  res.w = cfg.w;
  res.h = cfg.h;
  res.notes = p.notes;
  for (const PreparedProbeCube &pc : p.probe_cubes) {  // --check of the cubes rendered on GL
    if (pc.check_mismatched < 0) continue;
    res.check_cube_mismatched = std::max(0L, res.check_cube_mismatched) + pc.check_mismatched;
    res.check_cube_texels += pc.check_texels;
  }
  res.prepare_ms = m.prepare_ms;
  res.compile_ms = m.compile_ms;
  res.geometry_bytes = p.geometry_bytes();
  res.geometries = p.geometries();
  res.draws = static_cast<int>(p.draws.size());
  const bool cpu = m.cpu;

  // ---- lit pass -------------------------------------------------------------------------
  auto t0 = Clock::now();
  std::vector<int> draw_of_pixel;
  if (cfg.msaa > 1) {
    if (!m.msaa_frame(&res, err)) return false;
  } else if (cpu) {
    // Rasterised and shaded in bands (the visibility of a band at a time, the draws a slab of
    // bands at a time: glue/scene/band_slabs.h). The frame buffers of the caller's last
    // result are reused (reset, not reallocated: their page faults were a tenth of a 4K frame).
    if (out->lit.rgba.size() == static_cast<size_t>(cfg.w) * cfg.h * 4) res.lit.rgba.swap(out->lit.rgba);
    if (!m.float_path) res.display.swap(out->display);
    std::vector<uint8_t> *lop = m.mixed_encoding() ? &m.cpu_linear : nullptr;
    scene_render_cpu(p, &res.lit, lop, cfg.threads, [&](double f) {
      if (cfg.progress) cfg.progress("C fallback lit pass", f);
    });
    res.lit_ms = ms_since(t0);
  } else {
    std::function<void(int, GLuint)> capture;
    if (cfg.on_draw || cfg.progress)
      capture = [&](int di, GLuint prog) {
        if (cfg.on_draw) cfg.on_draw(m.sgl->gl(), p, p.draws[di], prog);
        if (cfg.progress)
          cfg.progress("GL lit pass (a variant's first draw JIT-compiles it)",
                       static_cast<double>(di) / p.draws.size());
      };
    const bool ok = m.sgl->frame(&res.lit, err, &res.lit_ms, capture);
    m.main_next.store(1 << 30);
    m.join_warmup();
    if (!ok) return false;
    if (cfg.on_lit) cfg.on_lit(res.lit);
    if (cfg.progress) cfg.progress("GL lit pass (a variant's first draw JIT-compiles it)", 1.0);
    if (cfg.check) {
      std::vector<float> slots, grads;
      if (!m.sgl->gbuffer(&draw_of_pixel, &slots, err, &grads)) return false;
      ImageF c;
      scene_shade_records(p, draw_of_pixel, slots, &c, cfg.threads, &grads);
      DiffStats st;
      diff_image(res.lit, c, &st);
      res.check_mismatched = st.mismatched_pixels;
      res.check_pixels = 0;
      for (int d : draw_of_pixel) res.check_pixels += d >= 0 || p.sky.present();  // the skybox covers the rest
      res.check_max_ulp = st.max_ulp;
      res.check_lit = std::move(c);
    }
  }

  t0 = Clock::now();
  if (cfg.check && !cpu) {
    // The post chain on GL against its C twin, both from GL's lit frame.
    SceneRenderResult c = res;
    if (!m.post(&c, true, draw_of_pixel, err) || !m.post(&res, false, draw_of_pixel, err)) return false;
    res.check_post_channels = static_cast<long>(res.display.size());
    res.check_post_mismatched = 0;
    for (size_t i = 0; i < res.display.size(); ++i) res.check_post_mismatched += res.display[i] != c.display[i];
  } else if (!m.post(&res, cpu, draw_of_pixel, err, cpu && cfg.msaa <= 1 ? &m.cpu_linear : nullptr)) {
    return false;
  }
  res.post_ms = ms_since(t0);
  res.frame_ms = ms_since(t_frame);
  *out = std::move(res);
  return true;
}

bool render_scene(const Scene &s, const SceneSelection &sel, const SceneRenderConfig &cfg, SceneRenderResult *out,
                  std::string *err) {
  const auto t0 = Clock::now();
  SceneRenderer r;
  if (!r.init(s, sel, cfg, err) || !r.frame(out, err)) return false;
  out->frame_ms = ms_since(t0);
  return true;
}


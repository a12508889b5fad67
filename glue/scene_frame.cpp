// tiershade glue: a scene frame end to end (glue/scene_frame.h).
#include "scene_frame.h"

#include <chrono>
#include <cmath>
#include <memory>

#include "cc_inputs.h"
#include "color_correction.h"
#include "parallel_rows.h"
#include "family.h"
#include "frame.h"
#include "hdr_formats.h"
#include "hdr_pipeline.h"
#include "lut_bake.h"
#include "lut_io.h"
#include "scene_cpu.h"
#include "scene_gl.h"
#include "scene_prepare.h"
#include "static_exposure.h"

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// The exact sRGB curve (IEC 61966-2-1), for linear outputs the render target would encode.
float srgb_encode(float v) {
  if (!(v > 0.f)) return 0.f;
  if (v >= 1.f) return 1.f;
  const double d = v;
  return static_cast<float>(d <= 0.0031308 ? d * 12.92 : 1.055 * std::pow(d, 1.0 / 2.4) - 0.055);
}

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

void to_codes(const ImageF &img, std::vector<uint8_t> *codes) {
  codes->resize(img.rgba.size());
  for (size_t i = 0; i < img.rgba.size(); ++i) (*codes)[i] = ts_unorm8_from_float(img.rgba[i]);
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
  Variant cc_var;
  const ShaderFamily *cc_family = nullptr;
  FamilyInputs cc_in;
  GlFrameProgram cc_prog;
  bool cc_ready = false;
  ~Impl() {
    if (cc_ready && renderer) gl_frame_release(*renderer, &cc_prog);
    pipe.reset();
    runner.reset();
    sgl.reset();
    renderer.reset();
    ctx.reset();
  }
  bool colour_correct(SceneRenderResult *res, std::string *err);
};

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
  auto t0 = Clock::now();
  const Api cube_api = m.cpu ? Api::GL33 : cfg.api;
  if (!prepare_scene(s, sel, cfg.w, cfg.h, cube_api, s.hdr.tone_map_scale, &m.p, err)) return false;
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
  m.sgl.reset(new SceneGl(*m.renderer, cfg.api));
  if (!m.sgl->init(m.p, err, &m.compile_ms)) return false;
  m.runner.reset(new PassRunner(*m.renderer));
  if (m.float_path) {
    m.pipe.reset(new HdrPipelineGl(*m.runner, cfg.api));
    if (!m.pipe->init_post(cfg.w, cfg.h, err)) return false;
  }
  return true;
}

bool SceneRenderer::Impl::colour_correct(SceneRenderResult *res, std::string *err) {
  const size_t n = static_cast<size_t>(cfg.w) * cfg.h;
  float weights[4] = {0, 0, 0, 0}, sum = 0;
  for (size_t i = 0; i < luts.size(); ++i) {
    weights[i] = s->hdr.luts[i].weight;
    sum += weights[i];
  }
  const ImageF disp = display_image(*res);
  cc_frame_inputs(disp, weights, std::max(0.f, 1.f - sum), luts[0].n, &cc_in);
  std::vector<const Lut3D *> lp;
  for (const Lut3D &l : luts) lp.push_back(&l);
  cc_set_luts(&cc_in, lp, true);
  ImageF cc;
  const FamilyInputs &in = cc_in;
  const Variant &v = cc_var;
  if (cpu) {
    // The twin per pixel with the LUT views made once (the family's generic eval remakes them).
    const cc_variant cv = {v.value("LUT_ATLAS"), v.value("SHADER_TRILINEAR"), v.value("NUM_LOOKUPS")};
    cc_luts views;
    cc_luts_of(in, &views);
    cc.w = in.w;
    cc.h = in.h;
    cc.rgba.assign(n * 4, 0.f);
    scene_parallel_rows(in.h, cfg.threads, [&](int y) {
      for (int x = 0; x < in.w; ++x) {
        ts_vec4f rec[CC_SLOTS];
        for (int k = 0; k < CC_SLOTS; ++k) rec[k] = in.slot(x, y, k);
        const ts_vec4f c = color_correction_f(&cv, rec, &views);
        float *o = &cc.rgba[(static_cast<size_t>(y) * in.w + x) * 4];
        o[0] = c.x;
        o[1] = c.y;
        o[2] = c.z;
        o[3] = c.w;
      }
    });
  } else {
    if (!cc_ready) {
      if (!gl_frame_setup(*renderer, cfg.api, *cc_family, v, in, &cc_prog, err)) return false;
      cc_ready = true;
    } else {
      // The record (the display frame) changed: upload it again.
      const TextureDesc rec = in.record_texture();
      renderer->delete_texture(cc_prog.textures.at(0).second);
      cc_prog.textures[0].second = renderer->upload_texture(rec);
    }
    renderer->gl().UseProgram(cc_prog.program);
    cc_family->bind_uniforms(renderer->gl(), cc_prog.program, in.shared);
    if (!gl_frame_draw(*renderer, cc_prog, in, &cc, nullptr, err)) return false;
  }
  to_codes(cc, &res->display);
  for (size_t i = 0; i < n; ++i) res->display[i * 4 + 3] = 255;
  return true;
}

bool SceneRenderer::frame(SceneRenderResult *out, std::string *err) {
  Impl &m = *impl_;
  const SceneRenderConfig &cfg = m.cfg;
  const Scene &s = *m.s;
  PreparedScene &p = m.p;
  const auto t_frame = Clock::now();
  SceneRenderResult res;
  res.w = cfg.w;
  res.h = cfg.h;
  res.notes = p.notes;
  res.prepare_ms = m.prepare_ms;
  res.compile_ms = m.compile_ms;
  const bool cpu = m.cpu, float_path = m.float_path;

  // ---- lit pass -------------------------------------------------------------------------
  auto t0 = Clock::now();
  std::vector<int> draw_of_pixel;
  if (cpu) {
    SceneVisibility vis;
    scene_rasterize_cpu(p, &vis, cfg.threads);
    scene_shade_cpu(p, vis, &res.lit, cfg.threads, [&](double f) {
      if (cfg.progress) cfg.progress("C fallback lit pass", f);
    });
    res.lit_ms = ms_since(t0);
    draw_of_pixel = vis.draw;
  } else {
    std::function<void(int, GLuint)> capture;
    if (cfg.on_draw) capture = [&](int di, GLuint prog) { cfg.on_draw(m.sgl->gl(), p.draws[di], prog); };
    if (!m.sgl->frame(&res.lit, err, &res.lit_ms, capture)) return false;
    if (cfg.check) {
      std::vector<float> slots;
      if (!m.sgl->gbuffer(&draw_of_pixel, &slots, err)) return false;
      ImageF c;
      scene_shade_records(p, draw_of_pixel, slots, &c, cfg.threads);
      DiffStats st;
      diff_image(res.lit, c, &st);
      res.check_mismatched = st.mismatched_pixels;
      res.check_pixels = 0;
      for (int d : draw_of_pixel) res.check_pixels += d >= 0;
      res.check_max_ulp = st.max_ulp;
    }
  }

  // ---- HDR ------------------------------------------------------------------------------
  t0 = Clock::now();
  const size_t n = static_cast<size_t>(cfg.w) * cfg.h;
  if (!float_path) {
    res.tone_map_scale = s.hdr.tone_map_scale;
    if (s.hdr.auto_exposure)
      res.notes.push_back("auto exposure runs on the float path; the integer path uses the fixed tone-map scale");
    // Which pixels hold linear values the (sRGB) render target would encode: ps20 and world draws.
    bool mixed = false, any_linear = false;
    for (const PreparedDraw &d : p.draws) any_linear = any_linear || !d.display_encoded;
    for (const PreparedDraw &d : p.draws) mixed = mixed || (d.display_encoded && any_linear);
    if (mixed && draw_of_pixel.empty()) {
      std::vector<float> slots;
      if (!m.sgl->gbuffer(&draw_of_pixel, &slots, err)) return false;
    }
    res.display.resize(n * 4);
    for (size_t i = 0; i < n; ++i) {
      bool linear = any_linear;
      if (mixed) linear = draw_of_pixel[i] >= 0 && !p.draws[draw_of_pixel[i]].display_encoded;
      for (int c = 0; c < 3; ++c) {
        const float v = res.lit.rgba[i * 4 + c];
        res.display[i * 4 + c] = ts_unorm8_from_float(linear ? srgb_encode(v) : v);
      }
      res.display[i * 4 + 3] = 255;
    }
  } else {
    std::vector<float> hdr(n * 4);
    for (size_t i = 0; i < hdr.size(); ++i) hdr[i] = ts_quantize_half(res.lit.rgba[i]);
    HdrSettings hs;
    hs.tone_map_scale = s.hdr.tone_map_scale;
    hs.bloom_amount = s.hdr.bloom_amount;
    if (s.hdr.auto_exposure) {
      const StaticLuminance lum(hdr.data(), cfg.w, cfg.h);
      hs.tone_map_scale = static_cast<float>(
          run_static_exposure(lum, s.hdr.tone_map_scale, s.hdr.exposure_min, s.hdr.exposure_max, cfg.exposure_frames)
              .scale);
      res.auto_exposure = true;
    }
    res.tone_map_scale = hs.tone_map_scale;
    if (cpu) {
      HdrFrameC f;
      hdr_post_float_c(hdr, cfg.w, cfg.h, hs, &f, cfg.threads);
      res.display = std::move(f.display);
    } else {
      if (!m.pipe->post_float(hdr, hs, err) || !read_rgba8(m.renderer->gl(), m.pipe->display(), &res.display, err))
        return false;
    }
  }
  if (!m.luts.empty() && !m.colour_correct(&res, err)) return false;
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

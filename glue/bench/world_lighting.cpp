// tiershade bench: the world_lighting section of `tiershade bench` (docs/accuracy_cost.md):
// what each lightmap encoding costs in error (against the float32 lightmap) and time, and
// what each tier costs against sm3, measured in one run on the room scene (scene_world.h).
// Not a test: nothing here passes or fails.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>

#include "shaderlib/assembler.h"
#include "budget/budget.h"
#include "gl/context.h"
#include "shaderlib/variants.h"
#include "demo/room_render.h"
#include "base/image_diff.h"
#include "base/stats.h"
#include "base/srgb.h"

namespace {

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double srgb(double x) { return srgb_encode_clamped(x); }

struct Err {
  double max = 0, mean = 0, over1 = 0;  // 8-bit display codes; % of channels off by more than 1 code
};
// Display-code error of frame a against b (linear, 4 floats or doubles per pixel), wall pixels only.
template <class A, class B>
Err display_error(const WorldFrame &f, const A &a, const B &b) {
  Err e;
  long n = 0, off = 0;
  double sum = 0;
  for (size_t p = 0; p < f.probe.size(); ++p) {
    if (f.probe[p] < 0) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = 255 * std::fabs(srgb(a[p * 4 + c]) - srgb(b[p * 4 + c]));
      e.max = std::max(e.max, d);
      sum += d;
      off += d > 1.0;
      ++n;
    }
  }
  e.mean = n ? sum / n : 0;
  e.over1 = n ? 100.0 * off / n : 0;
  return e;
}

BudgetCounts slots_of(const Variant &v) {
  BudgetCounts c;
  Assembled fs;
  std::string err;
  if (!assemble(v.shader->fragment, Target::GLSL330, Stage::Fragment, variant_defines(v, InputMode::Production), &fs,
                &err) ||
      !budget_count_fragment(fs.text, &c, &err))
    fprintf(stderr, "bench world_lighting: slots of %s: %s\n", v.name().c_str(), err.c_str());
  return c;
}

// Median GL 3.3 (OSMesa) time of a frame (both probe passes), and the frame itself.
bool gl_time(const WorldFrame &f, const WorldBake &b, const WorldPass &p, Backend be, Api api, int runs, double *ms,
             ImageF *img, std::string *err) {
  auto ctx = GlContext::create(be, api, err);
  if (!ctx) return false;
  GlRenderer r(*ctx);
  WorldPass q = p;
  q.nearest_cube = api != Api::GL33;
  WorldGl g;
  if (!world_gl_setup(r, api, f, b, q, &g, err)) return false;
  double t = 0;
  bool ok = world_gl_draw(r, g, f, img, err, &t);  // first frame: LLVM JIT of each pass, not timed
  std::vector<double> v;
  for (int i = 0; ok && i < runs; ++i) {
    ok = world_gl_draw(r, g, f, img, err, &t);
    v.push_back(t);
  }
  world_gl_release(r, &g);
  *ms = median(v);
  return ok;
}

struct EncRow {
  EncRow(const char *l, int e, const char *s) : label(l), encoding(e), stores(s) {}
  const char *label;
  int encoding;  // -1 float32
  const char *stores;
  double page_max = 0, page_mean = 0, clipped = 0;
  Err frame;
  double gl_ms = 0;
  BudgetCounts ps20, ps2b;
};

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  Selection sel;
  if (!load_shader_decls(&sel.decls, err)) return false;
  const WorldScene scene = default_world_scene();
  WorldBake bake;
  if (!bake_world(scene, &bake, err)) return false;
  WorldFrame frame;
  const int W = opt.size, H = std::max(8, opt.size / 2);
  if (!world_frame(scene, bake, W, H, &frame, err)) return false;
  auto variant = [&](const std::string &name, Variant *v) {
    return find_variant(sel.decls, "world_lighting", name, v, err);
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());

  // ---- encodings: page error, frame error (sm3, C twin = llvmpipe bits), time ----
  std::vector<EncRow> enc = {
      {"float32", -1, "32-bit float per channel (the reference)"},
      {"fp16", WL_LM_FLOAT, "half float (RGBA16F, filterable where half floats are)"},
      {"4.12", WL_LM_412, "16-bit unorm of radiance / 16, range [0, 16)"},
      {"LDR", WL_LM_LDR, "8-bit, 0.5 radiance^(1/2.2), range [0, 4.59]"},
      {"RGBE", WL_LM_RGBE, "ColorRGBExp32 (8-bit mantissas, shared exponent), NEAREST"},
  };
  const TextureDesc page32 = encode_page(scene, bake, -1);
  Variant sm3_float;
  if (!variant("sm3:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1", &sm3_float)) return false;
  ImageF ref32;
  world_render_cpu(frame, bake, WorldPass{&sm3_float, &page32, false, false}, &ref32);
  for (EncRow &r : enc) {
    const int e = r.encoding < 0 ? 0 : r.encoding;
    const TextureDesc page = r.encoding < 0 ? page32 : encode_page(scene, bake, r.encoding);
    // Page: every luxel of every lightmap of every face (borders excluded).
    const double range = r.encoding == WL_LM_412 ? 16.0 : r.encoding == WL_LM_LDR ? std::pow(2.0, 2.2) : 1e300;
    double sum = 0;
    long n = 0, clipped = 0;
    for (size_t f = 0; f < bake.place.size(); ++f) {
      const lm_face_place &pl = bake.place[f];
      for (int k = 0; k < pl.count; ++k)
        for (int j = 0; j < pl.block_h - 2; ++j)
          for (int i = 0; i < pl.block_w - 2; ++i) {
            int tx, ty;
            lm_page_texel(&pl, k, i, j, &tx, &ty);
            const size_t o = (static_cast<size_t>(ty) * scene.page_w + tx) * 4;
            double dec[3];
            decode_texel(r.encoding, &page.rgba[o], dec);
            for (int c = 0; c < 3; ++c) {
              const double v = bake.page[o + c];
              if (v > range) ++clipped;
              if (v < 1e-3) continue;  // relative error of the (near-)black channels is meaningless
              const double rel = std::fabs(dec[c] - v) / v;
              r.page_max = std::max(r.page_max, rel);
              sum += rel;
              ++n;
            }
          }
    }
    r.page_mean = n ? sum / n : 0;
    r.clipped = n ? 100.0 * clipped / n : 0;
    Variant v;
    const std::string tail = ",LIGHTMAP_ENCODING=" + std::to_string(e) + ",ENVMAP=1,ENVMAPMASK=1";
    if (!variant("sm3:BUMPMAP=1" + tail, &v)) return false;
    ImageF img;
    world_render_cpu(frame, bake, WorldPass{&v, &page, false, false}, &img);
    r.frame = display_error(frame, img.rgba, ref32.rgba);
    ImageF gl;
    if (!gl_time(frame, bake, WorldPass{&v, &page, false, false}, Backend::OSMesa, Api::GL33, opt.runs, &r.gl_ms, &gl,
                 err))
      return false;
    Variant v20, v2b;
    if (!variant("ps20:BUMPMAP=1" + tail, &v20) || !variant("ps2b:BUMPMAP=1" + tail, &v2b)) return false;
    r.ps20 = slots_of(v20);
    r.ps2b = slots_of(v2b);
    fprintf(stderr, "bench world_lighting: %-8s page max %.2e, frame err max %.2f, %.2f ms\n", r.label, r.page_max,
            r.frame.max, r.gl_ms);
  }

  // ---- tiers: the same scene and encoding (fp16) in ps20, ps2b, sm3 ----
  struct TierRow {
    TierRow(const char *l, const char *v, const char *w) : label(l), variant(v), what(w) {}
    const char *label, *variant, *what;
    BudgetCounts slots;
    double gl_ms = 0, gles_ms = 0, c_ms = 0;
    Err vs_sm3, vs_ref;
    long gl_vs_c = -1;
  };
  std::vector<TierRow> tiers = {
      {"ps20", "ps20:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1",
       "no pixel fog; N.V with one shared inversesqrt"},
      {"ps2b", "ps2b:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1", "everything, straight-line code"},
      {"sm3", "sm3:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1",
       "everything; contrast/saturation/Fresnel behind a uniform branch"},
      {"ps20 LDR", "ps20:BUMPMAP=1,LIGHTMAP_ENCODING=2,ENVMAP=1,ENVMAPMASK=1",
       "LDR lightmaps decoded as (2t)^2 instead of (2t)^2.2 (against sm3 LDR)"},
  };
  const TextureDesc page16 = encode_page(scene, bake, WL_LM_FLOAT), page_ldr = encode_page(scene, bake, WL_LM_LDR);
  std::vector<double> dref;
  world_render_double(frame, bake, WorldPass{&sm3_float, &page32, false, false}, &dref);
  ImageF sm3_img, sm3_ldr_img;
  Variant sm3_ldr;
  if (!variant("sm3:BUMPMAP=1,LIGHTMAP_ENCODING=2,ENVMAP=1,ENVMAPMASK=1", &sm3_ldr)) return false;
  world_render_cpu(frame, bake, WorldPass{&sm3_float, &page16, false, false}, &sm3_img);
  world_render_cpu(frame, bake, WorldPass{&sm3_ldr, &page_ldr, false, false}, &sm3_ldr_img);
  for (TierRow &t : tiers) {
    Variant v;
    if (!variant(t.variant, &v)) return false;
    const bool ldr = v.value("LIGHTMAP_ENCODING") == WL_LM_LDR;
    const WorldPass pass{&v, ldr ? &page_ldr : &page16, false, false};
    t.slots = slots_of(v);
    ImageF gl, gles, cpu;
    if (!gl_time(frame, bake, pass, Backend::OSMesa, Api::GL33, opt.runs, &t.gl_ms, &gl, err) ||
        !gl_time(frame, bake, pass, Backend::EGL, Api::GLES3, opt.runs, &t.gles_ms, &gles, err))
      return false;
    std::vector<double> ct;
    for (int i = 0; i < std::max(1, opt.runs / 2); ++i) {
      const double t0 = now_ms();
      world_render_cpu(frame, bake, pass, &cpu, static_cast<int>(cores));
      ct.push_back(now_ms() - t0);
    }
    t.c_ms = median(ct);
    t.gl_vs_c = 0;
    for (size_t i = 0; i < cpu.rgba.size(); ++i) t.gl_vs_c += ulp_distance(cpu.rgba[i], gl.rgba[i]) != 0;
    t.vs_sm3 = display_error(frame, cpu.rgba, ldr ? sm3_ldr_img.rgba : sm3_img.rgba);
    t.vs_ref = display_error(frame, cpu.rgba, dref);
    fprintf(stderr, "bench world_lighting: %-8s %.2f ms, vs sm3 max %.2f\n", t.label, t.gl_ms, t.vs_sm3.max);
  }
  // The share of ps20's error that is the missing fog: sm3 with the fog's density at 0.
  WorldFrame nofog = frame;
  nofog.in.shared[WL_SLOT_FOG_COLOR].w = 0.f;
  ImageF sm3_nofog, ps20_img;
  world_render_cpu(nofog, bake, WorldPass{&sm3_float, &page16, false, false}, &sm3_nofog);
  Variant ps20v;
  if (!variant(tiers[0].variant, &ps20v)) return false;
  world_render_cpu(frame, bake, WorldPass{&ps20v, &page16, false, false}, &ps20_img);
  const Err fog_share = display_error(frame, sm3_nofog.rgba, sm3_img.rgba);
  const Err rest = display_error(frame, ps20_img.rgba, sm3_nofog.rgba);

  std::ostringstream o;
  char b[1024];
  o << "## world_lighting (lightmaps, RNM, cube-map specular), " << W << "x" << H << " frame of the room\n\n"
    << "Scene: `glue/demo/room_scene.cpp`, five tiled walls with normal maps, three coloured point lights baked into\n"
    << "RNM lightmaps (`c_ref/offline/rnm_bake.c`) on a " << scene.page_w << "x" << scene.page_h
    << " page, two cube-map probes rendered from the room. Errors are in\n"
    << "8-bit display codes (sRGB-encoded, x255) over the wall pixels; times are llvmpipe medians of " << opt.runs
    << " frames\n(both probe passes, glFinish included).\n\n"
    << "### Lightmap encodings\n\n"
    << "Each encoding stores the baked float32 page as the run-time format would (quantised on the CPU,\n"
    << "uploaded as RGBA32F holding exactly the stored values; docs/world_lighting.md). **page error**: relative\n"
    << "error of the decoded luxels against float32 (channels >= 1e-3), **clipped**: share of channels beyond the\n"
    << "format's range. **frame error**: the sm3 shading (bumped, envmap, mask texture) with that encoding against\n"
    << "the same shading from the float32 page, both computed by the C twin, which is bit-exact with llvmpipe.\n"
    << "**decode slots**: ps20 / ps2b alu+tex of the bumped envmap variant (the float row = no decode).\n\n"
    << "| encoding | stores | page error max | page error mean | clipped | frame error max | frame error mean | >1 "
       "code | llvmpipe ms (GL 3.3) | slots ps20 | slots ps2b |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const EncRow &r : enc) {
    snprintf(b, sizeof b, "| %s | %s | %.2e | %.2e | %.2f%% | %.2f | %.3f | %.2f%% | %.2f | %d+%d | %d+%d |\n", r.label,
             r.stores, r.page_max, r.page_mean, r.clipped, r.frame.max, r.frame.mean, r.frame.over1, r.gl_ms,
             r.ps20.alu, r.ps20.tex, r.ps2b.alu, r.ps2b.tex);
    o << b;
  }
  o << "\n### Tiers\n\n"
    << "The same frame (fp16 lightmaps, bumped, envmap with a mask texture) in each tier. **vs sm3**: against\n"
    << "the sm3 frame; **vs reference**: against sm3 in double precision from the float32 page. **GL = C**:\n"
    << "channels where llvmpipe (GL 3.3) and the C twin differ.\n\n"
    << "| tier | what it does | slots alu+tex | llvmpipe ms (GL 3.3) | llvmpipe ms (GLES 3.0) | C ms (" << cores
    << " thr) | vs sm3 max | vs sm3 mean | vs reference max | vs reference mean | GL = C |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const TierRow &t : tiers) {
    snprintf(b, sizeof b, "| %s | %s | %d+%d | %.2f | %.2f | %.2f | %.2f | %.3f | %.2f | %.3f | %ld |\n", t.label,
             t.what, t.slots.alu, t.slots.tex, t.gl_ms, t.gles_ms, t.c_ms, t.vs_sm3.max, t.vs_sm3.mean, t.vs_ref.max,
             t.vs_ref.mean, t.gl_vs_c);
    o << b;
  }
  snprintf(
      b, sizeof b,
      "\nWhere ps20's difference from sm3 comes from: the pixel fog it drops accounts for a max of %.2f codes\n"
      "(mean %.3f; sm3 with and without fog); the rest, N.V from one shared inversesqrt instead of two\n"
      "normalisations, is rounding only: ps20 against sm3 without fog differs by a max of %.2f codes (mean %.4f).\n",
      fog_share.max, fog_share.mean, rest.max, rest.mean);
  o << b;
  *md = o.str();
  return true;
}

const BenchSection kSection = {"world_lighting", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

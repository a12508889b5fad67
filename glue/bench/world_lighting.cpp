// tiershade bench: the world_lighting section of `tiershade bench` (docs/accuracy_cost.md):
// what each lightmap encoding costs in error (against the float32 lightmap) and time, and what
// each tier costs against sm3, measured in one run on the lightmapped room
// (scenes/world_lighting.gltf) as the scene renderer draws it (glue/scene/frame.h).
// Not a test: nothing here passes or fails.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>

#include "base/image_diff.h"
#include "base/srgb.h"
#include "base/stats.h"
#include "bake/world_bake.h"
#include "budget/budget.h"
#include "demo/scene_files.h"
#include "scene/deferred.h"
#include "scene/frame.h"
#include "scene/reference.h"
#include "shaderlib/assembler.h"

namespace {

struct Err {
  double max = 0, mean = 0, over1 = 0;  // 8-bit display codes; % of channels off by more than 1 code
};
// Display-code error of frame a against b (linear rgb: `sa` / `sb` values per pixel), over the
// pixels a draw covers.
template <class A, class B>
Err display_error(const std::vector<int> &draw, const A &a, int sa, const B &b, int sb) {
  Err e;
  long n = 0, off = 0;
  double sum = 0;
  for (size_t p = 0; p < draw.size(); ++p) {
    if (draw[p] < 0) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = 255 * std::fabs(srgb_encode_clamped(a[p * sa + c]) - srgb_encode_clamped(b[p * sb + c]));
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

// The most expensive variant (alu + tex) the scene selects at `tier`.
BudgetCounts scene_slots(const SceneSelection &sel) {
  BudgetCounts best;
  for (const Variant &v : sel.variants) {
    const BudgetCounts c = slots_of(v);
    if (c.alu + c.tex > best.alu + best.tex) best = c;
  }
  return best;
}

// The room with its lightmap encoding set, and with or without its alpha envmap masks (normal-map
// alpha, inverted base alpha). The variants cross the lightmap encodings with no mask or a mask
// texture only (world_lighting.variants), so a non-float encoding drops those masks
// (glue/scene/selection.cpp); without them every encoding runs the same variants but for
// LIGHTMAP_ENCODING, and the difference is the encoding's alone.
Scene room_as(const Scene &s, const char *encoding, bool alpha_masks = true) {
  Scene o = s;
  o.lightmaps.encoding = encoding;
  for (SceneMaterial &m : o.materials)
    if (!alpha_masks && (m.envmap_mask == SceneEnvMask::NormalAlpha || m.envmap_mask == SceneEnvMask::InvBaseAlpha))
      m.envmap_mask = SceneEnvMask::None;
  return o;
}

// The sm3 double reference of `s` (float32 page) on the C renderer's G-buffer; *draw: the pixels'
// draws (-1: background).
bool reference(const Scene &s, int w, int h, std::vector<int> *draw, std::vector<double> *rgb, std::string *err) {
  SceneGBufferCpu g;
  if (!scene_gbuffer_cpu(s, Tier::SM3, w, h, false, &g, err) ||
      !scene_reference_linear(s, g.p, g.draw, g.slots, rgb, err))
    return false;
  *draw = g.draw;
  return true;
}

// The lit pass of the scene at `tier` on `be`/`api` (Backend::CPU: the C fallback), the median of
// `runs` frames' lit-pass times after a first frame (LLVM JIT on llvmpipe), and with `check` the
// channels where GL differs from the C twins on GL's G-buffer.
bool timed_frame(const Scene &s, Tier tier, Backend be, Api api, int w, int h, int runs, bool check, double *ms,
                 SceneRenderResult *res, std::string *err) {
  SceneSelection sel;
  if (!select_scene_variants(s, tier, "", &sel, err)) return false;
  SceneRenderConfig cfg;
  cfg.backend = be;
  cfg.api = api;
  cfg.w = w;
  cfg.h = h;
  cfg.check = check;
  SceneRenderer r;
  if (!r.init(s, sel, cfg, err) || !r.frame(res, err)) return false;
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    SceneRenderResult again;
    if (!r.frame(&again, err)) return false;
    t.push_back(again.lit_ms);
  }
  *ms = t.empty() ? res->lit_ms : median(t);
  return true;
}

struct EncRow {
  EncRow(const char *l, const char *e, int v, const char *s) : label(l), encoding(e), value(v), stores(s) {}
  const char *label, *encoding;
  int value;  // LIGHTMAP_ENCODING, -1 float32
  const char *stores;
  double page_max = 0, page_mean = 0, clipped = 0;
  Err frame;
  double gl_ms = 0;
  BudgetCounts ps20, ps2b;
};

// Relative error of every luxel of every lightmap of every face (borders excluded) of the page as
// the frame uploaded it, decoded, against the float32 page; and the share beyond the format's range.
void page_error(const PreparedScene &p, EncRow *r) {
  const PreparedDraw *wd = nullptr;
  for (const PreparedDraw &d : p.draws)
    if (d.world) wd = &d;
  if (!wd) return;
  const TextureDesc &page = p.texture(*wd, 2);
  const double range = r->value == WL_LM_412 ? 16.0 : r->value == WL_LM_LDR ? std::pow(2.0, 2.2) : 1e300;
  double sum = 0;
  long n = 0, clipped = 0;
  for (const lm_face_place &pl : p.lightmap_places)
    for (int k = 0; k < pl.count; ++k)
      for (int j = 0; j < pl.block_h - 2; ++j)
        for (int i = 0; i < pl.block_w - 2; ++i) {
          int tx, ty;
          lm_page_texel(&pl, k, i, j, &tx, &ty);
          const size_t o = (static_cast<size_t>(ty) * p.lightmap_w + tx) * 4;
          double dec[3];
          decode_texel(r->value, &page.rgba[o], dec);
          for (int c = 0; c < 3; ++c) {
            const double v = p.lightmap_page[o + c];
            if (v > range) ++clipped;
            if (v < 1e-3) continue;  // relative error of the (near-)black channels is meaningless
            const double rel = std::fabs(dec[c] - v) / v;
            r->page_max = std::max(r->page_max, rel);
            sum += rel;
            ++n;
          }
        }
  r->page_mean = n ? sum / n : 0;
  r->clipped = n ? 100.0 * clipped / n : 0;
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  std::vector<ShaderDecl> decls;
  if (!load_shader_decls(&decls, err)) return false;
  Scene room;
  if (!load_scene(kWorldLightingGltf, &room, err)) return false;
  const Scene unmasked = room_as(room, "rgbe", false);
  const int W = opt.size, H = std::max(8, opt.size / 2);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  auto variant = [&](const std::string &name, Variant *v) {
    return find_variant(decls, "world_lighting", name, v, err);
  };
  // Which pixels the room covers, and the sm3 references (double, float32 page) of the room and of
  // the room without alpha masks.
  std::vector<int> draw;
  std::vector<double> dref, dref_unmasked;
  // (The reference's own variants: the float encoding's, so that no mask is dropped.)
  if (!reference(room_as(room, "float"), W, H, &draw, &dref, err) ||
      !reference(room_as(unmasked, "float"), W, H, &draw, &dref_unmasked, err))
    return false;
  SceneGBufferCpu g;  // what the scene holds, for the text
  if (!scene_gbuffer_cpu(room, Tier::SM3, 8, 8, false, &g, err)) return false;
  auto c_frame = [&](const Scene &s, Tier tier, ImageF *img) {
    SceneRenderResult r;
    double ms;
    if (!timed_frame(s, tier, Backend::CPU, Api::GL33, W, H, 0, false, &ms, &r, err)) return false;
    *img = r.lit;
    return true;
  };

  // ---- encodings: page error, frame error (sm3, C twin = llvmpipe bits), time ----
  std::vector<EncRow> enc = {
      {"float32", "float32", -1, "32-bit float per channel (the reference)"},
      {"fp16", "float", WL_LM_FLOAT, "half float (RGBA16F, filterable where half floats are)"},
      {"4.12", "412", WL_LM_412, "16-bit unorm of radiance / 16, range [0, 16)"},
      {"LDR", "ldr", WL_LM_LDR, "8-bit, 0.5 radiance^(1/2.2), range [0, 4.59]"},
      {"RGBE", "rgbe_shader", WL_LM_RGBE, "ColorRGBExp32 (8-bit mantissas, shared exponent), decoded in the shader, NEAREST"},
      {"RGBE->fp16", "rgbe", WL_LM_FLOAT, "ColorRGBExp32 on disk, decoded at load to half float, LINEAR (Source's run time)"},
  };
  ImageF ref32;
  if (!c_frame(room_as(unmasked, "float32"), Tier::SM3, &ref32)) return false;
  for (EncRow &r : enc) {
    const Scene s = room_as(unmasked, r.encoding);
    SceneGBufferCpu ge;
    if (!scene_gbuffer_cpu(s, Tier::SM3, 8, 8, false, &ge, err)) return false;
    page_error(ge.p, &r);
    ImageF img;
    if (!c_frame(s, Tier::SM3, &img)) return false;
    r.frame = display_error(draw, img.rgba, 4, ref32.rgba, 4);
    SceneRenderResult gl;
    if (!timed_frame(s, Tier::SM3, Backend::OSMesa, Api::GL33, W, H, opt.runs, false, &r.gl_ms, &gl, err)) return false;
    const int e = r.value < 0 ? 0 : r.value;
    const std::string tail = ",LIGHTMAP_ENCODING=" + std::to_string(e) + ",ENVMAP=1,ENVMAPMASK=1";
    Variant v20, v2b;
    if (!variant("ps20:BUMPMAP=1" + tail, &v20) || !variant("ps2b:BUMPMAP=1" + tail, &v2b)) return false;
    r.ps20 = slots_of(v20);
    r.ps2b = slots_of(v2b);
    fprintf(stderr, "bench world_lighting: %-8s page max %.2e, frame err max %.2f, %.2f ms\n", r.label, r.page_max,
            r.frame.max, r.gl_ms);
  }

  // ---- tiers: the same scene and encoding (fp16) in ps20, ps2b, sm3 ----
  struct TierRow {
    TierRow(const char *l, Tier t, const char *e, const char *w) : label(l), tier(t), encoding(e), what(w) {}
    const char *label;
    Tier tier;
    const char *encoding, *what;
    BudgetCounts slots;
    int variants = 0;
    double gl_ms = 0, gles_ms = 0, c_ms = 0;
    Err vs_sm3, vs_ref;
    long gl_vs_c = -1;
  };
  std::vector<TierRow> tiers = {
      {"ps20", Tier::PS20, "float", "no pixel fog; N.V with one shared inversesqrt"},
      {"ps2b", Tier::PS2B, "float", "everything, straight-line code"},
      {"sm3", Tier::SM3, "float", "everything; contrast/saturation/Fresnel behind a uniform branch"},
      {"ps20 LDR", Tier::PS20, "ldr", "LDR lightmaps decoded as (2t)^2 instead of (2t)^2.2 (against sm3 LDR)"},
  };
  ImageF sm3_img, sm3_ldr_img;
  if (!c_frame(room_as(room, "float"), Tier::SM3, &sm3_img) ||
      !c_frame(room_as(unmasked, "ldr"), Tier::SM3, &sm3_ldr_img))
    return false;
  for (TierRow &t : tiers) {
    const bool ldr = std::string(t.encoding) == "ldr";
    const Scene s = room_as(ldr ? unmasked : room, t.encoding);
    SceneSelection sel;
    if (!select_scene_variants(s, t.tier, "", &sel, err)) return false;
    t.slots = scene_slots(sel);
    t.variants = static_cast<int>(sel.variants.size());
    SceneRenderResult gl, gles, cpu;
    if (!timed_frame(s, t.tier, Backend::OSMesa, Api::GL33, W, H, opt.runs, true, &t.gl_ms, &gl, err) ||
        !timed_frame(s, t.tier, Backend::EGL, Api::GLES3, W, H, opt.runs, false, &t.gles_ms, &gles, err) ||
        !timed_frame(s, t.tier, Backend::CPU, Api::GL33, W, H, std::max(1, opt.runs / 2), false, &t.c_ms, &cpu, err))
      return false;
    t.gl_vs_c = gl.check_mismatched;
    t.vs_sm3 = display_error(draw, cpu.lit.rgba, 4, ldr ? sm3_ldr_img.rgba : sm3_img.rgba, 4);
    t.vs_ref = display_error(draw, cpu.lit.rgba, 4, ldr ? dref_unmasked : dref, 3);
    fprintf(stderr, "bench world_lighting: %-8s %.2f ms, vs sm3 max %.2f\n", t.label, t.gl_ms, t.vs_sm3.max);
  }

  // The share of ps20's difference that is the pixel fog it drops: sm3 with and without the fog, and
  // ps20 against sm3 without it.
  Scene nofog = room_as(room, "float");
  nofog.fog.enabled = false;
  ImageF sm3_nofog, ps20_img;
  if (!c_frame(nofog, Tier::SM3, &sm3_nofog) || !c_frame(room_as(room, "float"), Tier::PS20, &ps20_img)) return false;
  const Err fog_share = display_error(draw, sm3_nofog.rgba, 4, sm3_img.rgba, 4);
  const Err rest = display_error(draw, ps20_img.rgba, 4, sm3_nofog.rgba, 4);

  std::ostringstream o;
  char b[1024];
  o << "## world_lighting (lightmaps, RNM, cube-map specular), " << W << "x" << H << " frame of the room\n\n"
    << "Scene: `" << kWorldLightingGltf << "` (docs/scenes.md), drawn by the scene renderer: " << g.p.draws.size()
    << " lightmapped draws (RNM, ssbump and flat walls,\nmasked envmaps, range fog), three point lights baked into RNM "
       "lightmaps "
    << "(`c_ref/offline/rnm_bake.c`) on a " << g.p.lightmap_w << "x" << g.p.lightmap_h
    << " page, two cube-map probes\nrendered from the room. Errors are in 8-bit display codes (sRGB-encoded, x255) "
       "over "
       "the pixels the room covers;\ntimes are llvmpipe medians of "
    << opt.runs << " lit passes (every draw, glFinish included).\n\n"
    << "### Lightmap encodings\n\n"
    << "The scene's `lightmaps.encoding` set to each format, the alpha envmap masks off in every row (the variants\n"
    << "cross the encodings with no mask or a mask texture only): the page is stored as the run-time format would "
       "(quantised "
       "on\nthe CPU, uploaded as RGBA32F holding exactly the stored values; docs/world_lighting.md). **page error**: "
       "relative\nerror of the decoded luxels against float32 (channels >= 1e-3), **clipped**: share of channels "
       "beyond "
       "the\nformat's range. **frame error**: the sm3 frame with that encoding against the sm3 frame from the float32 "
       "page\n(`\"float32\"`), both from the C fallback, which is bit-exact with llvmpipe. **decode slots**: ps20 / "
       "ps2b "
       "alu+tex of\nthe bumped envmap variant with a mask texture (the float row = no decode).\n\n"
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
    << "The same frame (fp16 lightmaps) at each tier, every draw with the variant the selection derives for it.\n"
    << "**slots**: the most expensive of those variants. **vs sm3**: against the sm3 frame; **vs reference**: against\n"
    << "sm3 in double precision from the float32 page (glue/scene/reference.h); the LDR row, as the encodings,\n"
    << "without the alpha envmap masks, against sm3 LDR and the reference without them. **GL = C**: channels where "
       "llvmpipe\n"
    << "(GL 3.3) and the C twins on GL's G-buffer differ.\n\n"
    << "| tier | what it does | variants | slots alu+tex | llvmpipe ms (GL 3.3) | llvmpipe ms (GLES 3.0) | C ms ("
    << cores << " thr) | vs sm3 max | vs sm3 mean | vs reference max | vs reference mean | GL = C |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const TierRow &t : tiers) {
    snprintf(b, sizeof b, "| %s | %s | %d | %d+%d | %.2f | %.2f | %.2f | %.2f | %.3f | %.2f | %.3f | %ld |\n", t.label,
             t.what, t.variants, t.slots.alu, t.slots.tex, t.gl_ms, t.gles_ms, t.c_ms, t.vs_sm3.max, t.vs_sm3.mean,
             t.vs_ref.max, t.vs_ref.mean, t.gl_vs_c);
    o << b;
  }
  snprintf(
      b, sizeof b,
      "\nWhere ps20's difference from sm3 comes from: the scene's range fog, which ps20 drops, accounts for a max "
      "of %.2f\ncodes (mean %.3f; sm3 with and without the fog); the rest, N.V from one shared inversesqrt instead "
      "of two\nnormalisations, is rounding only: ps20 against sm3 without fog differs by a max of %.2f codes "
      "(mean %.4f).\n",
      fog_share.max, fog_share.mean, rest.max, rest.mean);
  o << b;
  *md = o.str();
  return true;
}

const BenchSection kSection = {"world_lighting", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

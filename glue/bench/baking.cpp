// tiershade bench: the baking section of `tiershade bench` (docs/accuracy_cost.md): what each bake
// setting of the lightmapped room (scenes/world_lighting.gltf) costs in bake time and what it
// leaves as error against a converged bake (many samples, gather rays and bounces): relative
// irradiance of the flat luxels, and display codes of the frame the double reference shades from
// each page (glue/scene/reference.h: only the lightmaps differ between the frames). Bake times are
// medians of 3 bakes; the gather's rays per second per core come from the bounce passes' own time.
// Not a test: nothing here passes or fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>

#include "base/srgb.h"
#include "base/stats.h"
#include "demo/scene_files.h"
#include "scene/deferred.h"
#include "scene/reference.h"

namespace {

struct Setting {
  const char *label;
  int bounces, gather, supersample;
  double density;
  int seed = 0;  // the converged bake takes another seed: its noise is independent of the rows'
};

struct Bake {
  std::vector<float> page;
  std::vector<double> frame;  // the double reference's rgb, 3 per pixel
  std::vector<int> draw;
  double ms = 0, direct_ms = 0, bounce_ms = 0;
  long luxels = 0, rays = 0;
  int passes = 0;
  // The passes before the bounces (glue/bake/world_bake.h): shadow rays, sky, area lights.
  long direct_rays = 0, sky_rays = 0, area_rays = 0;
  double sky_ms = 0, area_ms = 0;
};

bool bake(const Scene &room, const Setting &st, int w, int h, int runs, Bake *out, std::string *err) {
  Scene s = room;
  s.lightmaps.bounces = st.bounces;
  s.lightmaps.gather_rays = st.gather;
  s.lightmaps.supersample = st.supersample;
  s.lightmaps.luxels_per_unit = st.density;
  if (st.density > 8) {  // the page grows with the luxels
    s.lightmaps.page_w = static_cast<int>(512 * st.density / 8);
    s.lightmaps.page_h = static_cast<int>(256 * st.density / 8);
  }
  s.lightmaps.encoding = "float32";
  s.lightmaps.seed = st.seed;
  std::vector<double> ms, direct, bounce;
  for (int r = 0; r < runs && (r == 0 || ms[0] < 3000); ++r) {  // a bake over 3 s: once
    SceneGBufferCpu g;
    if (!scene_gbuffer_cpu(s, Tier::SM3, w, h, false, &g, err)) return false;
    ms.push_back(g.p.bake_ms);
    direct.push_back(g.p.bake_direct_ms);
    bounce.push_back(g.p.bake_bounce_ms);
    if (r > 0) continue;
    if (!scene_reference_linear(s, g.p, g.draw, g.slots, &out->frame, err)) return false;
    out->page = g.p.lightmap_page;
    out->draw = g.draw;
    out->luxels = g.p.bake_luxels;
    out->rays = g.p.bake_gather_rays;
    out->passes = g.p.bake_passes;
    out->direct_rays = g.p.bake_direct_rays;
    out->sky_rays = g.p.bake_sky_rays;
    out->sky_ms = g.p.bake_sky_ms;
    out->area_rays = g.p.bake_area_rays;
    out->area_ms = g.p.bake_area_ms;
  }
  out->ms = median(ms);
  out->direct_ms = median(direct);
  out->bounce_ms = median(bounce);
  return true;
}

struct Err {
  double irr_max = -1, irr_mean = -1, code_max = 0, code_mean = 0;
};

Err error_of(const Bake &b, const Bake &ref, bool same_layout) {
  Err e;
  if (same_layout && b.page.size() == ref.page.size()) {
    double sum = 0, mx = 0;
    long n = 0;
    for (size_t i = 0; i < b.page.size(); ++i) {
      if (i % 4 == 3 || ref.page[i] < 1e-3) continue;  // alpha; (near-)black luxels
      const double rel = std::fabs(b.page[i] - ref.page[i]) / ref.page[i];
      mx = std::max(mx, rel);
      sum += rel;
      ++n;
    }
    e.irr_max = mx;
    e.irr_mean = n ? sum / n : 0;
  }
  double sum = 0;
  long n = 0;
  for (size_t p = 0; p < b.draw.size(); ++p) {
    if (b.draw[p] < 0) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = 255 * std::fabs(srgb_encode_clamped(b.frame[p * 3 + c]) - srgb_encode_clamped(ref.frame[p * 3 + c]));
      e.code_max = std::max(e.code_max, d);
      sum += d;
      ++n;
    }
  }
  e.code_mean = n ? sum / n : 0;
  return e;
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  Scene room;
  if (!load_scene(kWorldLightingGltf, &room, err)) return false;
  const int W = std::max(16, opt.size / 2), H = std::max(8, opt.size / 4);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const Setting kRef = {"converged", 16, 1024, 4, 8, 1};
  Bake ref;
  fprintf(stderr, "bench baking: the converged bake\n");
  if (!bake(room, kRef, W, H, 1, &ref, err)) return false;
  const Setting kRows[] = {
      {"direct only (shipped default)", 0, 64, 2, 8},
      {"1 bounce", 1, 64, 2, 8},
      {"2 bounces", 2, 64, 2, 8},
      {"4 bounces", 4, 64, 2, 8},
      {"16 bounces (to the threshold)", 16, 64, 2, 8},
      {"16 bounces, 16 gather rays", 16, 16, 2, 8},
      {"16 bounces, 256 gather rays", 16, 256, 2, 8},
      {"16 bounces, 1 direct sample", 16, 64, 1, 8},
      {"16 bounces, 4 x 4 direct samples", 16, 64, 4, 8},
      {"16 bounces, 4 luxels / unit", 16, 64, 2, 4},
      {"16 bounces, 16 luxels / unit", 16, 64, 2, 16},
  };
  std::ostringstream o;
  char b[640];
  o << "## baking (lightmaps of the room: shadows, bounces)\n\n"
    << "The room (`" << kWorldLightingGltf << "`) baked with each setting (docs/baking.md) against a converged bake ("
    << kRef.bounces << " bounces\nup to the 1e-3 threshold, " << kRef.gather << " gather rays per value, " << kRef.supersample
    << " x " << kRef.supersample << " direct samples, " << kRef.density << " luxels per unit; " << ref.luxels
    << " luxels, " << ref.passes << " passes, another seed than the rows', " << std::fixed;
  o.precision(1);
  o << ref.ms / 1000 << " s).\n"
    << "**irradiance**: relative error of the page's values against the converged page (channels >= 1e-3; same\n"
    << "density only). **frame**: display codes (sRGB x 255) of the sm3 frame shaded in double precision from each\n"
    << "page, over the room's " << W << "x" << H << " pixels. Times: bake medians of 3 (once for a bake over 3 s) on " << cores
    << " cores; Mrays/s per core: the bounce passes' gather rays\nover their own time.\n\n"
    << "| setting | luxels | passes | gather rays | bake ms | direct ms | bounce ms | Mrays/s/core | irradiance max | "
       "irradiance mean | frame max | frame mean |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  Bake shipped;  // the first row: the shipped default, whose passes the second table lists
  for (const Setting &st : kRows) {
    Bake bk;
    fprintf(stderr, "bench baking: %s\n", st.label);
    if (!bake(room, st, W, H, 3, &bk, err)) return false;
    if (&st == &kRows[0]) shipped = bk;
    const Err e = error_of(bk, ref, st.density == kRef.density);
    const double mrays = bk.bounce_ms > 0 ? bk.rays / (bk.bounce_ms * 1e3) / cores : 0;
    char irr[64];
    if (e.irr_max >= 0)
      snprintf(irr, sizeof irr, "%.2e | %.2e", e.irr_max, e.irr_mean);
    else
      snprintf(irr, sizeof irr, "- | -");
    snprintf(b, sizeof b, "| %s | %ld | %d | %.2fM | %.0f | %.0f | %.0f | %.2f | %s | %.2f | %.3f |\n", st.label, bk.luxels,
             bk.passes, bk.rays / 1e6, bk.ms, bk.direct_ms, bk.bounce_ms, mrays, irr, e.code_max, e.code_mean);
    o << b;
  }
  // The passes of the shipped default bake (the first run's times): rays, ms, Mrays/s per core.
  o << "\nThe passes of the shipped default bake (" << kRows[0].label << "; the first bake's times):\n\n"
    << "| pass | rays | ms | Mrays/s/core |\n|---|---|---|---|\n";
  const struct {
    const char *name;
    long rays;
    double ms;
  } passes[] = {{"direct light (shadow rays; the sun's jittered in its spread)", shipped.direct_rays, shipped.direct_ms},
                {"sky (glue/bake/sky.h)", shipped.sky_rays, shipped.sky_ms},
                {"area lights (glue/bake/area_lights.h)", shipped.area_rays, shipped.area_ms}};
  for (const auto &p : passes) {
    snprintf(b, sizeof b, "| %s | %.3fM | %.0f | %.2f |\n", p.name, p.rays / 1e6, p.ms,
             p.ms > 0 ? p.rays / (p.ms * 1e3) / cores : 0.0);
    o << b;
  }
  o << "\nThe shipped room bakes direct light only (`lightmaps.bounces` 0): `render` bakes it at load, and a\n"
       "committed bake directory would go stale with every edit of the scene (docs/baking.md, \"Not done yet\").\n";
  *md = o.str();
  return true;
}

const BenchSection kSection = {"baking", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

// tiershade bench: the baking section of `tiershade bench` (docs/accuracy_cost.md): what each bake
// quality preset (glue/bake/bake_quality.h) and each single setting of the lightmapped room
// (scenes/world_lighting.gltf) costs in bake time and what it leaves as error against a converged
// bake (many more samples, gather rays and bounces, another seed): the RMS of the lightmap values
// (every luxel of every block, rgb), their relative error, and display codes of the frame the
// double reference shades from each page (glue/scene/reference.h: only the lightmaps differ between
// the frames); Embree's share of the bake's CPU time; a plot of error against time
// (baking_accuracy_cost.svg). Bake times are medians of 3 bakes. Not a test: nothing here passes
// or fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>

#include "bake/bake_quality.h"
#include "bake/ray_scene.h"
#include "base/srgb.h"
#include "base/stats.h"
#include "demo/scene_files.h"
#include "io/atomic_file.h"
#include "offline/lightmap_page.h"
#include "scene/deferred.h"
#include "scene/reference.h"

namespace {

struct Setting {
  std::string label;
  BakeQuality q;
  int seed = 0;  // the converged bakes take other seeds: their noise is independent of the rows'
};

struct Bake {
  std::vector<float> page;
  std::vector<lm_face_place> places;
  int page_w = 0;
  std::vector<double> frame;  // the double reference's rgb, 3 per pixel
  std::vector<int> draw;
  double ms = 0, direct_ms = 0, bounce_ms = 0;
  double cpu_ms = 0, embree_ms = 0;  // the timed run (RayScene::set_timing): every thread's CPU time
  long luxels = 0, rays = 0;
  int passes = 0;
  // The passes before the bounces (glue/bake/world_bake.h): shadow rays, sky, area lights.
  long direct_rays = 0, sky_rays = 0, area_rays = 0;
  double sky_ms = 0, area_ms = 0;
  long all_rays() const { return direct_rays + sky_rays + area_rays + rays; }
};

// Bakes `runs` times (once only past 3 s unless `all_runs`), the first run's page and frame kept;
// with `share`, one more run with Embree's queries timed (the timing costs two clock reads a ray,
// so that run's time is not among the medians).
bool bake(const Scene &room, const Setting &st, int w, int h, int runs, bool all_runs, bool share, Bake *out,
          std::string *err) {
  Scene s = room;
  s.lightmaps.quality = st.q;
  const double density = st.q.luxels_per_unit;
  if (density > 8) {  // the page grows with the luxels
    s.lightmaps.page_w = static_cast<int>(512 * density / 8);
    s.lightmaps.page_h = static_cast<int>(256 * density / 8);
  }
  s.lightmaps.encoding = "float32";
  s.lightmaps.seed = st.seed;
  std::vector<double> ms, direct, bounce;
  for (int r = 0; r < runs + (share ? 1 : 0); ++r) {
    const bool timed = share && r == runs;
    if (!timed && r > 0 && !all_runs && ms[0] > 3000) continue;  // a bake over 3 s: once
    SceneGBufferCpu g;
    if (timed) RayScene::set_timing(true);
    const bool ok = scene_gbuffer_cpu(s, Tier::SM3, w, h, false, &g, err);
    if (timed) {
      out->embree_ms = RayScene::timed_ms();
      out->cpu_ms = g.p.bake_cpu_ms;
      RayScene::set_timing(false);
    }
    if (!ok) return false;
    if (timed) continue;
    ms.push_back(g.p.bake_ms);
    direct.push_back(g.p.bake_direct_ms);
    bounce.push_back(g.p.bake_bounce_ms);
    if (r > 0) continue;
    if (!scene_reference_linear(s, g.p, g.draw, g.slots, &out->frame, err)) return false;
    out->page = g.p.lightmap_page;
    out->places = g.p.lightmap_places;
    out->page_w = g.p.lightmap_w;
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
  double rms = -1, rel_rms = -1;  // the lightmap values' RMS error, and over the reference's RMS
};

// Calls f(texel index) for the rgb texels of every luxel of every block (borders excluded).
template <class F>
void each_luxel(const std::vector<lm_face_place> &places, int page_w, F f) {
  for (const lm_face_place &p : places)
    for (int k = 0; k < p.count; ++k)
      for (int j = 0; j < p.block_h - 2; ++j)
        for (int i = 0; i < p.block_w - 2; ++i) {
          int tx, ty;
          lm_page_texel(&p, k, i, j, &tx, &ty);
          f((static_cast<size_t>(ty) * page_w + tx) * 4);
        }
}

Err error_of(const Bake &b, const Bake &ref) {
  Err e;
  const bool same_layout = b.page_w == ref.page_w && b.page.size() == ref.page.size() &&
      b.places.size() == ref.places.size() &&
      std::equal(b.places.begin(), b.places.end(), ref.places.begin(), [](const lm_face_place &x, const lm_face_place &y) {
        return x.x == y.x && x.y == y.y && x.block_w == y.block_w && x.block_h == y.block_h && x.count == y.count;
      });
  if (same_layout) {
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
    double d2 = 0, r2 = 0;
    long m = 0;
    each_luxel(ref.places, ref.page_w, [&](size_t t) {
      for (int c = 0; c < 3; ++c) {
        const double d = static_cast<double>(b.page[t + c]) - ref.page[t + c];
        d2 += d * d;
        r2 += static_cast<double>(ref.page[t + c]) * ref.page[t + c];
        ++m;
      }
    });
    e.rms = m ? std::sqrt(d2 / m) : 0;
    e.rel_rms = r2 > 0 ? std::sqrt(d2 / r2) : 0;
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

}  // namespace

namespace {

struct Point {
  std::string label;
  double s, err;  // bake seconds, relative RMS
  bool preset;
};

// Relative RMS error against bake time (log10 axis: the times span two decades): the presets in
// blue, the single settings in grey.
std::string plot(const std::vector<Point> &pts) {
  const int W = 640, H = 360, L = 64, R = 20, T = 20, B = 44;
  double tmin = 1e30, tmax = 0, emax = 0;
  for (const Point &p : pts) {
    tmin = std::min(tmin, p.s);
    tmax = std::max(tmax, p.s);
    emax = std::max(emax, p.err);
  }
  const double d0 = std::floor(std::log10(std::max(1e-3, tmin))), d1 = std::max(d0 + 1, std::ceil(std::log10(std::max(1e-3, tmax))));
  emax = emax > 0 ? emax * 1.15 : 1;
  auto X = [&](double s) { return L + (W - L - R) * (std::log10(std::max(1e-3, s)) - d0) / (d1 - d0); };
  auto Y = [&](double e) { return (H - B) - (H - B - T) * e / emax; };
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
      << "' font-family='sans-serif' font-size='11'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << "<line x1='" << L << "' y1='" << H - B << "' x2='" << W - R << "' y2='" << H - B << "' stroke='black'/>\n"
      << "<line x1='" << L << "' y1='" << T << "' x2='" << L << "' y2='" << H - B << "' stroke='black'/>\n"
      << "<text x='" << (L + W - R) / 2 << "' y='" << H - 8
      << "' text-anchor='middle'>bake seconds (median of 3, log scale)</text>\n<text x='14' y='" << H / 2
      << "' transform='rotate(-90 14 " << H / 2 << ")' text-anchor='middle'>lightmap RMS error / RMS of the converged bake</text>\n";
  char b[400];
  for (double d = d0; d <= d1; d += 1) {
    snprintf(b, sizeof b, "<text x='%.1f' y='%d' text-anchor='middle'>%g</text>\n", X(std::pow(10.0, d)), H - B + 15,
             std::pow(10.0, d));
    svg << b;
  }
  for (int i = 0; i <= 4; ++i) {
    snprintf(b, sizeof b, "<text x='%d' y='%.1f' text-anchor='end'>%.3f</text>\n", L - 4, Y(emax * i / 4) + 4,
             emax * i / 4);
    svg << b;
  }
  for (const Point &p : pts) {
    snprintf(b, sizeof b, "<circle cx='%.1f' cy='%.1f' r='%d' fill='%s'/><text x='%.1f' y='%.1f'%s>%s</text>\n",
             X(p.s), Y(p.err), p.preset ? 6 : 3, p.preset ? "#3366cc" : "#999999", X(p.s) + 8, Y(p.err) - 5,
             p.preset ? " font-weight='bold'" : " fill='#666666'", p.label.c_str());
    svg << b;
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string values(const BakeQuality &q) {
  char b[200];
  snprintf(b, sizeof b, "%d x %d direct, sky %d, area %d, sun %d, %s%d gather (thr %g)", q.supersample, q.supersample,
           q.sky_samples, q.area_samples, q.spread_samples,
           q.bounces ? ("<= " + std::to_string(q.bounces) + " bounces, ").c_str() : "no bounces, ", q.gather_rays,
           q.threshold);
  return b;
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  Scene room;
  if (!load_scene(kWorldLightingGltf, &room, err)) return false;
  const int W = std::max(16, opt.size / 2), H = std::max(8, opt.size / 4);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const double density = room.lightmaps.quality.luxels_per_unit;
  // The converged bake: final's passes with 4 x (16 x for the direct samples) its samples and gather
  // rays, bounces to a tenth of final's threshold; twice, with two seeds, for its own noise.
  Setting kRef{"converged", BakeQuality(), 1};
  bake_quality_preset("final", &kRef.q);
  kRef.q.luxels_per_unit = density;
  kRef.q.supersample = 8;
  kRef.q.area_samples = 256;
  kRef.q.spread_samples = 400;
  kRef.q.sky_samples = 1024;
  kRef.q.gather_rays = 1024;
  kRef.q.threshold = 1e-5;
  Setting kRef2 = kRef;
  kRef2.seed = 2;
  Bake ref, ref2;
  fprintf(stderr, "bench baking: the converged bakes\n");
  if (!bake(room, kRef, W, H, 1, false, false, &ref, err) || !bake(room, kRef2, W, H, 1, false, false, &ref2, err))
    return false;
  const Err ref_noise = error_of(ref2, ref);
  std::vector<Point> pts;
  std::ostringstream o;
  char b[900];
  o << std::fixed;
  o.precision(1);
  o << "## baking (lightmaps of the room: quality presets, shadows, bounces)\n\n"
    << "The room (`" << kWorldLightingGltf << "`, " << ref.luxels << " luxels at " << density
    << " luxels per unit) baked at each quality preset (docs/baking.md, \"Quality\": the preset's own values at\n"
    << "the scene's luxel density; `tiershade bake --quality P` would also apply the scene's `sky.samples` key)\nand with single "
    << "settings changed, against a converged bake ("
    << kRef.q.supersample << " x " << kRef.q.supersample << " direct\nsamples, " << kRef.q.sky_samples << " sky rays, "
    << kRef.q.spread_samples << " sun rays per luxel, " << kRef.q.gather_rays << " gather rays per value, bounces to the "
    << std::defaultfloat << kRef.q.threshold << std::fixed << " threshold: " << ref.passes << " passes, " << ref.ms / 1000 << " s; another seed than the rows').\n"
    << "**lightmap RMS**: the RMS of the page's values (rgb of every luxel of every block: flat, b0, b1, b2)\nagainst the converged "
    << "page, and **/ ref** the same over the converged page's RMS. The converged bake's own noise\n(the RMS between it and a "
    << "bake of another seed, over sqrt 2): ";
  o.precision(4);
  o << ref_noise.rms / std::sqrt(2.0);
  o.precision(1);
  o << " (" << 100 * ref_noise.rel_rms / std::sqrt(2.0) << " % of its RMS). **frame**: display codes (sRGB x 255) of the sm3 frame\n"
    << "shaded in double precision from each page over the room's " << W << "x" << H << " pixels. Times: medians of 3 bakes "
    << "on " << cores << " cores\n(the machine shared with other work: ratios within one run are what to compare). **Embree**: "
    << "the CPU time inside\nEmbree's queries over the bake's CPU time (every thread's), from a fourth bake sampled every 1 ms "
    << "of CPU time\n(SIGPROF: other work on the machine counts in neither). **Mrays/s/core**: every ray of the bake over "
    << "its CPU seconds\n(the bounces trace their gather rays in their first pass and iterate over the kept hits after it: "
    << "docs/baking.md).\n\n"
    << "| preset | values | passes | rays | bake s | CPU s | Embree | Mrays/s/core | lightmap RMS | / ref | frame mean | frame max |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const char *name : {"draft", "default", "final"}) {
    Setting st{name, BakeQuality()};
    bake_quality_preset(name, &st.q);
    st.q.luxels_per_unit = density;
    Bake bk;
    fprintf(stderr, "bench baking: preset %s\n", name);
    if (!bake(room, st, W, H, 3, true, true, &bk, err)) return false;
    const Err e = error_of(bk, ref);
    snprintf(b, sizeof b, "| **%s** | %s | %d | %.2fM | %.2f | %.2f | %.0f %% | %.2f | %.4f | %.3f | %.2f | %.1f |\n", name,
             values(st.q).c_str(), bk.passes, bk.all_rays() / 1e6, bk.ms / 1000, bk.cpu_ms / 1000,
             bk.cpu_ms > 0 ? 100 * bk.embree_ms / bk.cpu_ms : 0.0, bk.cpu_ms > 0 ? bk.all_rays() / (bk.cpu_ms * 1e3) : 0.0,
             e.rms, e.rel_rms, e.code_mean, e.code_max);
    o << b;
    pts.push_back({name, bk.ms / 1000, e.rel_rms, true});
  }
  // Bake time against luxel count: the default preset at 1x, 4x and 16x the scene's luxels (2x and
  // 4x its density), CPU time per luxel (the issue: linear in the luxels).
  o << "\nThe default preset at 1x, 4x and 16x the room's luxels (" << density << ", " << 2 * density << " and "
    << 4 * density << " luxels per unit; the page grows with them): bake and CPU time, and CPU time per luxel over the "
       "1x bake's\n(1.00: linear in the luxels).\n\n"
    << "| luxels | x | rays | bake s | CPU s | Embree | Mrays/s/core | CPU us per luxel | per luxel / 1x |\n"
    << "|---|---|---|---|---|---|---|---|---|\n";
  double per_luxel_1x = 0;
  for (int mult : {1, 2, 4}) {
    Setting st{"default", BakeQuality()};
    bake_quality_preset("default", &st.q);
    st.q.luxels_per_unit = density * mult;
    Bake bk;
    fprintf(stderr, "bench baking: default at %g luxels per unit\n", st.q.luxels_per_unit);
    if (!bake(room, st, W, H, 1, false, true, &bk, err)) return false;
    const double per = bk.luxels > 0 ? bk.cpu_ms * 1e3 / bk.luxels : 0;
    if (mult == 1) per_luxel_1x = per;
    snprintf(b, sizeof b, "| %ld | %d | %.2fM | %.2f | %.2f | %.0f %% | %.2f | %.1f | %.2f |\n", bk.luxels, mult * mult,
             bk.all_rays() / 1e6, bk.ms / 1000, bk.cpu_ms / 1000, bk.cpu_ms > 0 ? 100 * bk.embree_ms / bk.cpu_ms : 0.0,
             bk.cpu_ms > 0 ? bk.all_rays() / (bk.cpu_ms * 1e3) : 0.0, per, per_luxel_1x > 0 ? per / per_luxel_1x : 0.0);
    o << b;
  }
  auto row = [&](const char *label, int bounces, int gather, int ss, double dens) {
    Setting st{label, room.lightmaps.quality};  // the scene's own (what render bakes at load)
    st.q.bounces = bounces;
    st.q.gather_rays = gather;
    st.q.supersample = ss;
    st.q.luxels_per_unit = dens;
    return st;
  };
  const Setting kRows[] = {
      row("direct only (the scene at load)", 0, 64, 2, density),
      row("1 bounce", 1, 64, 2, density),
      row("2 bounces", 2, 64, 2, density),
      row("4 bounces", 4, 64, 2, density),
      row("16 bounces (to the threshold)", 16, 64, 2, density),
      row("16 bounces, 16 gather rays", 16, 16, 2, density),
      row("16 bounces, 256 gather rays", 16, 256, 2, density),
      row("16 bounces, 1 direct sample", 16, 64, 1, density),
      row("16 bounces, 4 x 4 direct samples", 16, 64, 4, density),
      row("16 bounces, 4 luxels / unit", 16, 64, 2, density / 2),
      row("16 bounces, 16 luxels / unit", 16, 64, 2, density * 2),
  };
  o << "\nSingle settings, from the scene's own (its `lightmaps` and `sky.samples` " << room.lightmaps.quality.sky_samples
    << " keys: what `render` bakes at load):\n**irradiance**: relative error of the page's values (channels >= 1e-3); the "
    << "RMS and irradiance columns need the\nconverged bake's density. Mrays/s per core: the bounce passes' traced gather rays "
    << "(the first pass's: the later passes read its hits back) over their own wall time; a bake over 3 s runs once.\n\n"
    << "| setting | luxels | passes | gather rays | bake ms | direct ms | bounce ms | Mrays/s/core | lightmap RMS | / ref | "
       "irradiance max | irradiance mean | frame max | frame mean |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  Bake shipped;  // the first row: the scene at load, whose passes the last table lists
  for (const Setting &st : kRows) {
    Bake bk;
    fprintf(stderr, "bench baking: %s\n", st.label.c_str());
    if (!bake(room, st, W, H, 3, false, false, &bk, err)) return false;
    if (&st == &kRows[0]) shipped = bk;
    const Err e = error_of(bk, ref);
    const double mrays = bk.bounce_ms > 0 ? bk.rays / (bk.bounce_ms * 1e3) / cores : 0;
    char irr[96];
    if (e.irr_max >= 0)
      snprintf(irr, sizeof irr, "%.4f | %.3f | %.2e | %.2e", e.rms, e.rel_rms, e.irr_max, e.irr_mean);
    else
      snprintf(irr, sizeof irr, "- | - | - | -");
    snprintf(b, sizeof b, "| %s | %ld | %d | %.2fM | %.0f | %.0f | %.0f | %.2f | %s | %.2f | %.3f |\n", st.label.c_str(),
             bk.luxels, bk.passes, bk.rays / 1e6, bk.ms, bk.direct_ms, bk.bounce_ms, mrays, irr, e.code_max, e.code_mean);
    o << b;
    if (e.rel_rms >= 0) pts.push_back({st.label, bk.ms / 1000, e.rel_rms, false});
  }
  // The passes of the scene's bake at load (the first run's times): rays, ms, Mrays/s per core.
  o << "\nThe passes of the scene's bake at load (" << kRows[0].label << "; the first bake's times):\n\n"
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
  o << "\n![lightmap error against bake time](baking_accuracy_cost.svg)\n\n"
    << "The shipped room renders from a bake at load (draft: direct light only), as `render` bakes it: a\n"
       "committed bake directory would go stale with every edit of the scene (docs/baking.md, \"Not done yet\").\n";
  if (!opt.plot_dir.empty() &&
      !write_file_atomic(opt.plot_dir + "/baking_accuracy_cost.svg", plot(pts), err))
    return false;
  *md = o.str();
  return true;
}

const BenchSection kSection = {"baking", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

// tiershade cli: `bake` subcommand: bakes a scene's LightmappedGeneric faces (glue/bake/) and writes
// the bake directory (glue/bake/bake_dir.h: page.exr + manifest.json, atomically, each finished pass
// checkpointed in DIR.partial so that a killed bake resumes), or, with -o PAGE.exr, the float32 page
// alone (for extras.tiershade.lightmaps.image). Prints what it baked and why, and what it saved
// against baking everything (docs/baking.md).
#include <cstdio>
#include <filesystem>
#include <algorithm>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/memory_estimate.h"
#include "base/image.h"
#include "io/exr.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"

// `tiershade bake --help`.
const char kHelp[] = R"(usage: tiershade bake SCENE.gltf -o DIR [--quality draft|default|final] [OVERRIDES] [--threads N]
                      [--max-memory MIB]
       tiershade bake SCENE.gltf -o PAGE.exr [the same options]
Bakes the scene's lightmaps (flat and three RNM lightmaps per LightmappedGeneric face: direct light
with shadows, the sky, emitters, then the bounces) and writes the bake directory DIR:
page.exr (RGBA float32, rows as GL texture rows) and manifest.json (the scene's content hash, the
faces' places, the settings, each pass's rays and time), and for a scene with models the irradiance
volume (volume.bin, docs/irradiance_volume.md). Each finished pass is saved in DIR.partial:
a bake that was killed resumes from it; DIR appears only when the bake is complete. Name DIR in the
scene's extras.tiershade.lightmaps.bake to render from it (a stale bake is refused). With a .exr
name, writes the page alone (for extras.tiershade.lightmaps.image). --max-memory MIB: what the
scene's files and the bake may take (default 1024; docs/reliability.md).
Quality (docs/baking.md, "Quality"): the preset (--quality P, else the scene's lightmaps.quality,
else default), then the scene's own keys (lightmaps.bounces, ..., sky.samples), then these options:
  --luxel-density X (0.01..1024)  --supersample N (1..8, N x N direct samples)
  --area-samples N (0..1024)      --spread-samples N (1..1024)   --sky-samples N (1..4096)
  --bounces N (0..100)            --gather-rays N (1..1024)      --threshold X (0..1)
Presets: draft (direct light only: what render bakes at load), default (+ up to 100 bounces to the
threshold 1e-3), final (4 x the samples, 256 gather rays, threshold 1e-4). The manifest records the
quality; a render of DIR takes it (and says so when the scene's differs). --threads N: the bake's
threads (0 = all cores, default); the same bytes for any N.)";

namespace fs = std::filesystem;

namespace {

std::string base_name(const std::string &p) {
  const size_t s = p.find_last_of('/');
  return s == std::string::npos ? p : p.substr(s + 1);
}

// What was baked and why, and the rays and time saved against baking everything (every face with
// four gathered values, every pass): the lines of the report and of the manifest's "baked".
std::vector<std::string> bake_report(const BakeSummary &s) {
  std::vector<std::string> r;
  int bumped = 0, flat = 0, black = 0;
  long flat_luxels = 0, black_luxels = 0;
  for (const BakeFace &f : s.faces) {
    const long n = static_cast<long>(f.luxels_w) * f.luxels_h;
    const bool is_black = f.face.reflectivity.x == 0 && f.face.reflectivity.y == 0 && f.face.reflectivity.z == 0;
    if (f.face.bumped) {
      ++bumped;
    } else {
      ++flat;
      flat_luxels += n;
    }
    if (is_black) {
      ++black;
      black_luxels += n;
    }
  }
  char b[400];
  snprintf(b, sizeof b, "%zu faces, %ld luxels on a %d x %d page (%.3g luxels per unit)", s.faces.size(), s.luxels,
           s.page_w, s.page_h, s.luxels_per_unit);
  r.push_back(b);
  snprintf(b, sizeof b,
           "%d faces with a normal map: 4 values each (flat, b0, b1, b2); %d without: the flat value gathered alone "
           "(%ld luxels; their shader reads the flat lightmap only)",
           bumped, flat, flat_luxels);
  r.push_back(b);
  snprintf(b, sizeof b, "direct: %d lights, %ld shadow rays (%d x %d samples per luxel)", s.lights, s.direct_rays,
           s.supersample, s.supersample);
  r.push_back(b);
  if (!s.sky)
    r.push_back("no sky in the scene: no sky rays");
  else if (s.resumed_after >= 0)
    r.push_back("sky: in the saved direct pass (resumed)");
  else {
    snprintf(b, sizeof b, "sky: %ld rays through the openings (%.0f ms)", s.sky_pass.rays, s.sky_pass.ms);
    r.push_back(b);
  }
  if (s.emitters == 0 && s.model_emitters == 0)
    r.push_back("no emissive face or model: no area-light rays");
  else if (s.area_samples == 0)
    r.push_back("emissive faces and models reach the luxels through the bounces alone (area lights off)");
  else if (s.resumed_after < 0) {
    snprintf(b, sizeof b, "%d emissive faces and %d emissive models as area lights: %ld shadow rays (%.0f ms)",
             s.emitters, s.model_emitters, s.area_pass.rays, s.area_pass.ms);
    r.push_back(b);
  }
  if (black)
    snprintf(b, sizeof b, "%d faces of reflectivity 0: no bounce rays (%ld luxels; they show black)", black,
             black_luxels);
  else
    snprintf(b, sizeof b, "no face of reflectivity 0: every face gathers its bounces");
  r.push_back(b);
  if (s.bounce.max_bounces == 0) {
    r.push_back("bounces 0: direct light only");
  } else {
    snprintf(b, sizeof b,
             "%d of at most %d bounces (stopped when a pass adds < %.3g of the light so far), %d gather "
             "rays per value",
             s.report.passes, s.bounce.max_bounces, s.bounce.threshold, s.bounce.gather_rays);
    r.push_back(b);
    if (s.report.cached > 0) {
      snprintf(b, sizeof b,
               "bounces: %ld gather rays traced in the first pass, their hits read back %ld times by the passes "
               "after it (the same rays every pass)",
               s.report.rays, s.report.cached);
      r.push_back(b);
    }
  }
  // Where the probes' cube maps come from (not stored here: made at load from this page).
  snprintf(b, sizeof b,
           "%d world probes: %d cube maps ray traced from the bake (probes[].source \"rays\" or an ambient "
           "sample's from_probe), %d rendered in-engine from it at load by the frame's renderer",
           s.probes, s.traced_cubes, s.probes - s.traced_cubes);
  r.push_back(b);
  // Baking everything: every luxel gathers 4 values of m rays in every pass (some fall behind the face
  // and are not traced: this is an upper bound of what the bake would trace).
  const int side = [&] {
    int k = 1;
    while (k * k < s.bounce.gather_rays) ++k;
    return k;
  }();
  const long m = static_cast<long>(side) * side;
  const long everything = s.luxels * 4 * m * s.report.passes;
  double ms = 0;
  for (double t : s.report.pass_ms) ms += t;
  if (s.report.passes > 0 && s.report.rays > 0) {
    const double saved = static_cast<double>(everything - s.report.rays);
    snprintf(b, sizeof b,
             "saved against baking everything (every face bumped and gathering, %ld rays): %.0f gather rays "
             "(%.0f%%), about %.0f ms at this bake's %.2f Mrays/s",
             everything, saved, 100.0 * saved / static_cast<double>(everything),
             ms > 0 ? saved * ms / static_cast<double>(s.report.rays) : 0.0, ms > 0 ? s.report.rays / ms / 1e3 : 0.0);
    r.push_back(b);
  }
  return r;
}

}  // namespace

int cmd_bake(int argc, char **argv) {
  Args a("bake", argc, argv, {"--help"},
         {"-o", "--max-memory", "--quality", "--luxel-density", "--supersample", "--area-samples", "--spread-samples",
          "--sky-samples", "--bounces", "--gather-rays", "--threshold", "--threads"});
  if (a.help(kHelp)) return 0;
  apply_max_memory(a);  // --max-memory MIB: what the scene's files may take (docs/reliability.md)
  // The quality (glue/bake/bake_quality.h): each option checked before anything is read; the
  // ranges are those of the scene's keys (glue/scene/gltf_extras.cpp).
  const std::string preset = a.get("--quality");
  BakeQuality q;
  if (a.has("--quality") && !bake_quality_preset(preset, &q))
    a.fail("--quality: '" + preset + "' is not a preset (" + bake_quality_preset_names() + ")");
  BakeQualityKeys opt;
  opt.luxels_per_unit = a.get_number("--luxel-density", -1, 0.01, 1024);
  opt.supersample = a.get_int("--supersample", -1, 1, 8);
  opt.area_samples = a.get_int("--area-samples", -1, 0, 1024);
  opt.spread_samples = a.get_int("--spread-samples", -1, 1, 1024);
  opt.sky_samples = a.get_int("--sky-samples", -1, 1, 4096);
  opt.bounces = a.get_int("--bounces", -1, 0, 100);
  opt.gather_rays = a.get_int("--gather-rays", -1, 1, 1024);
  opt.threshold = a.get_number("--threshold", -1, 0, 1);
  const int threads = a.get_int("--threads", 0, 0, 256);
  if (a.positional().size() != 1) a.fail("expected one scene file (tiershade bake SCENE.gltf -o DIR)");
  if (!a.has("-o")) a.fail("-o DIR is required (the bake directory; or -o PAGE.exr for the page alone)");
  const std::string out = a.get("-o");
  const bool page_only = out.size() > 4 && out.compare(out.size() - 4, 4, ".exr") == 0;
  if (out.empty()) a.fail("-o: empty name");
  if (!page_only) {  // refused before the bake, not after it: DIR is absent or a previous bake directory
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(out, ec);
    if (fs::exists(st) && (!fs::is_directory(st) || !fs::is_regular_file(fs::path(out) / "manifest.json", ec))) {
      fprintf(stderr,
              "tiershade bake: %s: exists and is not a previous bake directory (no manifest.json); refusing to "
              "replace it\n",
              out.c_str());
      return 1;
    }
  }
  Scene scene;
  std::string err;
  if (!load_scene(a.positional()[0], &scene, &err)) {
    fprintf(stderr, "tiershade bake: %s\n", err.c_str());
    return 1;
  }
  if (!scene.lightmaps.image.empty() || !scene.lightmaps.bake.empty()) {  // bake from the lights all the same
    printf("note: %s reads its page from %s; this bakes the page from the scene's lights\n", scene.path.c_str(),
           scene.lightmaps.image.empty() ? scene.lightmaps.bake.c_str() : scene.lightmaps.image.c_str());
    scene.lightmaps.image.clear();
    scene.lightmaps.image_rgba.clear();
    scene.lightmaps.bake.clear();
  }
  // The preset (--quality, else the scene's, else default), the scene's own keys, the options.
  const std::string base = a.has("--quality")                  ? preset
                           : scene.lightmaps.quality_preset.empty() ? std::string("default")
                                                                    : scene.lightmaps.quality_preset;
  bake_quality_preset(base, &q);
  scene.lightmaps.quality = bake_quality_with(bake_quality_with(q, scene.lightmaps.keys), opt);
  scene.lightmaps.threads = threads;
  printf("quality: %s\n", bake_quality_text(scene.lightmaps.quality).c_str());
  if (!scene.lightmaps.keys.names().empty())
    printf("note: the scene's keys %s override the preset %s (the command line's options override both)\n",
           scene.lightmaps.keys.names().c_str(), base.c_str());
  if (!page_only) scene.lightmaps.bake_checkpoint = out;
  scene.lightmaps.bake_progress = true;
  if (!render_fits_memory(scene, 1, 1, false, false, &err)) {  // the page's bake, checked before it starts
    fprintf(stderr, "tiershade bake: %s: %s\n", scene.path.c_str(), err.c_str());
    return 1;
  }
  SceneSelection sel;
  PreparedScene ps;
  // The page does not depend on the tier or the frame size: faces, density and page size only.
  if (!select_scene_variants(scene, Tier::SM3, "", &sel, &err) ||
      !prepare_scene(scene, sel, 16, 16, Api::GL33, 1.f, &ps, &err)) {
    fprintf(stderr, "tiershade bake: %s: %s\n", scene.path.c_str(), err.c_str());
    return 1;
  }
  if (ps.lightmap_page.empty()) {
    fprintf(stderr, "tiershade bake: %s: no LightmappedGeneric primitive: the scene has no lightmap page\n",
            scene.path.c_str());
    return 1;
  }
  const BakeSummary &sum = ps.bake_summary;
  if (!sum.resume_note.empty()) printf("note: %s\n", sum.resume_note.c_str());
  if (sum.resumed_after >= 0)
    printf("resumed after pass %d (%s) from %s: the finished passes were not baked again\n", sum.resumed_after,
           sum.resumed_after == 0 ? "direct" : ("bounce " + std::to_string(sum.resumed_after)).c_str(),
           bake_checkpoint_dir(out).c_str());
  const std::vector<std::string> why = bake_report(sum);
  if (page_only) {
    ImageF img;
    img.w = ps.lightmap_w;
    img.h = ps.lightmap_h;
    img.rgba = ps.lightmap_page;
    if (!write_exr(out, img, &err)) {
      fprintf(stderr, "tiershade bake: %s\n", err.c_str());
      return 1;
    }
  } else if (!write_bake_dir(out, base_name(scene.path), sum, ps.lightmap_page, why, &err, &ps.volume)) {
    fprintf(stderr, "tiershade bake: %s\n", err.c_str());
    return 1;
  }
  for (const std::string &l : why) printf("baked: %s\n", l.c_str());
  if (!ps.volume.cube.empty()) {
    int valid = 0;
    for (uint8_t x : ps.volume.valid) valid += x;
    const long all = static_cast<long>(ps.volume.cube.size());
    printf("baked: irradiance volume of %d x %d x %d samples (%d valid), %ld rays, %.1f ms%s\n", ps.volume.n[0],
           ps.volume.n[1], ps.volume.n[2], valid, ps.volume.rays, ps.volume.bake_ms,
           page_only ? " (not written: -o PAGE.exr writes the page alone)" : ", written as volume.bin");
    if (ps.volume.baked < all)  // only where models can be (nodes' extras.tiershade.reach)
      printf("baked: volume samples only where models can be: %ld of %ld (%ld rays saved)\n", ps.volume.baked, all,
             (all - ps.volume.baked) * static_cast<long>(volume_ray_directions().size()));
  }
  printf("direct: %ld shadow rays, %.1f ms\n", sum.direct_rays, sum.direct_ms);
  for (size_t k = 0; k < sum.report.pass_rays.size(); ++k)
    printf("bounce %zu: %ld gather rays, %.1f ms%s\n", k + 1, sum.report.pass_rays[k],
           k < sum.report.pass_ms.size() ? sum.report.pass_ms[k] : 0.0,
           static_cast<int>(k) + 1 <= sum.resumed_after ? " (from the checkpoint)" : "");
  printf("wrote %s: %d x %d lightmap page%s%s, %.1f ms to bake\n", out.c_str(), ps.lightmap_w,
         ps.lightmap_h / std::max(1, ps.lightmap_pages),
         ps.lightmap_pages > 1 ? (" x " + std::to_string(ps.lightmap_pages) + " (stacked)").c_str() : "",
         page_only ? "" : " and manifest.json", ps.bake_ms);
  return 0;
}

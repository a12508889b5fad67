// tiershade cli: `demo` subcommand: the lit sphere grid (scenes/sphere_grid.gltf) in each tier (ps20,
// ps2b, sm3), rendered by the scene renderer on OSMesa and EGL (llvmpipe) and by its C fallback,
// written to OUT/ as PNG and EXR, with GL-vs-C difference images and a side-by-side of the tiers.

#include <cmath>
#include <cstdio>
#include <cstring>

#include "cli/select_args.h"
#include "base/image_diff.h"
#include "io/atomic_dir.h"
#include "io/exr.h"
#include "io/png.h"
#include "base/srgb.h"
#include "demo/scene_files.h"
#include "families/family.h"
#include "io/lights_file.h"
#include "scene/cpu_renderer.h"
#include "scene/deferred.h"
#include "scene/frame.h"
#include "scene/reference.h"
#include "scene/scene.h"
#include "scene/selection.h"

namespace {

// The sphere grid (kSphereGridGltf, written by tools/make_scenes.py from scenes/sphere_grid.lights)
// is rendered by the scene renderer in each tier.
const Tier kTiers[] = {Tier::PS20, Tier::PS2B, Tier::SM3};

// The file every demo output holds: a directory with it may be replaced by the next run.
const char kDemoMarker[] = "model_lighting_tiers.png";

bool save(const std::string &base, const ImageF &img, Encode enc, bool exr, std::string *err) {
  if (!write_png(base + ".png", img, enc, err)) return false;
  return !exr || write_exr(base + ".exr", img, err);
}

// The lit pass with an opaque background (rgb 0, alpha 1), as the pictures are written.
ImageF opaque(const ImageF &lit) {
  ImageF o = lit;
  for (size_t p = 3; p < o.rgba.size(); p += 4) o.rgba[p] = 1.f;
  return o;
}

// The double reference of the grid: every light local, from the C renderer's G-buffer at sm3.
bool grid_reference(const Scene &s, int w, int h, ImageF *out, std::string *err) {
  SceneGBufferCpu g;
  std::vector<double> ref;
  if (!scene_gbuffer_cpu(s, Tier::SM3, w, h, false, &g, err) ||
      !scene_reference_linear(s, g.p, g.draw, g.slots, &ref, err))
    return false;
  out->w = w;
  out->h = h;
  out->rgba.assign(static_cast<size_t>(w) * h * 4, 1.f);
  for (size_t q = 0; q < static_cast<size_t>(w) * h; ++q)
    for (int c = 0; c < 3; ++c) out->rgba[q * 4 + c] = static_cast<float>(ref[q * 3 + c]);
  return true;
}

}  // namespace

// `tiershade demo --help`.
const char kHelp[] = R"(usage: tiershade demo [-o DIR] [--size WxH] [--backend osmesa|egl|all] [--lights FILE]
Renders the lit sphere grid (scenes/sphere_grid.gltf: six lights, ambient cube, orthographic
camera) with the HL2 model lighting in each tier, through the scene renderer (the variants the
scene selects, as `tiershade render`): ps20 (2 local lights, the rest folded into the ambient
cube, linear output for an sRGB target), ps2b (4 lights), sm3 (4 lights in a dynamic loop);
ps2b and sm3 tone-map and encode sRGB in the shader. Each tier is rendered on llvmpipe through
OSMesa (GL 3.3) and EGL (GLES 2.0, GLES 3.0, GL 3.3) and by the C fallback; every GL frame is
compared bit for bit with the C twin shading GL's own G-buffer.
Writes DIR/model_lighting_<tier>_<backend>.png/.exr, DIR/model_lighting_<tier>_diff_<backend>.png
(black = bit-equal), DIR/model_lighting_reference.png (double precision, every light local)
and DIR/model_lighting_tiers.png (ps20 | ps2b | sm3 | reference). Default DIR: out.
DIR is written whole or not at all: the files go to DIR.tmp.<pid>, renamed to DIR when every
section succeeded. An existing DIR is replaced only when it is empty or a previous demo output
(it holds model_lighting_tiers.png); any other directory is refused: remove it or pick another -o.
The scenes are found next to the executable (its repository's scenes/), from any directory.
--lights replaces the six lights with a lights file (format: tiershade fold --help;
example: scenes/sphere_grid.lights).)";

int cmd_demo(int argc, char **argv) {
  Args a("demo", argc, argv, {"--help"}, {"-o", "--size", "--backend", "--lights"});
  if (a.help(kHelp)) return 0;
  a.no_positional();
  std::string dir = a.get("-o", "out");
  int w = 640, h = 320;
  if (a.has("--size")) {
    const std::string s = a.get("--size");
    if (!parse_wxh(s, 8, 4096, &w, &h))
      a.fail("--size wants WxH with 8 <= W, H <= 4096, got '" + s + "'");
  }
  std::vector<BackendApi> configs = select_configs(a);
  std::string err;
  std::vector<ts_light> lights;
  if (a.has("--lights") && !read_lights(a.get("--lights"), &lights, &err)) a.fail(err);
  Scene scene;
  if (!load_scene(kSphereGridGltf, &scene, &err)) a.fail(err);
  if (a.has("--lights")) {
    scene.lights.clear();
    for (size_t i = 0; i < lights.size(); ++i)
      scene.lights.push_back({a.get("--lights") + ": light " + std::to_string(i + 1), lights[i]});
  }
  // Everything goes into DIR.tmp.<pid>, renamed over DIR only when the whole demo succeeded
  // (io/atomic_dir.h): a failed or killed run leaves no DIR, and a previous one intact.
  DirWriter out_dir;
  if (!out_dir.begin(dir, kDemoMarker, "demo output", &err)) a.fail(err);
  const std::string final_dir = dir;
  dir = out_dir.tmp();
  int failures = 0;
  std::vector<ImageF> panels;
  std::vector<Encode> panel_enc;

  // The reference (every light local, double).
  ImageF ref_img;
  if (!grid_reference(scene, w, h, &ref_img, &err) ||
      !save(dir + "/model_lighting_reference", ref_img, Encode::SRGB, true, &err)) {
    fprintf(stderr, "tiershade demo: %s\n", err.c_str());
    return 1;
  }

  printf("%-5s %-16s %10s %12s %10s  %s\n", "tier", "backend", "pixels", "mismatched", "max ULP",
         "lights local+folded");
  for (const Tier tier : kTiers) {
    SceneSelection sel;
    if (!select_scene_variants(scene, tier, "", &sel, &err)) {
      fprintf(stderr, "tiershade demo: %s\n", err.c_str());
      return 1;
    }
    // OUTPUT_MODE 0: linear out for an sRGB target (ps20); else the shader encodes the display.
    const Encode png = sel.variants.at(0).value("OUTPUT_MODE") == 0 ? Encode::SRGB : Encode::Linear;
    const std::string base = dir + "/model_lighting_" + tier_name(tier);
    SceneRenderConfig cfg;
    cfg.w = w;
    cfg.h = h;
    cfg.backend = Backend::CPU;
    SceneRenderResult cpu;
    if (!render_scene(scene, sel, cfg, &cpu, &err) || !save(base + "_cpu", opaque(cpu.lit), png, true, &err)) {
      fprintf(stderr, "tiershade demo: %s: %s\n", tier_name(tier), err.c_str());
      return 1;
    }
    panels.push_back(opaque(cpu.lit));
    panel_enc.push_back(png);
    printf("%-5s %-16s %10d %12s %10s  %d+%d\n", tier_name(tier), "cpu", w * h, "-", "-", sel.draws.at(0).lights_local,
           sel.draws.at(0).lights_folded);
    for (const auto &c : configs) {
      const std::string tag = std::string(backend_name(c.backend)) + "_" + api_name(c.api);
      cfg.backend = c.backend;
      cfg.api = c.api;
      cfg.check = true;  // the C twin on GL's own G-buffer, compared bit for bit
      SceneRenderResult gl;
      if (!render_scene(scene, sel, cfg, &gl, &err)) {
        fprintf(stderr, "tiershade demo: %s %s: %s\n", tier_name(tier), tag.c_str(), err.c_str());
        ++failures;
        continue;
      }
      DiffStats st;
      const ImageF diff = diff_image(gl.lit, gl.check_lit, &st);
      if (!save(base + "_" + tag, opaque(gl.lit), png, true, &err) ||
          !write_png(base + "_diff_" + tag + ".png", diff, Encode::Linear, &err)) {
        fprintf(stderr, "tiershade demo: %s\n", err.c_str());
        return 1;
      }
      if (st.mismatched_pixels) ++failures;
      printf("%-5s %-16s %10ld %12ld %10u\n", tier_name(tier), tag.c_str(), st.pixels, st.mismatched_pixels,
             st.max_ulp);
    }
  }
  // Side by side: ps20 | ps2b | sm3 | reference, each as a display image.
  std::vector<ImageF> display;
  for (size_t i = 0; i < panels.size(); ++i)
    display.push_back(panel_enc[i] == Encode::SRGB ? srgb_display(panels[i]) : panels[i]);
  display.push_back(srgb_display(ref_img));
  std::vector<const ImageF *> ptrs;
  for (const auto &d : display) ptrs.push_back(&d);
  if (!write_png(dir + "/model_lighting_tiers.png", hstack(ptrs, 4, 1.f), Encode::Linear, &err)) {
    fprintf(stderr, "tiershade demo: %s\n", err.c_str());
    return 1;
  }
  printf(
      "model_lighting_*.png, *.exr; side by side: model_lighting_tiers.png (ps20 | ps2b | sm3 | "
      "reference)\n");
  // The other families' sections (glue/demo_*.cpp).
  DemoOptions opt;
  opt.dir = dir;
  opt.w = w;
  opt.h = h;
  opt.configs = configs;
  for (const DemoSection *s : demo_sections()) {
    printf("\n== %s\n", s->name);
    if (!s->run(opt, &err)) {
      fprintf(stderr, "tiershade demo: %s: %s\n", s->name, err.c_str());
      ++failures;
    }
  }
  if (failures) {
    fprintf(stderr, "tiershade demo: %d GL frames differ from the C fallback or failed; nothing written to %s\n",
            failures, final_dir.c_str());
    return 1;
  }
  if (!out_dir.commit(&err)) {
    fprintf(stderr, "tiershade demo: %s\n", err.c_str());
    return 1;
  }
  printf("wrote %s/\n", final_dir.c_str());
  return 0;
}

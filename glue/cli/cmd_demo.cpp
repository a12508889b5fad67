// tiershade: `demo` subcommand: the lit sphere grid in each tier (ps20, ps2b, sm3),
// rendered on OSMesa and EGL (llvmpipe) and by the C fallback, written to OUT/ as
// PNG and EXR, with GL-vs-C difference images and a side-by-side of the tiers.
#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "demo/family_frame.h"
#include "io/lights_file.h"
#include "demo/sphere_grid_scene.h"
#include "cli/select_args.h"
#include "base/image_diff.h"
#include "io/exr.h"
#include "io/png.h"
#include "color/srgb.h"

namespace {

struct DemoTier {
  Tier tier;
  const char *variant;
  int max_local;
  Encode png;  // how the variant's output becomes a display PNG
};

const DemoTier kTiers[] = {
    {Tier::PS20, "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=0,NUM_LIGHTS=2", 2, Encode::SRGB},
    {Tier::PS2B, "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=1,NUM_LIGHTS=4", 4, Encode::Linear},
    {Tier::SM3, "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2", 4, Encode::Linear},
};

bool save(const std::string &base, const ImageF &img, Encode enc, bool exr, std::string *err) {
  if (!write_png(base + ".png", img, enc, err)) return false;
  return !exr || write_exr(base + ".exr", img, err);
}

}  // namespace

int cmd_demo(int argc, char **argv) {
  Args a("demo", argc, argv, {"--help"}, {"-o", "--size", "--backend", "--lights"});
  if (a.flag("--help")) {
    puts("usage: tiershade demo [-o DIR] [--size WxH] [--backend osmesa|egl|all] [--lights FILE]\n"
         "Renders the lit sphere grid (six lights, ambient cube) with the HL2 model lighting in each\n"
         "tier: ps20 (2 local lights, the rest folded into the ambient cube, linear output for an sRGB\n"
         "target), ps2b (4 lights, gamma 2.2 in the shader), sm3 (4 lights in a dynamic loop, exact sRGB).\n"
         "Each tier is rendered on llvmpipe through OSMesa (GL 3.3) and EGL (GLES 2.0, GLES 3.0, GL 3.3)\n"
         "and by the C fallback; every GL frame is compared bit for bit with the C frame.\n"
         "Writes DIR/model_lighting_<tier>_<backend>.png/.exr, DIR/model_lighting_<tier>_diff_<backend>.png\n"
         "(black = bit-equal), DIR/model_lighting_reference.png (double precision, every light local)\n"
         "and DIR/model_lighting_tiers.png (ps20 | ps2b | sm3 | reference). Default DIR: out.\n"
         "--lights replaces the six lights with a lights file (format: tiershade fold --help;\n"
         "example: scenes/sphere_grid.lights).");
    return 0;
  }
  if (!a.positional().empty()) a.fail("unexpected argument '" + a.positional()[0] + "'");
  const std::string dir = a.get("-o", "out");
  int w = 640, h = 320;
  if (a.has("--size")) {
    const std::string s = a.get("--size");
    char extra;
    if (sscanf(s.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 8 || h < 8 || w > 4096 || h > 4096)
      a.fail("--size wants WxH with 8 <= W, H <= 4096, got '" + s + "'");
  }
  std::vector<BackendApi> configs = select_configs(a);
  std::string err;
  if (mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "tiershade demo: cannot create directory '%s': %s\n", dir.c_str(), strerror(errno));
    return 1;
  }
  Selection sel;
  if (!load_shader_decls(&sel.decls, &err)) a.fail(err);
  const ShaderFamily *fam = find_family("model_lighting");
  SphereScene scene = default_sphere_scene();
  if (a.has("--lights")) {
    scene.lights.clear();
    if (!read_lights(a.get("--lights"), &scene.lights, &err)) a.fail(err);
  }
  int failures = 0;
  std::vector<ImageF> panels;

  // The reference (every light local, double) only depends on the geometry.
  SphereFrame ref_frame;
  if (!sphere_frame(scene, w, h, 64, &ref_frame, &err)) {
    fprintf(stderr, "tiershade demo: %s\n", err.c_str());
    return 1;
  }
  std::vector<double> ref;
  sphere_reference_linear(scene, ref_frame, &ref);
  ImageF ref_img;
  ref_img.w = w;
  ref_img.h = h;
  ref_img.rgba.resize(static_cast<size_t>(w) * h * 4);
  for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) ref_img.rgba[p * 4 + c] = static_cast<float>(ref[p * 3 + c]);
    ref_img.rgba[p * 4 + 3] = 1.f;
  }
  if (!save(dir + "/model_lighting_reference", ref_img, Encode::SRGB, true, &err)) {
    fprintf(stderr, "tiershade demo: %s\n", err.c_str());
    return 1;
  }

  printf("%-5s %-16s %10s %12s %10s  %s\n", "tier", "backend", "pixels", "mismatched", "max ULP", "lights local+folded");
  for (const DemoTier &t : kTiers) {
    Variant v;
    if (!find_variant(sel.decls, "model_lighting", t.variant, &v, &err)) a.fail(err);
    SphereFrame frame;
    if (!sphere_frame(scene, w, h, t.max_local, &frame, &err)) {
      fprintf(stderr, "tiershade demo: %s\n", err.c_str());
      return 1;
    }
    const std::string base = dir + "/model_lighting_" + tier_name(t.tier);
    ImageF cpu;
    cpu_render_frame(*fam, v, frame.in, &cpu);
    sphere_mask(frame, &cpu);
    if (!save(base + "_cpu", cpu, t.png, true, &err)) {
      fprintf(stderr, "tiershade demo: %s\n", err.c_str());
      return 1;
    }
    panels.push_back(cpu);
    printf("%-5s %-16s %10d %12s %10s  %d+%d\n", tier_name(t.tier), "cpu", w * h, "-", "-", frame.lights_kept,
           frame.lights_folded);
    for (const auto &cfg : configs) {
      const std::string tag = std::string(backend_name(cfg.backend)) + "_" + api_name(cfg.api);
      auto ctx = GlContext::create(cfg.backend, cfg.api, &err);
      if (!ctx) {
        fprintf(stderr, "tiershade demo: %s: %s\n", tag.c_str(), err.c_str());
        ++failures;
        continue;
      }
      GlRenderer r(*ctx);
      GlFrameProgram fp;
      ImageF gl;
      if (!gl_frame_setup(r, cfg.api, *fam, v, frame.in, &fp, &err) ||
          !gl_frame_draw(r, fp, frame.in, &gl, nullptr, &err)) {
        fprintf(stderr, "tiershade demo: %s %s: %s\n", t.variant, tag.c_str(), err.c_str());
        ++failures;
        gl_frame_release(r, &fp);
        continue;
      }
      gl_frame_release(r, &fp);
      sphere_mask(frame, &gl);
      DiffStats st;
      const ImageF diff = diff_image(gl, cpu, &st);
      if (!save(base + "_" + tag, gl, t.png, true, &err) ||
          !write_png(base + "_diff_" + tag + ".png", diff, Encode::Linear, &err)) {
        fprintf(stderr, "tiershade demo: %s\n", err.c_str());
        return 1;
      }
      if (st.mismatched_pixels) ++failures;
      printf("%-5s %-16s %10ld %12ld %10u\n", tier_name(t.tier), tag.c_str(), st.pixels, st.mismatched_pixels,
             st.max_ulp);
    }
  }
  // Side by side: ps20 | ps2b | sm3 | reference, each as a display image.
  std::vector<ImageF> display;
  for (size_t i = 0; i < panels.size(); ++i)
    display.push_back(kTiers[i].png == Encode::SRGB ? srgb_display(panels[i]) : panels[i]);
  display.push_back(srgb_display(ref_img));
  std::vector<const ImageF *> ptrs;
  for (const auto &d : display) ptrs.push_back(&d);
  if (!write_png(dir + "/model_lighting_tiers.png", hstack(ptrs, 4, 1.f), Encode::Linear, &err)) {
    fprintf(stderr, "tiershade demo: %s\n", err.c_str());
    return 1;
  }
  printf("wrote %s/model_lighting_*.png, *.exr; side by side: %s/model_lighting_tiers.png (ps20 | ps2b | sm3 | reference)\n",
         dir.c_str(), dir.c_str());
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
  if (failures) printf("demo: %d GL frames differ from the C fallback or failed\n", failures);
  return failures ? 1 : 0;
}

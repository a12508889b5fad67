// tiershade demo: the world_lighting section of `tiershade demo`: the lightmapped room
// (scenes/world_lighting.gltf, rendered by the scene renderer, glue/scene/frame.h) in each tier,
// "lightmaps only" and the final shading (the talk's "Light Maps Only" / "Final Rendered Scene"
// pair, glue/scene/views.h), on every GL backend and by the C fallback. Each GL frame is
// compared bit for bit with the C twins shading GL's own G-buffer (SceneRenderConfig::check).
// Last, the room baked with direct light only and with radiosity bounces, side by side.
#include <cmath>
#include <cstdio>

#include "base/image_diff.h"
#include "base/srgb.h"
#include "demo/scene_files.h"
#include "demo/section_util.h"
#include "io/exr.h"
#include "io/png.h"
#include "scene/deferred.h"
#include "scene/frame.h"
#include "scene/reference.h"
#include "scene/views.h"

namespace {

const Tier kTiers[] = {Tier::PS20, Tier::PS2B, Tier::SM3};

bool save(const std::string &base, const ImageF &img, bool exr, std::string *err) {
  if (!write_png(base + ".png", img, Encode::SRGB, err)) return false;
  return !exr || write_exr(base + ".exr", img, err);
}

// Rows bottom-up (ImageF): the first image is the bottom row.
ImageF vstack2(const ImageF &bottom, const ImageF &top, int gap) {
  ImageF o;
  o.w = bottom.w;
  o.h = bottom.h + gap + top.h;
  o.rgba.assign(static_cast<size_t>(o.w) * o.h * 4, 1.f);
  std::copy(bottom.rgba.begin(), bottom.rgba.end(), o.rgba.begin());
  std::copy(top.rgba.begin(), top.rgba.end(), o.rgba.begin() + static_cast<long>(bottom.h + gap) * o.w * 4);
  return o;
}

// The lit pass of `s` at `tier` on the C fallback (cfg.backend CPU) or on GL with the check.
bool lit_frame(const Scene &s, Tier tier, SceneRenderConfig cfg, SceneRenderResult *res, std::string *err) {
  SceneSelection sel;
  return select_scene_variants(s, tier, "", &sel, err) && render_scene(s, sel, cfg, res, err);
}

bool run(const DemoOptions &opt, std::string *err) {
  Scene room;
  if (!load_scene(kWorldLightingGltf, &room, err)) return false;
  const std::string dir = opt.dir + "/world_lighting_";
  int failures = 0;
  std::vector<ImageF> finals, lightmaps;
  SceneRenderConfig cfg;
  cfg.w = opt.w;
  cfg.h = opt.h;
  printf("room: %s, %dx%d\n", kWorldLightingGltf, opt.w, opt.h);
  printf("%-5s %-10s %-16s %10s %12s %10s\n", "tier", "image", "backend", "pixels", "mismatched", "max ULP");
  for (const Tier tier : kTiers) {
    for (const SceneView view : {SceneView::Final, SceneView::Lightmaps}) {
      const bool lm_only = view == SceneView::Lightmaps;
      const Scene s = scene_view(room, view);
      const std::string base = dir + tier_name(tier) + (lm_only ? "_lightmaps" : "");
      SceneRenderResult cpu;
      cfg.backend = Backend::CPU;
      cfg.check = false;
      if (!lit_frame(s, tier, cfg, &cpu, err) || !save(base + "_cpu", cpu.lit, !lm_only, err)) return false;
      (lm_only ? lightmaps : finals).push_back(cpu.lit);
      printf("%-5s %-10s %-16s %10d %12s %10s\n", tier_name(tier), lm_only ? "lightmaps" : "final", "cpu",
             opt.w * opt.h, "-", "-");
      for (const BackendApi &bc : opt.configs) {
        const std::string tag = config_tag(bc);
        cfg.backend = bc.backend;
        cfg.api = bc.api;
        cfg.check = true;
        SceneRenderResult gl;
        if (!lit_frame(s, tier, cfg, &gl, err)) {
          fprintf(stderr, "world_lighting demo: %s %s: %s\n", tier_name(tier), tag.c_str(), err->c_str());
          ++failures;
          continue;
        }
        DiffStats st;
        const ImageF diff = diff_image(gl.lit, gl.check_lit, &st);
        if (!save(base + "_" + tag, gl.lit, false, err) ||
            !write_png(base + "_diff_" + tag + ".png", diff, Encode::Linear, err))
          return false;
        if (st.mismatched_pixels || gl.check_mismatched != 0) ++failures;
        printf("%-5s %-10s %-16s %10ld %12ld %10u\n", tier_name(tier), lm_only ? "lightmaps" : "final", tag.c_str(),
               st.pixels, st.mismatched_pixels, st.max_ulp);
      }
    }
  }
  // The reference: every draw's shading at sm3 in double precision from the unquantised float32
  // page, on the C renderer's G-buffer (glue/scene/reference.h).
  SceneGBufferCpu g;
  std::vector<double> ref;
  if (!scene_gbuffer_cpu(room, Tier::SM3, opt.w, opt.h, false, &g, err) ||
      !scene_reference_linear(room, g.p, g.draw, g.slots, &ref, err))
    return false;
  ImageF ref_img;
  ref_img.w = opt.w;
  ref_img.h = opt.h;
  ref_img.rgba.assign(static_cast<size_t>(opt.w) * opt.h * 4, 1.f);
  for (size_t q = 0; q < ref.size() / 3; ++q)
    for (int c = 0; c < 3; ++c) ref_img.rgba[q * 4 + c] = static_cast<float>(ref[q * 3 + c]);
  if (!save(dir + "reference", ref_img, true, err)) return false;
  finals.push_back(ref_img);
  // The flat lightmap alone, no normal maps: what a Source level without bump maps shows.
  SceneRenderResult flat;
  cfg.backend = Backend::CPU;
  cfg.check = false;
  if (!lit_frame(scene_view(room, SceneView::FlatLightmaps), Tier::SM3, cfg, &flat, err)) return false;
  lightmaps.push_back(flat.lit);
  // Grid: top row final shading (ps20 | ps2b | sm3 | double reference), bottom row lightmaps
  // only (ps20 | ps2b | sm3 | the flat lightmap without normal maps); sRGB-encoded for display.
  auto display = [](std::vector<ImageF> v) {
    for (ImageF &im : v) im = srgb_display(im);
    return v;
  };
  const std::vector<ImageF> top = display(finals), bottom = display(lightmaps);
  std::vector<const ImageF *> tp, bp;
  for (const ImageF &i : top) tp.push_back(&i);
  for (const ImageF &i : bottom) bp.push_back(&i);
  if (!write_png(dir + "tiers.png", vstack2(hstack(bp, 4, 1.f), hstack(tp, 4, 1.f), 4), Encode::Linear, err))
    return false;
  printf(
      "wrote %sTIER[_lightmaps]_BACKEND.png, the diffs, %sreference.exr and %stiers.png\n"
      "(top: final ps20 | ps2b | sm3 | double reference; bottom: lightmaps only, and the flat lightmap)\n",
      dir.c_str(), dir.c_str(), dir.c_str());
  // The talk's "Direct lighting only" / "Radiosity lighting" pair: the room baked without and with
  // diffuse bounces (docs/baking.md), sm3, the C fallback.
  std::vector<ImageF> pair;
  for (const int bounces : {0, 8}) {
    Scene r = room;
    r.lightmaps.quality.bounces = bounces;
    SceneRenderResult res;
    if (!lit_frame(r, Tier::SM3, cfg, &res, err)) return false;
    pair.push_back(srgb_display(res.lit));
  }
  if (!write_png(dir + "radiosity.png", hstack({&pair[0], &pair[1]}, 4, 1.f), Encode::Linear, err)) return false;
  printf("wrote %sradiosity.png (direct light only | 8 bounces of radiosity)\n", dir.c_str());
  return demo_section_result(failures, "world_lighting GL frames differ from the C twins or failed", err);
}

const DemoSection kSection = {"world_lighting", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

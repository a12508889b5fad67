// tiershade demo: the world_lighting section of `tiershade demo`: the room (scene_world.h)
// in each tier, "lightmaps only" and the final shading (the talk's "Light Maps Only" /
// "Final Rendered Scene" pair), on every GL backend and by the C fallback, each GL frame
// compared bit for bit with the C frame. GLES frames sample the cube maps NEAREST (GLES
// cube maps are seamless; docs/world_lighting.md), so they are compared with a C frame
// rendered the same way.
#include <cmath>
#include <cstdio>

#include "gl/context.h"
#include "shaderlib/variants.h"
#include "demo/room_render.h"
#include "base/image_diff.h"
#include "io/exr.h"
#include "io/png.h"
#include "base/srgb.h"

namespace {

struct DemoTierW {
  const char *tier;
  const char *final_variant, *lightmap_variant;
};
const DemoTierW kTiers[] = {
    {"ps20", "ps20:BUMPMAP=1,LIGHTMAP_ENCODING=1,ENVMAP=1,ENVMAPMASK=1",
     "ps20:BUMPMAP=1,LIGHTMAP_ENCODING=1,ENVMAP=0,ENVMAPMASK=0"},
    {"ps2b", "ps2b:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1",
     "ps2b:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=0,ENVMAPMASK=0"},
    {"sm3", "sm3:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=1",
     "sm3:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=0,ENVMAPMASK=0"},
};

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

bool run(const DemoOptions &opt, std::string *err) {
  Selection sel;
  if (!load_shader_decls(&sel.decls, err)) return false;
  const WorldScene scene = default_world_scene();
  WorldBake bake;
  if (!bake_world(scene, &bake, err)) return false;
  WorldFrame frame;
  if (!world_frame(scene, bake, opt.w, opt.h, &frame, err)) return false;
  const std::string dir = opt.dir + "/world_lighting_";
  int failures = 0;
  std::vector<ImageF> finals, lightmaps;
  printf("%-5s %-10s %-16s %10s %12s %10s\n", "tier", "image", "backend", "pixels", "mismatched", "max ULP");
  for (const DemoTierW &t : kTiers) {
    for (int lm_only = 0; lm_only < 2; ++lm_only) {
      Variant v;
      if (!find_variant(sel.decls, "world_lighting", lm_only ? t.lightmap_variant : t.final_variant, &v, err))
        return false;
      const TextureDesc page = encode_page(scene, bake, v.value("LIGHTMAP_ENCODING"));
      WorldPass pass{&v, &page, lm_only == 1, false};
      const std::string base = dir + t.tier + (lm_only ? "_lightmaps" : "");
      ImageF cpu, cpu_nearest;
      world_render_cpu(frame, bake, pass, &cpu);
      if (!save(base + "_cpu", cpu, !lm_only, err)) return false;
      (lm_only ? lightmaps : finals).push_back(cpu);
      printf("%-5s %-10s %-16s %10d %12s %10s\n", t.tier, lm_only ? "lightmaps" : "final", "cpu", opt.w * opt.h, "-",
             "-");
      for (const BackendApi &cfg : opt.configs) {
        const std::string tag = std::string(backend_name(cfg.backend)) + "_" + api_name(cfg.api);
        auto ctx = GlContext::create(cfg.backend, cfg.api, err);
        if (!ctx) {
          fprintf(stderr, "world_lighting demo: %s: %s\n", tag.c_str(), err->c_str());
          ++failures;
          continue;
        }
        GlRenderer r(*ctx);
        WorldPass p = pass;
        p.nearest_cube = cfg.api != Api::GL33;
        const ImageF *ref = &cpu;
        if (p.nearest_cube) {
          if (cpu_nearest.rgba.empty()) world_render_cpu(frame, bake, p, &cpu_nearest);
          ref = &cpu_nearest;
        }
        ImageF gl;
        if (!world_render_gl(r, cfg.api, frame, bake, p, &gl, err)) {
          fprintf(stderr, "world_lighting demo: %s %s: %s\n", v.name().c_str(), tag.c_str(), err->c_str());
          ++failures;
          continue;
        }
        DiffStats st;
        const ImageF diff = diff_image(gl, *ref, &st);
        if (!save(base + "_" + tag, gl, false, err) ||
            !write_png(base + "_diff_" + tag + ".png", diff, Encode::Linear, err))
          return false;
        if (st.mismatched_pixels) ++failures;
        printf("%-5s %-10s %-16s %10ld %12ld %10u\n", t.tier, lm_only ? "lightmaps" : "final", tag.c_str(), st.pixels,
               st.mismatched_pixels, st.max_ulp);
      }
    }
  }
  // The reference: the sm3 shading in double precision from the unquantised float32 page.
  Variant sm3;
  if (!find_variant(sel.decls, "world_lighting", kTiers[2].final_variant, &sm3, err)) return false;
  const TextureDesc page32 = encode_page(scene, bake, -1);
  std::vector<double> ref;
  world_render_double(frame, bake, WorldPass{&sm3, &page32, false, false}, &ref);
  ImageF ref_img;
  ref_img.w = opt.w;
  ref_img.h = opt.h;
  ref_img.rgba.assign(ref.begin(), ref.end());
  if (!save(dir + "reference", ref_img, true, err)) return false;
  finals.push_back(ref_img);
  // The flat lightmap (k = 0) alone, no normal map: what a Source level without bump maps shows.
  Variant flat;
  if (!find_variant(sel.decls, "world_lighting", "sm3:BUMPMAP=0,LIGHTMAP_ENCODING=0,ENVMAP=0,ENVMAPMASK=0", &flat, err))
    return false;
  const TextureDesc page16 = encode_page(scene, bake, WL_LM_FLOAT);
  WorldFrame flat_frame = frame;
  flat_frame.in.shared[WL_SLOT_TINT_SCALE].x = flat_frame.in.shared[WL_SLOT_TINT_SCALE].y =
      flat_frame.in.shared[WL_SLOT_TINT_SCALE].z = 1.f;
  ImageF flat_img;
  world_render_cpu(flat_frame, bake, WorldPass{&flat, &page16, true, false}, &flat_img);
  lightmaps.push_back(flat_img);
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
  if (failures) {
    *err = std::to_string(failures) + " world_lighting GL frames differ from the C frames or failed";
    return false;
  }
  return true;
}

const DemoSection kSection = {"world_lighting", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

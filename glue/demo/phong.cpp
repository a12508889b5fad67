// tiershade demo: the Episode One demo section: one normal-mapped sphere with an exponent map
// (scenes/phong_sphere.gltf, framed by the scene renderer: glue/scene/deferred.h), lit by four
// lights and an ambient cube from the Grace Cathedral probe, as the seed's "Diffuse Lighting" /
// "Specular Lighting" / "High Quality Lighting" comparison: ps20 (HL2, no Phong),
// the ps2b Phong specular alone, ps2b with Phong, and sm3 with rim light and envmap.
// Every GL frame is compared with the C fallback.
#include <cmath>
#include <cstdio>

#include "conform/conform.h"
#include "conform/family_frame.h"
#include "base/image_diff.h"
#include "io/exr.h"
#include "io/png.h"
#include "base/srgb.h"
#include "demo/scene_files.h"
#include "demo/section_util.h"
#include "scene/deferred.h"

namespace {

struct Panel {
  const char *tag, *variant;  // the variant's tier sets the lights kept (ps20: 2, else 4)
  bool black_albedo;  // specular alone
  Encode png;
};

const Panel kPanels[] = {
    {"ps20_diffuse", "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,NUM_LIGHTS=2", false, Encode::SRGB},
    {"ps2b_specular", "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,NUM_LIGHTS=4",
     true, Encode::Linear},
    {"ps2b_phong", "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,NUM_LIGHTS=4",
     false, Encode::Linear},
    {"sm3_full", "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,ENVMAP=1",
     false, Encode::Linear},
};

ImageF to_display(const ImageF &img, Encode enc) { return enc == Encode::SRGB ? srgb_display(img) : img; }

bool run(const DemoOptions &opt, std::string *err) {
  std::vector<ShaderDecl> decls;
  if (!load_shader_decls(&decls, err)) return false;
  const ShaderFamily *fam = find_family("model_lighting");
  Scene ball;
  if (!load_scene(kPhongSphereGltf, &ball, err)) return false;
  const int size = std::max(32, std::min(opt.w, opt.h));
  printf("phong sphere: %s\n", kPhongSphereGltf);
  std::vector<ImageF> display;
  int failures = 0;
  for (const Panel &p : kPanels) {
    Variant v;
    if (!find_variant(decls, "model_lighting", p.variant, &v, err)) return false;
    // The frame at the panel's tier (ps20: 2 lights local), every texture of the material real.
    SceneDeferredFrame frame;
    if (!scene_deferred_frame(ball, v.tier, size, size, &frame, err, true)) return false;
    if (p.black_albedo)
      for (size_t i = 0; i < frame.in.textures[0].rgba.size(); ++i)
        if (i % 4 != 3) frame.in.textures[0].rgba[i] = 0.f;
    ImageF cpu;
    cpu_render_frame(*fam, v, frame.in, &cpu);
    scene_deferred_mask(frame, &cpu);
    const std::string file = opt.dir + "/phong_" + p.tag;
    if (!write_png(file + "_cpu.png", cpu, p.png, err) || !write_exr(file + "_cpu.exr", cpu, err)) return false;
    display.push_back(to_display(cpu, p.png));
    const bool gl_ok = for_each_gl_config(
        opt,
        [&](const BackendApi &cfg, const std::string &tag, GlRenderer &r) {
          FamilyInputs in = frame.in;
          adapt_textures_for_api(cfg.api, &in);  // NEAREST cube maps on GLES (seamless, glue/conform/conform.h)
          ImageF ref = cpu;
          if (cfg.api != Api::GL33) {
            cpu_render_frame(*fam, v, in, &ref);
            scene_deferred_mask(frame, &ref);
          }
          GlFrameProgram fp;
          ImageF gl;
          const bool ok =
              gl_frame_setup(r, cfg.api, *fam, v, in, &fp, err) && gl_frame_draw(r, fp, in, &gl, nullptr, err);
          gl_frame_release(r, &fp);
          if (!ok) return false;
          scene_deferred_mask(frame, &gl);
          DiffStats st;
          diff_image(gl, ref, &st);
          if (st.mismatched_pixels) ++failures;
          if (!write_png(file + "_" + tag + ".png", gl, p.png, err)) return false;
          printf("%-14s %-16s %8ld px %8ld mismatched  max %u ULP\n", p.tag, tag.c_str(), st.pixels,
                 st.mismatched_pixels, st.max_ulp);
          return true;
        },
        err);
    if (!gl_ok) return false;
  }
  std::vector<const ImageF *> ptrs;
  for (const auto &d : display) ptrs.push_back(&d);
  if (!write_png(opt.dir + "/phong_comparison.png", hstack(ptrs, 4, 1.f), Encode::Linear, err)) return false;
  printf(
      "wrote %s/phong_*.png; side by side: %s/phong_comparison.png (ps20 diffuse | ps2b specular | ps2b Phong | "
      "sm3 with rim and envmap)\n",
      opt.dir.c_str(), opt.dir.c_str());
  return demo_section_result(failures, "GL frames differ from the C fallback", err);
}

const DemoSection kSection = {"model_lighting_phong", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

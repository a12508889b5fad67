// tiershade glue: the Episode One demo section: one normal-mapped sphere with an
// exponent map, lit by four lights and an ambient cube (from a real light probe when
// ../shared/data/probes/grace.hdr is readable), as the seed's "Diffuse Lighting" /
// "Specular Lighting" / "High Quality Lighting" comparison: ps20 (HL2, no Phong),
// the ps2b Phong specular alone, ps2b with Phong, and sm3 with rim light and envmap.
// Every GL frame is compared with the C fallback.
#include <cmath>
#include <cstdio>

#include "conform/conform.h"
#include "demo/family_frame.h"
#include "demo/sphere_grid_scene.h"

namespace {

struct Panel {
  const char *tag, *variant;
  int max_local;
  bool black_albedo;  // specular alone
  Encode png;
};

const Panel kPanels[] = {
    {"ps20_diffuse", "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,NUM_LIGHTS=2", 2, false, Encode::SRGB},
    {"ps2b_specular", "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,NUM_LIGHTS=4", 4,
     true, Encode::Linear},
    {"ps2b_phong", "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,NUM_LIGHTS=4", 4,
     false, Encode::Linear},
    {"sm3_full", "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,ENVMAP=1", 4,
     false, Encode::Linear},
};

ImageF to_display(const ImageF &img, Encode enc) {
  ImageF d = img;
  if (enc != Encode::SRGB) return d;
  for (size_t p = 0; p < d.rgba.size(); ++p)
    if (p % 4 != 3) {
      const float x = std::fmin(std::fmax(d.rgba[p], 0.f), 1.f);
      d.rgba[p] = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.f / 2.4f) - 0.055f;
    }
  return d;
}

bool run(const DemoOptions &opt, std::string *err) {
  std::vector<ShaderDecl> decls;
  if (!load_shader_decls(&decls, err)) return false;
  const ShaderFamily *fam = find_family("model_lighting");
  std::string note;
  SphereScene base;
  if (!phong_sphere_scene("../shared/data/probes/grace.hdr", &base, &note, err)) return false;
  const int size = std::max(32, std::min(opt.w, opt.h));
  printf("phong sphere: %s\n", note.c_str());
  std::vector<ImageF> display;
  int failures = 0;
  for (const Panel &p : kPanels) {
    Variant v;
    if (!find_variant(decls, "model_lighting", p.variant, &v, err)) return false;
    SphereScene scene = base;
    if (p.black_albedo)
      for (size_t i = 0; i < scene.textures[0].rgba.size(); ++i)
        if (i % 4 != 3) scene.textures[0].rgba[i] = 0.f;
    SphereFrame frame;
    if (!sphere_frame(scene, size, size, p.max_local, &frame, err)) return false;
    ImageF cpu;
    cpu_render_frame(*fam, v, frame.in, &cpu);
    sphere_mask(frame, &cpu);
    const std::string file = opt.dir + "/phong_" + p.tag;
    if (!write_png(file + "_cpu.png", cpu, p.png, err) || !write_exr(file + "_cpu.exr", cpu, err)) return false;
    display.push_back(to_display(cpu, p.png));
    for (const auto &cfg : opt.configs) {
      const std::string tag = std::string(backend_name(cfg.backend)) + "_" + api_name(cfg.api);
      auto ctx = GlContext::create(cfg.backend, cfg.api, err);
      if (!ctx) return false;
      GlRenderer r(*ctx);
      FamilyInputs in = frame.in;
      adapt_textures_for_api(cfg.api, &in);  // NEAREST cube maps on GLES (seamless, glue/conform/conform.h)
      ImageF ref = cpu;
      if (cfg.api != Api::GL33) {
        cpu_render_frame(*fam, v, in, &ref);
        sphere_mask(frame, &ref);
      }
      GlFrameProgram fp;
      ImageF gl;
      const bool ok = gl_frame_setup(r, cfg.api, *fam, v, in, &fp, err) && gl_frame_draw(r, fp, in, &gl, nullptr, err);
      gl_frame_release(r, &fp);
      if (!ok) return false;
      sphere_mask(frame, &gl);
      DiffStats st;
      diff_image(gl, ref, &st);
      if (st.mismatched_pixels) ++failures;
      if (!write_png(file + "_" + tag + ".png", gl, p.png, err)) return false;
      printf("%-14s %-16s %8ld px %8ld mismatched  max %u ULP\n", p.tag, tag.c_str(), st.pixels, st.mismatched_pixels,
             st.max_ulp);
    }
  }
  std::vector<const ImageF *> ptrs;
  for (const auto &d : display) ptrs.push_back(&d);
  if (!write_png(opt.dir + "/phong_comparison.png", hstack(ptrs, 4, 1.f), Encode::Linear, err)) return false;
  printf("wrote %s/phong_*.png; side by side: %s/phong_comparison.png (ps20 diffuse | ps2b specular | ps2b Phong | "
         "sm3 with rim and envmap)\n",
         opt.dir.c_str(), opt.dir.c_str());
  if (failures) {
    *err = std::to_string(failures) + " GL frames differ from the C fallback";
    return false;
  }
  return true;
}

const DemoSection kSection = {"model_lighting_phong", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

// tiershade demo: the colour-correction section of `tiershade demo`: one frame (a tone-mapped
// light probe above a colour chart) without and with two colour corrections, Source-style
// 32^3 LUTs baked with OpenColorIO from the colourist-style .cube files of scenes/luts:
// day for night, desaturation, and the two blended 50/50 (talk: "Color Correction").
// GLES 2.0 renders the ps20 atlas variant, the other APIs the ps2b 3D-texture variant; every
// GL frame is compared bit for bit with the C twin, and each corrected frame with OpenColorIO's
// CPU processor applied to the frame directly (CIEDE2000).
#include <cstdio>

#include "families/color_correction_inputs.h"
#include "demo/color_correction_scene.h"
#include "conform/family_frame.h"
#include "gl/context.h"
#include "shaderlib/variants.h"
#include "base/image_diff.h"
#include "io/exr.h"
#include "io/png.h"

namespace {

struct Panel {
  const char *name;
  float weights[4];
  float default_weight;
};
// LUT 0 = day for night, LUT 1 = desaturate.
const Panel kPanels[] = {
    {"day_for_night", {1, 0, 0, 0}, 0},
    {"desaturate", {0, 1, 0, 0}, 0},
    {"blend", {0.5f, 0.5f, 0, 0}, 0},
};
const char kVariant3D[] = "ps2b:LUT_ATLAS=0,SHADER_TRILINEAR=0,NUM_LOOKUPS=2";
const char kVariantAtlas[] = "ps20:LUT_ATLAS=1,SHADER_TRILINEAR=0,NUM_LOOKUPS=2";
const int kLutEdge = 32;  // Source's edge (fact sheet section 9)

bool run(const DemoOptions &opt, std::string *err) {
  std::string note;
  const ImageF frame = cc_frame(opt.w, opt.h, &note);
  std::vector<CcExample> ex;
  if (!cc_examples(&ex, err)) return false;
  Lut3D luts[2];
  for (int i = 0; i < 2; ++i)
    if (!bake_lut(ex[i].transform, kLutEdge, &luts[i], err)) return false;
  std::vector<ShaderDecl> decls;
  if (!load_shader_decls(&decls, err)) return false;
  Variant v3d, vatlas;
  if (!find_variant(decls, "color_correction", kVariant3D, &v3d, err) ||
      !find_variant(decls, "color_correction", kVariantAtlas, &vatlas, err))
    return false;
  const ShaderFamily *fam = find_family("color_correction");
  if (!fam) {
    *err = "color_correction family not registered";
    return false;
  }
  const std::string base = opt.dir + "/color_correction";
  if (!write_png(base + "_original.png", frame, Encode::Linear, err)) return false;
  printf("frame: %s; LUTs %d^3 baked with OpenColorIO from %s and %s\n", note.c_str(), kLutEdge, ex[0].file.c_str(),
         ex[1].file.c_str());

  // OpenColorIO's CPU processor on the frame itself: the reference of each panel.
  ImageF ref[3];
  ref[0] = cc_apply_reference(ex[0].transform, frame);
  ref[1] = cc_apply_reference(ex[1].transform, frame);
  ref[2] = ref[0];
  for (size_t i = 0; i < ref[2].rgba.size(); ++i)
    if (i % 4 != 3) ref[2].rgba[i] = 0.5f * ref[0].rgba[i] + 0.5f * ref[1].rgba[i];

  // The C twin, for both variants and every panel.
  FamilyInputs in;
  cc_frame_inputs(frame, kPanels[0].weights, 0, kLutEdge, &in);
  cc_set_luts(&in, {&luts[0], &luts[1]}, true);
  ImageF cpu3d[3], cpuatlas[3];
  for (int p = 0; p < 3; ++p) {
    cc_frame_inputs(frame, kPanels[p].weights, kPanels[p].default_weight, kLutEdge, &in);
    cpu_render_frame(*fam, v3d, in, &cpu3d[p]);
    cpu_render_frame(*fam, vatlas, in, &cpuatlas[p]);
    if (!write_png(base + "_" + kPanels[p].name + "_cpu.png", cpu3d[p], Encode::Linear, err)) return false;
    if (!write_exr(base + "_" + kPanels[p].name + "_cpu.exr", cpu3d[p], err)) return false;
  }
  printf("%-14s %-16s %-50s %10s %10s %16s\n", "correction", "backend", "variant", "mismatched", "max ULP",
         "dE00 vs OCIO max/mean");
  for (int p = 0; p < 3; ++p) {
    double mx, mean;
    cc_frame_difference(cpu3d[p], ref[p], &mx, &mean);
    printf("%-14s %-16s %-50s %10s %10s %8.3f/%.4f\n", kPanels[p].name, "cpu", kVariant3D, "-", "-", mx, mean);
  }
  bool all_equal = true;
  for (const BackendApi &cfg : opt.configs) {
    const std::string tag = std::string(backend_name(cfg.backend)) + "_" + api_name(cfg.api);
    const bool es2 = cfg.api == Api::GLES2;
    const Variant &v = es2 ? vatlas : v3d;
    auto ctx = GlContext::create(cfg.backend, cfg.api, err);
    if (!ctx) {
      *err = tag + ": " + *err;
      return false;
    }
    GlRenderer r(*ctx);
    GlFrameProgram fp;
    cc_frame_inputs(frame, kPanels[0].weights, kPanels[0].default_weight, kLutEdge, &in);
    if (!gl_frame_setup(r, cfg.api, *fam, v, in, &fp, err)) {
      *err = tag + ": " + *err;
      return false;
    }
    for (int p = 0; p < 3; ++p) {
      cc_frame_inputs(frame, kPanels[p].weights, kPanels[p].default_weight, kLutEdge, &in);
      r.gl().UseProgram(fp.program);
      fam->bind_uniforms(r.gl(), fp.program, in.shared);
      ImageF gl;
      if (!gl_frame_draw(r, fp, in, &gl, nullptr, err)) {
        gl_frame_release(r, &fp);
        *err = tag + ": " + *err;
        return false;
      }
      const ImageF &cpu = es2 ? cpuatlas[p] : cpu3d[p];
      DiffStats st;
      const ImageF diff = diff_image(gl, cpu, &st);
      const std::string pb = base + "_" + kPanels[p].name;
      if (!write_png(pb + "_" + tag + ".png", gl, Encode::Linear, err) ||
          !write_png(pb + "_diff_" + tag + ".png", diff, Encode::Linear, err)) {
        gl_frame_release(r, &fp);
        return false;
      }
      double mx, mean;
      cc_frame_difference(gl, ref[p], &mx, &mean);
      printf("%-14s %-16s %-50s %10ld %10u %8.3f/%.4f\n", kPanels[p].name, tag.c_str(), v.name().c_str(),
             st.mismatched_pixels, st.max_ulp, mx, mean);
      if (st.mismatched_pixels) all_equal = false;
    }
    gl_frame_release(r, &fp);
  }
  // Side by side: original | day for night | desaturate | blend.
  const ImageF *row[] = {&frame, &cpu3d[0], &cpu3d[1], &cpu3d[2]};
  if (!write_png(base + ".png", hstack({row[0], row[1], row[2], row[3]}, 4, 1.f), Encode::Linear, err)) return false;
  printf("wrote %s_*.png, *.exr; side by side: %s.png (original | day for night | desaturate | 50/50 blend)\n",
         base.c_str(), base.c_str());
  if (!all_equal) {
    *err = "a GL frame differs from the C frame";
    return false;
  }
  return true;
}

const DemoSection kSection = {"color_correction", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

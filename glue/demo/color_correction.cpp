// tiershade demo: the colour-correction section of `tiershade demo`: one frame
// (scenes/probe_chart.gltf: mirror spheres of two HDR probes above a colour chart, rendered by the
// scene renderer) without and with two colour corrections, Source-style 32^3 LUTs baked with
// OpenColorIO from the colourist-style .cube files of scenes/luts: day for night, desaturation,
// and the two blended 50/50 (talk: "Color Correction").
// The frame is the C fallback's; the scene is also rendered on every GL backend, each GL frame
// checked against the C twins on GL's own inputs. GLES 2.0 renders the ps20 atlas variant, the
// other APIs the ps2b 3D-texture variant; every GL frame is compared bit for bit with the C twin,
// and each corrected frame with OpenColorIO's CPU processor applied to the frame directly
// (CIEDE2000).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "families/color_correction_inputs.h"
#include "demo/color_correction_scene.h"
#include "demo/section_util.h"
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

// The scene on each GL backend, against the C twins run on GL's own G-buffer and lit frame.
// The frame corrected below is the C fallback's: GL interpolates the vertex attributes its own
// way (the mirrors magnify a last-bit difference in a normal), and GLES samples cube maps NEAREST.
int check_scene_on_gl(const DemoOptions &opt, const ImageF &c_frame, std::string *err) {
  printf("%-16s %-28s %-28s %s\n", "scene on", "lit: GL = C twin (pixels)", "post: GL = C twin (channels)",
         "display differs from the C fallback's");
  int failures = 0;
  for (const BackendApi &b : opt.configs) {
    SceneRenderConfig cfg;
    cfg.w = c_frame.w;
    cfg.h = c_frame.h;
    cfg.backend = b.backend;
    cfg.api = b.api;
    cfg.check = true;
    ImageF gl;
    SceneRenderResult res;
    std::string note;
    if (!cc_scene_frame(cfg, &gl, &res, &note, err)) {
      *err = config_tag(b) + ": " + *err;
      return -1;
    }
    long differ = 0;
    int max_codes = 0;
    for (size_t p = 0; p < gl.rgba.size(); p += 4) {
      int d = 0;
      for (int k = 0; k < 3; ++k)
        d = std::max(d, static_cast<int>(std::lround(std::fabs(gl.rgba[p + k] - c_frame.rgba[p + k]) * 255)));
      differ += d > 0;
      max_codes = std::max(max_codes, d);
    }
    char lit[64], post[64];
    snprintf(lit, sizeof lit, "%ld of %ld differ", res.check_mismatched, res.check_pixels);
    snprintf(post, sizeof post, "%ld of %ld differ", res.check_post_mismatched, res.check_post_channels);
    printf("%-16s %-28s %-28s %ld of %zu pixels, at most %d codes\n", config_tag(b).c_str(), lit, post, differ,
           gl.rgba.size() / 4, max_codes);
    if (res.check_mismatched != 0 || res.check_post_mismatched != 0) ++failures;
  }
  return failures;
}

bool run(const DemoOptions &opt, std::string *err) {
  // The scene's view is square (it keeps square pixels: a wider frame would only add wall).
  const int size = std::max(32, std::min(opt.w, opt.h));
  ImageF frame;
  std::string note;
  double frame_ms = 0;
  if (!cc_frame_c(size, &frame, &note, err, &frame_ms)) return false;
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
  printf("frame: %s, %dx%d in %.0f ms; LUTs %d^3 baked with OpenColorIO from %s and %s\n", note.c_str(), frame.w,
         frame.h, frame_ms, kLutEdge, ex[0].file.c_str(), ex[1].file.c_str());
  int failures = check_scene_on_gl(opt, frame, err);
  if (failures < 0) return false;

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
  printf("\n%-14s %-16s %-50s %10s %10s %16s\n", "correction", "backend", "variant", "mismatched", "max ULP",
         "dE00 vs OCIO max/mean");
  for (int p = 0; p < 3; ++p) {
    double mx, mean;
    cc_frame_difference(cpu3d[p], ref[p], &mx, &mean);
    printf("%-14s %-16s %-50s %10s %10s %8.3f/%.4f\n", kPanels[p].name, "cpu", kVariant3D, "-", "-", mx, mean);
  }
  const bool gl_ok = for_each_gl_config(
      opt,
      [&](const BackendApi &cfg, const std::string &tag, GlRenderer &r) {
        const bool es2 = cfg.api == Api::GLES2;
        const Variant &v = es2 ? vatlas : v3d;
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
          DiffStats st;
          const ImageF diff = diff_image(gl, es2 ? cpuatlas[p] : cpu3d[p], &st);
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
          if (st.mismatched_pixels) ++failures;
        }
        gl_frame_release(r, &fp);
        return true;
      },
      err);
  if (!gl_ok) return false;
  // Side by side: original | day for night | desaturate | blend.
  if (!write_png(base + ".png", hstack({&frame, &cpu3d[0], &cpu3d[1], &cpu3d[2]}, 4, 1.f), Encode::Linear, err))
    return false;
  printf("wrote %s_*.png, *.exr; side by side: %s.png (original | day for night | desaturate | 50/50 blend)\n",
         base.c_str(), base.c_str());
  return demo_section_result(failures, "GL frames differ from the C twins", err);
}

const DemoSection kSection = {"color_correction", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

// tiershade bench: the colour-correction section of `tiershade bench` (docs/accuracy_cost.md):
// for LUT edges 16, 32 and 64, hardware against shader trilinear filtering, 3D texture
// against the ES2 atlas: the error against OpenColorIO's own CPU processor applied to the
// frame (CIEDE2000 max and mean) and llvmpipe's time per frame (median of the runs; ratios
// are to the 32^3 hardware 3D row of the same run). Not a test: nothing passes or fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "budget/budget.h"
#include "families/color_correction_inputs.h"
#include "demo/color_correction_scene.h"
#include "color/ciede2000.h"
#include "conform/family_frame.h"
#include "gl/context.h"
#include "shaderlib/variants.h"
#include "base/image_diff.h"
#include "base/stats.h"

namespace {

struct Row {
  int n;
  int atlas, shader;  // LUT_ATLAS, SHADER_TRILINEAR
  bool raw8;  // the LUT quantised to 8 bits (Source .raw storage)
  // measured
  BudgetCounts slots;
  double de_max = 0, de_mean = 0, model_max = 0, model_mean = 0, ms = 0;
  long mismatched = -1;
};

std::string variant_name(int atlas, int shader, int lookups) {
  return std::string(atlas ? "ps20" : "ps2b") + ":LUT_ATLAS=" + std::to_string(atlas) +
      ",SHADER_TRILINEAR=" + std::to_string(shader) + ",NUM_LOOKUPS=" + std::to_string(lookups);
}

// GPU-style hardware filtering, modelled in double: the trilinear (3D) or bilinear (atlas
// slice) weights rounded to 1/256, i.e. 8 fractional bits of sub-texel precision as many
// GPU texture units have (OpenColorIO issue #1763). The atlas's blue lerp is shader math
// (full precision). Same texel-centre addressing as the shader.
void model_8bit_weights(const Lut3D &l, bool atlas, const float c_in[3], double out[3]) {
  const int n = l.n;
  double p[3], f[3];
  int i0[3], i1[3];
  for (int k = 0; k < 3; ++k) {
    const double c = std::min(1.0, std::max(0.0, static_cast<double>(c_in[k])));
    p[k] = c * (n - 1);
    i0[k] = std::min(n - 1, static_cast<int>(std::floor(p[k])));
    i1[k] = std::min(n - 1, i0[k] + 1);
    f[k] = p[k] - i0[k];
    if (k < 2 || !atlas) f[k] = std::round(f[k] * 256.0) / 256.0;
  }
  for (int ch = 0; ch < 3; ++ch) {
    auto t = [&](int r, int g, int b) { return static_cast<double>(l.at(r, g, b)[ch]); };
    auto lerp = [](double a, double b, double w) { return a + (b - a) * w; };
    const double s0 = lerp(lerp(t(i0[0], i0[1], i0[2]), t(i1[0], i0[1], i0[2]), f[0]),
                           lerp(t(i0[0], i1[1], i0[2]), t(i1[0], i1[1], i0[2]), f[0]), f[1]);
    const double s1 = lerp(lerp(t(i0[0], i0[1], i1[2]), t(i1[0], i0[1], i1[2]), f[0]),
                           lerp(t(i0[0], i1[1], i1[2]), t(i1[0], i1[1], i1[2]), f[0]), f[1]);
    out[ch] = std::min(1.0, std::max(0.0, lerp(s0, s1, f[2])));
  }
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  const int size = opt.size;
  ImageF frame;  // the scene's display frame by the C fallback, before colour correction
  std::string note;
  if (!cc_frame_c(size, &frame, &note, err)) return false;
  std::vector<CcExample> ex;
  if (!cc_examples(&ex, err)) return false;
  std::vector<ShaderDecl> decls;
  if (!load_shader_decls(&decls, err)) return false;
  const ShaderFamily *fam = find_family("color_correction");
  if (!fam) {
    *err = "color_correction family not registered";
    return false;
  }
  const CcExample &main_ex = ex[0];  // day for night
  const ImageF ref = cc_apply_reference(main_ex.transform, frame);
  const float w1[4] = {1, 0, 0, 0};
  // A frame costs tens of ms: at least 21 draws per median (the machine may be shared).
  const int draws = std::max(opt.runs, 21);

  // Every timed program lives in one OSMesa GL 3.3 context; after the first (JIT) draw of
  // each, the draws go round-robin, one per program per round, so that a change of machine
  // load during the run moves every row alike and the ratios stay comparable.
  std::string cerr;
  auto ctx = GlContext::create(Backend::OSMesa, Api::GL33, &cerr);
  if (!ctx) {
    *err = "OSMesa GL 3.3: " + cerr;
    return false;
  }
  GlRenderer renderer(*ctx);
  struct Timed {
    GlFrameProgram fp;
    FamilyInputs in;
    std::vector<double> ms;
    double *out;
  };
  std::vector<std::unique_ptr<Timed>> timed;
  auto add_timed = [&](const Variant &v, FamilyInputs in, ImageF *img, double *out) -> bool {
    auto t = std::make_unique<Timed>();
    t->in = std::move(in);
    t->out = out;
    if (!gl_frame_setup(renderer, Api::GL33, *fam, v, t->in, &t->fp, err)) return false;
    double ms = 0;
    if (!gl_frame_draw(renderer, t->fp, t->in, img, &ms, err)) return false;  // JIT, not timed
    timed.push_back(std::move(t));
    return true;
  };
  std::vector<Row> rows;
  for (int n : {16, 32, 64})
    for (int atlas : {0, 1})
      for (int shader : {0, 1}) rows.push_back({n, atlas, shader, false, {}});
  rows.push_back({32, 0, 0, true, {}});
  for (Row &row : rows) {
    Lut3D lut;
    if (!bake_lut(main_ex.transform, row.n, &lut, err)) return false;
    if (row.raw8)
      for (float &x : lut.rgb) x = static_cast<float>(std::lround(std::min(1.f, std::max(0.f, x)) * 255.f)) / 255.f;
    Variant v;
    if (!find_variant(decls, "color_correction", variant_name(row.atlas, row.shader, 1), &v, err)) return false;
    Assembled fs;
    std::string berr;
    if (!assemble(v.shader->fragment, Target::GLSL330, Stage::Fragment, variant_defines(v, InputMode::Production), &fs,
                  &berr) ||
        !budget_count_fragment(fs.text, &row.slots, &berr))
      fprintf(stderr, "bench color_correction: slots of %s: %s\n", v.name().c_str(), berr.c_str());
    FamilyInputs in;
    cc_frame_inputs(frame, w1, 0, row.n, &in);
    cc_set_luts(&in, {&lut}, !row.shader);  // shader filtering binds NEAREST (docs/color_correction.md)
    ImageF gl, cpu;
    if (!add_timed(v, in, &gl, &row.ms)) return false;
    cpu_render_frame(*fam, v, in, &cpu);
    row.mismatched = 0;
    for (size_t i = 0; i < gl.rgba.size(); ++i)
      if (ulp_distance(gl.rgba[i], cpu.rgba[i]) != 0) ++row.mismatched;
    cc_frame_difference(gl, ref, &row.de_max, &row.de_mean);
    if (row.shader) {
      row.model_max = row.de_max;
      row.model_mean = row.de_mean;
    } else {
      double s = 0, m = 0;
      const size_t np = static_cast<size_t>(frame.w) * frame.h;
      for (size_t i = 0; i < np; ++i) {
        double o[3];
        model_8bit_weights(lut, row.atlas != 0, &frame.rgba[i * 4], o);
        const float *q = &ref.rgba[i * 4];
        const double d = ciede2000(srgb_to_lab(o[0], o[1], o[2]), srgb_to_lab(q[0], q[1], q[2]));
        m = std::max(m, d);
        s += d;
      }
      row.model_max = m;
      row.model_mean = s / static_cast<double>(np);
    }
    fprintf(stderr, "bench: color_correction %d^3 %s %s%s: dE00 max %.3f mean %.4f\n", row.n,
            row.atlas ? "atlas" : "3D", row.shader ? "shader" : "hardware", row.raw8 ? " 8-bit" : "", row.de_max,
            row.de_mean);
  }

  // The three example transforms at Source's 32^3, hardware 3D.
  struct TRow {
    std::string name, file;
    double de_max, de_mean;
  };
  std::vector<TRow> trows;
  {
    Variant v;
    if (!find_variant(decls, "color_correction", variant_name(0, 0, 1), &v, err)) return false;
    for (const CcExample &e : ex) {
      Lut3D lut;
      if (!bake_lut(e.transform, 32, &lut, err)) return false;
      FamilyInputs in;
      cc_frame_inputs(frame, w1, 0, 32, &in);
      cc_set_luts(&in, {&lut}, true);
      ImageF cpu;
      cpu_render_frame(*fam, v, in, &cpu);  // = the GL frame (GL = C, table above)
      TRow t{e.name, e.file, 0, 0};
      cc_frame_difference(cpu, cc_apply_reference(e.transform, frame), &t.de_max, &t.de_mean);
      trows.push_back(t);
    }
  }
  // Blending cost: 0..4 LUTs of 32^3.
  struct LRow {
    int lookups;
    double hw_ms, shader_ms;
  };
  std::vector<LRow> lrows;
  lrows.reserve(5);
  {
    std::vector<Lut3D> luts(4);
    for (int i = 0; i < 4; ++i)
      if (!bake_lut(ex[i % ex.size()].transform, 32, &luts[i], err)) return false;
    const float w[4] = {0.25f, 0.25f, 0.25f, 0.25f};
    for (int k = 0; k <= 4; ++k) {
      lrows.push_back({k, 0, 0});
      LRow &lr = lrows.back();  // stable: reserved above
      for (int shader : {0, 1}) {
        if (k == 0 && shader) continue;  // no LUT: one program (copied after timing)
        Variant v;
        if (!find_variant(decls, "color_correction", variant_name(0, shader, k), &v, err)) return false;
        FamilyInputs in;
        cc_frame_inputs(frame, w, 0, 32, &in);
        cc_set_luts(&in, {&luts[0], &luts[1], &luts[2], &luts[3]}, !shader);
        ImageF gl;
        if (!add_timed(v, in, &gl, shader ? &lr.shader_ms : &lr.hw_ms)) return false;
      }
    }
  }

  // Timing: round-robin over every program, then the median of each.
  for (int round = 0; round < draws; ++round) {
    for (auto &t : timed) {
      ImageF img;
      double ms = 0;
      if (!gl_frame_draw(renderer, t->fp, t->in, &img, &ms, err)) return false;
      t->ms.push_back(ms);
    }
  }
  for (auto &t : timed) {
    *t->out = median(t->ms);
    gl_frame_release(renderer, &t->fp);
  }
  lrows[0].shader_ms = lrows[0].hw_ms;
  double base_ms = 0;
  for (const Row &r : rows)
    if (r.n == 32 && !r.atlas && !r.shader && !r.raw8) base_ms = r.ms;

  std::ostringstream o;
  char b[512];
  o << "## color_correction (Source colour correction), " << size << "x" << size << " frame\n\n"
    << "Frame: " << note << ". Correction: `" << main_ex.file
    << "` (the day-for-night look of `scenes/luts/looks.ocio`, as a colourist's 17^3 .cube), read by\n"
    << "OpenColorIO's FileTransform (trilinear) and baked into an N^3 LUT at the lattice nodes; one LUT, weight 1,\n"
    << "default weight 0 (docs/color_correction.md).\n\n"
    << "- **dE00**: CIEDE2000 between the llvmpipe frame and OpenColorIO's CPU processor applied to the frame\n"
    << "  itself (OPTIMIZATION_LOSSLESS, output clamped to [0, 1] like the shader), max and mean over every pixel.\n"
    << "  A dE00 of 1 is about one just-noticeable difference.\n"
    << "- **modelled 8-bit weights**: the same LUT filtered in double with the hardware filter weights rounded to\n"
    << "  1/256, as GPUs with 8 fractional bits of sub-texel precision do (OpenColorIO issue #1763). A model, not a\n"
    << "  measurement: llvmpipe filters RGBA32F in float, so its hardware rows equal its shader rows to rounding.\n"
    << "  Shader-filtered rows compute the weights in float on any GPU: the column repeats the measurement.\n"
    << "- **ms**: llvmpipe (OSMesa GL 3.3), median of " << draws
    << " draws, glFinish included, the draws of all programs taken round-robin (so that load changes\n"
    << "  during the run move every row alike); **x**: ratio to the 32^3 hardware 3D row\n"
    << "  of the same run. **GL = C**: channels where llvmpipe and the C twin differ (0 = bit-exact frame).\n\n"
    << "| LUT edge | storage | filtering | variant | slots alu+tex | dE00 max | dE00 mean | modelled 8-bit weights: "
       "max / mean | ms | x | GL = C |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row &r : rows) {
    snprintf(
        b, sizeof b, "| %d%s | %s | %s | `%s` | %d+%d | %.3f | %.4f | %s | %.2f | %.2f | %ld |\n", r.n,
        r.raw8 ? " (8-bit, Source .raw)" : "", r.atlas ? "2D atlas" : "3D texture",
        r.shader ? "shader (8 taps)" : (r.atlas ? "hardware bilinear x2 + lerp" : "hardware trilinear"),
        variant_name(r.atlas, r.shader, 1).c_str(), r.slots.alu, r.slots.tex, r.de_max, r.de_mean,
        r.shader
            ? "= measured"
            : (std::to_string(r.model_max).substr(0, 5) + " / " + std::to_string(r.model_mean).substr(0, 6)).c_str(),
        r.ms, base_ms > 0 ? r.ms / base_ms : 0, r.mismatched);
    o << b;
  }
  o << "\nThe example corrections at Source's 32^3 (hardware 3D), against OpenColorIO on the same frame:\n\n"
    << "| correction | source | dE00 max | dE00 mean |\n|---|---|---|---|\n";
  for (const TRow &t : trows) {
    snprintf(b, sizeof b, "| %s | `%s` | %.3f | %.4f |\n", t.name.c_str(), t.file.c_str(), t.de_max, t.de_mean);
    o << b;
  }
  o << "\nBlending cost, 32^3 3D LUTs (weights 0.25 each), llvmpipe ms per frame:\n\n"
    << "| LUTs | hardware trilinear | shader trilinear |\n|---|---|---|\n";
  for (const LRow &l : lrows) {
    snprintf(b, sizeof b, "| %d | %.2f | %.2f |\n", l.lookups, l.hw_ms, l.shader_ms);
    o << b;
  }
  o << "\nReading the tables: docs/color_correction.md, \"Demo and benchmark\" (what the numbers say).\n";
  *md = o.str();
  return true;
}

const BenchSection kSection = {"color_correction", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

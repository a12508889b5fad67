// tiershade cli: `bench` subcommand: accuracy against time, measured in one run, written
// to docs/accuracy_cost.md (+ SVG plots). Timings are medians; comparisons are ratios
// of numbers measured in the same run. Not a test: nothing here passes or fails.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "shaderlib/assembler.h"
#include "budget/budget.h"
#include "conform/family_frame.h"
#include "demo/scene_files.h"
#include "cli/select_args.h"
#include "base/image_diff.h"
#include "base/stats.h"
#include "base/srgb.h"
#include "io/atomic_file.h"
#include "scene/deferred.h"
#include "scene/scene.h"

namespace {

struct BenchRow {
  const char *label;
  const char *variant;
  const char *precision;  // float precision of the GLSL (mediump only matters on GLES)
  bool c_twin;  // the C twin models this row (not for mediump)
  const char *what;
  // measured
  BudgetCounts slots;
  double gl_ms = 0, gles_ms = 0, cold_ms = 0, c_ms = 0, c1_ms = 0;
  double err_max = 0, err_mean = 0, err_frac = 0, round_max = 0;
  long gl_vs_c_mismatch = -1;
};

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double srgb(double x) { return srgb_encode_clamped(x); }

// Display value (sRGB-encoded, [0,1]) of a variant's output channel.
double display(int output_mode, double v) { return output_mode == 0 ? srgb(v) : std::min(1.0, std::max(0.0, v)); }

struct Context {
  std::vector<ShaderDecl> decls;
  const ShaderFamily *fam = nullptr;
  int n = 1024, runs = 7;
  unsigned cores = 1;
};

// Measures every row on the deferred frames of `scene` (cx.n x cx.n, at the row's tier; all_features:
// scene_deferred_frame's); ref_display holds the reference's display rgb per pixel. The mediump
// row's rounding is measured against the row before it (its highp twin).
bool measure_rows(const Context &cx, const Scene &scene, bool all_features, const std::vector<double> &ref_display,
                  std::vector<BenchRow> *rows, std::string *err) {
  ImageF prev_gles;
  for (BenchRow &row : *rows) {
    Variant v;
    if (!find_variant(cx.decls, "model_lighting", row.variant, &v, err)) return false;
    SceneDeferredFrame frame;
    if (!scene_deferred_frame(scene, v.tier, cx.n, cx.n, &frame, err, all_features)) return false;
    Assembled fs;
    std::string e;
    if (!assemble(v.shader->fragment, Target::GLSL330, Stage::Fragment, variant_defines(v, InputMode::Production), &fs,
                  &e) ||
        !budget_count_fragment(fs.text, &row.slots, &e))
      fprintf(stderr, "tiershade bench: slots of %s: %s\n", row.variant, e.c_str());
    const int om = v.value("OUTPUT_MODE");

    ImageF gl_img, gles_img;
    struct Cfg {
      Backend b;
      Api api;
      double *ms;
      ImageF *img;
    };
    std::vector<Cfg> cfgs = {{Backend::EGL, Api::GLES3, &row.gles_ms, &gles_img}};
    if (row.c_twin) cfgs.insert(cfgs.begin(), {Backend::OSMesa, Api::GL33, &row.gl_ms, &gl_img});
    for (const Cfg &c : cfgs) {
      auto ctx = GlContext::create(c.b, c.api, err);
      if (!ctx) return false;
      GlRenderer r(*ctx);
      GlFrameProgram fp;
      FamilyInputs in = frame.in;
      const double t0 = now_ms();
      if (!gl_frame_setup(r, c.api, *cx.fam, v, in, &fp, err, row.precision)) return false;
      double ms = 0;
      if (!gl_frame_draw(r, fp, in, c.img, &ms, err)) return false;
      if (c.ms == &row.gl_ms || !row.c_twin) row.cold_ms = now_ms() - t0;
      std::vector<double> t;
      for (int i = 0; i < cx.runs; ++i) {
        if (!gl_frame_draw(r, fp, in, c.img, &ms, err)) return false;
        t.push_back(ms);
      }
      *c.ms = median(t);
      gl_frame_release(r, &fp);
    }
    const ImageF &img = row.c_twin ? gl_img : gles_img;
    if (row.c_twin) {
      ImageF cpu;
      std::vector<double> t, t1;
      for (int i = 0; i < cx.runs; ++i) {
        const double t0 = now_ms();
        cpu_render_frame(*cx.fam, v, frame.in, &cpu, static_cast<int>(cx.cores));
        t.push_back(now_ms() - t0);
      }
      for (int i = 0; i < std::max(1, cx.runs / 2); ++i) {
        const double t0 = now_ms();
        cpu_render_frame(*cx.fam, v, frame.in, &cpu, 1);
        t1.push_back(now_ms() - t0);
      }
      row.c_ms = median(t);
      row.c1_ms = median(t1);
      row.gl_vs_c_mismatch = 0;
      for (size_t p = 0; p < cpu.rgba.size(); ++p)
        if (frame.hit[p / 4] && ulp_distance(cpu.rgba[p], gl_img.rgba[p]) != 0) ++row.gl_vs_c_mismatch;
      // Arithmetic precision alone: the same variant in float32 against itself in double.
      std::vector<double> dbl;
      cpu_render_frame_double(*cx.fam, v, frame.in, &dbl, static_cast<int>(cx.cores));
      for (size_t p = 0; p < frame.hit.size(); ++p)
        if (frame.hit[p])
          for (int c = 0; c < 3; ++c)
            row.round_max = std::max(row.round_max,
                                     255 * std::fabs(display(om, cpu.rgba[p * 4 + c]) - display(om, dbl[p * 4 + c])));
    } else if (prev_gles.rgba.size() == gles_img.rgba.size()) {
      for (size_t p = 0; p < frame.hit.size(); ++p)
        if (frame.hit[p])
          for (int c = 0; c < 3; ++c)
            row.round_max = std::max(
                row.round_max,
                255 * std::fabs(display(om, gles_img.rgba[p * 4 + c]) - display(om, prev_gles.rgba[p * 4 + c])));
    }
    prev_gles = gles_img;
    double sum = 0;
    long off = 0, hits = 0;
    for (size_t p = 0; p < frame.hit.size(); ++p) {
      if (!frame.hit[p]) continue;
      ++hits;
      for (int c = 0; c < 3; ++c) {
        const double e2 = 255 * std::fabs(display(om, img.rgba[p * 4 + c]) - ref_display[p * 3 + c]);
        row.err_max = std::max(row.err_max, e2);
        sum += e2;
        if (e2 > 1.0) ++off;
      }
    }
    row.err_mean = sum / (3.0 * std::max(1L, hits));
    row.err_frac = 100.0 * off / (3.0 * std::max(1L, hits));
    fprintf(stderr, "bench: %-14s gl %.2f ms, gles %.2f ms, C %.2f ms, err max %.2f mean %.3f\n", row.label, row.gl_ms,
            row.gles_ms, row.c_ms, row.err_max, row.err_mean);
  }
  return true;
}

std::string fmt(double v, const char *f = "%.2f") {
  char b[64];
  snprintf(b, sizeof b, f, v);
  return b;
}

std::string table(const std::vector<BenchRow> &rows, size_t base, unsigned cores) {
  std::ostringstream md;
  md << "| row | what it does | slots alu+tex | llvmpipe ms (GL 3.3) | llvmpipe ms (GLES 3.0) | x " << rows[base].label
     << " time | cold first frame ms | C ms (" << cores
     << " thr) | C ms (1 thr) | C / llvmpipe | error max | error mean | >1 code | rounding max | GL = C |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow &r : rows) {
    const double t = r.c_twin ? r.gl_ms : r.gles_ms;
    const double tb = r.c_twin ? rows[base].gl_ms : rows[base].gles_ms;
    md << "| " << r.label << " | " << r.what << " | " << r.slots.alu << "+" << r.slots.tex << " | "
       << (r.c_twin ? fmt(r.gl_ms) : "-") << " | " << fmt(r.gles_ms) << " | " << (tb > 0 ? fmt(t / tb) : "-") << " | "
       << fmt(r.cold_ms, "%.0f") << " | " << (r.c_twin ? fmt(r.c_ms) : "-") << " | " << (r.c_twin ? fmt(r.c1_ms) : "-")
       << " | " << (r.c_twin && r.gl_ms > 0 ? fmt(r.c_ms / r.gl_ms) : "-") << " | " << fmt(r.err_max) << " | "
       << fmt(r.err_mean, "%.3f") << " | " << fmt(r.err_frac) << "% | " << fmt(r.round_max, "%.4f") << " | "
       << (r.gl_vs_c_mismatch < 0 ? "-" : std::to_string(r.gl_vs_c_mismatch)) << " |\n";
  }
  return md.str();
}

// SVG: mean error (y) against llvmpipe GLES time (x), one labelled point per row.
std::string plot(const std::vector<BenchRow> &rows, int n) {
  std::ostringstream svg;
  const int W = 560, H = 320, L = 60, B = 40;
  double tmax = 0, emax = 0;
  for (const BenchRow &r : rows) {
    tmax = std::max(tmax, r.gles_ms);
    emax = std::max(emax, r.err_mean);
  }
  tmax = tmax > 0 ? tmax * 1.2 : 1;
  emax = emax > 0 ? emax * 1.2 : 1;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << "<line x1='" << L << "' y1='" << H - B << "' x2='" << W - 20 << "' y2='" << H - B << "' stroke='black'/>\n"
      << "<line x1='" << L << "' y1='20' x2='" << L << "' y2='" << H - B << "' stroke='black'/>\n"
      << "<text x='" << (W / 2) << "' y='" << H - 8 << "' text-anchor='middle'>llvmpipe ms per " << n << "x" << n
      << " frame (GLES 3.0, median)</text>\n<text x='14' y='" << H / 2 << "' transform='rotate(-90 14 " << H / 2
      << ")' text-anchor='middle'>mean error (8-bit codes)</text>\n";
  char b[256];
  for (int i = 0; i <= 4; ++i) {
    const double x = L + (W - 20 - L) * i / 4.0, y = (H - B) - (H - B - 20) * i / 4.0;
    snprintf(
        b, sizeof b,
        "<text x='%.0f' y='%d' text-anchor='middle'>%.1f</text><text x='%d' y='%.0f' text-anchor='end'>%.2f</text>\n",
        x, H - B + 15, tmax * i / 4, L - 4, y + 4, emax * i / 4);
    svg << b;
  }
  for (const BenchRow &r : rows) {
    const double x = L + (W - 20 - L) * r.gles_ms / tmax, y = (H - B) - (H - B - 20) * r.err_mean / emax;
    snprintf(b, sizeof b, "<circle cx='%.1f' cy='%.1f' r='5' fill='#3366cc'/><text x='%.1f' y='%.1f'>%s</text>\n", x, y,
             x + 8, y - 6, r.label);
    svg << b;
  }
  svg << "</svg>\n";
  return svg.str();
}

bool write_atomic(const std::string &path, const std::string &text) {
  std::string err;
  if (write_file_atomic(path, text, &err)) return true;
  fprintf(stderr, "tiershade bench: %s\n", err.c_str());
  return false;
}

std::string stem(const std::string &path) {
  const size_t dot = path.rfind(".md");
  return dot != std::string::npos ? path.substr(0, dot) : path;
}

std::string basename_of(const std::string &p) {
  const size_t s = p.rfind('/');
  return s == std::string::npos ? p : p.substr(s + 1);
}

}  // namespace

// `tiershade bench --help`.
const char kHelp[] = R"(usage: tiershade bench [-o docs/accuracy_cost.md] [--size N] [--runs K] [--section NAME [--plots DIR]]
--section NAME runs one registered section (e.g. scenes, world_lighting, baking) and prints its
markdown without writing any file (--plots DIR: but the section's SVG plots, into DIR).
Measures, for each tier of each shader family, in one run: instruction slots, llvmpipe
milliseconds per N x N frame (median of K draws; OSMesa GL 3.3 and EGL GLES 3.0), the
cold first frame (compile + JIT, Mesa's shader cache off), the C fallback's milliseconds
per frame (all cores, and one), and the error against the double-precision reference of
the full model (every light local, exact sRGB), in 8-bit display code values.
Writes the markdown tables to -o and SVG plots next to it. Default N = 1024, K = 7.)";

int cmd_bench(int argc, char **argv) {
  Args a("bench", argc, argv, {"--help"}, {"-o", "--size", "--runs", "--section", "--plots"});
  if (a.help(kHelp)) return 0;
  a.no_positional();
  const std::string out_path = a.get("-o", "docs/accuracy_cost.md");
  Context cx;
  cx.n = a.get_int("--size", 1024, 16, 4096);
  cx.runs = a.get_int("--runs", 7, 1, 101);
  cx.cores = std::max(1u, std::thread::hardware_concurrency());
  // Cold compile + JIT for the first-frame column; identical output either way.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  if (a.has("--plots") && !a.has("--section")) a.fail("--plots DIR goes with --section NAME (a full run writes its plots beside -o)");
  if (a.has("--section")) {
    BenchOptions bopt;
    bopt.size = cx.n;
    bopt.runs = cx.runs;
    bopt.plot_dir = a.get("--plots");
    for (const BenchSection *s : bench_sections()) {
      if (a.get("--section") != s->name) continue;
      std::string section, e;
      if (!s->run(bopt, &section, &e)) {
        fprintf(stderr, "tiershade bench: %s: %s\n", s->name, e.c_str());
        return 1;
      }
      printf("%s", section.c_str());
      return 0;
    }
    a.fail("no bench section '" + a.get("--section") + "'");
  }
  std::string err;
  if (!load_shader_decls(&cx.decls, &err)) a.fail(err);
  cx.fam = find_family("model_lighting");
  const int n = cx.n;

  // ---- HL2 model lighting: the sphere grid (scenes/sphere_grid.gltf), six lights ----
  // The frames are the scene renderer's G-buffer of the grid, lights folded for the row's tier.
  Scene grid;
  if (!load_scene(kSphereGridGltf, &grid, &err)) a.fail(err);
  std::vector<BenchRow> hl2 = {
      {"ps20",
       "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,NUM_LIGHTS=2",
       "highp",
       true,
       "2 local lights with per-vertex attenuation, 4 folded into the ambient cube, linear out (sRGB target)",
       {}},
      {"ps2b",
       "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=1,NUM_LIGHTS=4",
       "highp",
       true,
       "4 local lights per pixel, 2 folded, gamma 2.2 in the shader",
       {}},
      {"sm3",
       "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2",
       "highp",
       true,
       "4 local lights in a dynamic loop, 2 folded, exact sRGB in the shader",
       {}},
      {"sm3 mediump",
       "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2",
       "mediump",
       false,
       "the sm3 shader at mediump on GLES 3.0 (llvmpipe computes fp16)",
       {}},
  };
  SceneDeferredFrame ref_frame;
  if (!scene_deferred_frame(grid, Tier::SM3, n, n, &ref_frame, &err, false, true)) a.fail(err);
  std::vector<double> ref_display(ref_frame.reference.size());
  for (size_t i = 0; i < ref_display.size(); ++i) ref_display[i] = srgb(ref_frame.reference[i]);
  if (!measure_rows(cx, grid, false, ref_display, &hl2, &err)) {
    fprintf(stderr, "tiershade bench: %s\n", err.c_str());
    return 1;
  }

  // ---- Episode One Phong: one normal-mapped sphere, four lights (none folded) ----
  std::string note;
  Scene ball;
  if (!load_scene(kPhongSphereGltf, &ball, &err)) a.fail(err);
  note = std::string(kPhongSphereGltf) + ", envmap and ambient cube from the Grace Cathedral probe";
  const char *full =
      "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,ENVMAP=1";
  std::vector<BenchRow> ep1 = {
      {"ps20 (no Phong)",
       "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,NUM_LIGHTS=2",
       "highp",
       true,
       "HL2 lighting: no normal map, no specular; 2 local lights, 2 folded",
       {}},
      {"ps2b Phong",
       "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,NUM_LIGHTS=4",
       "highp",
       true,
       "normal map, exponent map, Fresnel ranges, 4 Phong lights; no rim, no envmap",
       {}},
      {"ps2b full",
       "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,ENVMAP=1,NUM_"
       "LIGHTS=4",
       "highp",
       true,
       "Phong + rim light + envmap, 4 lights as dynamic combos",
       {}},
      {"sm3 full", full, "highp", true, "the same in a dynamic loop over the light count", {}},
  };
  {
    Variant v;
    if (!find_variant(cx.decls, "model_lighting", full, &v, &err)) a.fail(err);
    SceneDeferredFrame frame;
    if (!scene_deferred_frame(ball, Tier::SM3, n, n, &frame, &err, true)) a.fail(err);
    std::vector<double> dbl;
    cpu_render_frame_double(*cx.fam, v, frame.in, &dbl, static_cast<int>(cx.cores));
    ref_display.assign(static_cast<size_t>(n) * n * 3, 0.0);
    for (size_t p = 0; p < frame.hit.size(); ++p)
      for (int c = 0; c < 3; ++c) ref_display[p * 3 + c] = display(2, dbl[p * 4 + c]);
  }
  if (!measure_rows(cx, ball, true, ref_display, &ep1, &err)) {
    fprintf(stderr, "tiershade bench: %s\n", err.c_str());
    return 1;
  }

  const std::string svg1 = stem(out_path) + ".svg", svg2 = stem(out_path) + "_phong.svg";
  std::ostringstream md;
  md << "# Accuracy against cost\n\n"
     << "Written by `make bench` (`tiershade bench`); every number below was measured in one run of the\n"
     << "current code on this machine (" << cx.cores << " cores, Mesa llvmpipe). Do not edit by hand.\n\n"
     << "Columns:\n"
     << "- **slots**: DX9-style instruction slots of the production fragment shader (docs/budget_model.md).\n"
     << "- **llvmpipe ms**: median of " << cx.runs << " draws of a " << n << "x" << n
     << " frame (glFinish included, readback excluded); **cold**:\n"
     << "  the first frame with compile, link and LLVM JIT, Mesa's shader cache off. Frames are deferred-style:\n"
     << "  a per-pixel G-buffer record plus the production uniforms (docs/conformance.md).\n"
     << "- **x ... time**: the row's llvmpipe time over the named row's, measured in the same run.\n"
     << "- **C ms**: the C fallback (the bit-exact float32 twin) on " << cx.cores << " threads and on 1.\n"
     << "- **error**: against the double-precision reference of the full model, in 8-bit display code values\n"
     << "  (sRGB-encoded, x255), over the sphere pixels; **>1 code**: share of channels off by more than one code.\n"
     << "- **rounding max**: the same variant in float32 against itself in double (for mediump: against the\n"
     << "  highp frame), the part of the error that is arithmetic precision, not approximation.\n"
     << "- **GL = C**: channels where llvmpipe and the C twin differ (0 = bit-exact frame).\n\n"
     << "## model_lighting: Half-Life 2 (sphere grid, 15 spheres, 6 lights)\n\n"
     << "Scene: `scenes/sphere_grid.gltf`; the frames are the scene renderer's G-buffer (its C rasteriser,\n"
     << "`scene_deferred_frame`), the lights folded for each row's tier at the grid's centre.\n"
     << "Reference: every light local (none folded), exact sRGB, double precision (`scene_reference_linear`).\n\n"
     << table(hl2, 2, cx.cores) << "\n![error against time](" << basename_of(svg1) << ")\n\n"
     << "The ps20 error is dominated by the four folded lights and the per-vertex attenuation; ps2b's by\n"
     << "the gamma-2.2 curve standing in for sRGB in the darks; sm3 keeps the error of the two folded lights;\n"
     << "mediump adds fp16 rounding (and, on llvmpipe, costs time: the fp16 conversions are not free).\n\n"
     << "## model_lighting: Episode One Phong (one normal-mapped sphere, 4 lights, " << note << ")\n\n"
     << "Reference: the full model (sm3 with Phong, exponent map, rim light and envmap) in double precision.\n\n"
     << table(ep1, 3, cx.cores) << "\n![error against time](" << basename_of(svg2) << ")\n";
  BenchOptions bopt;
  bopt.size = n;
  bopt.runs = cx.runs;
  {  // the sections' plots beside the markdown
    const size_t slash = out_path.rfind('/');
    bopt.plot_dir = slash == std::string::npos ? "." : out_path.substr(0, slash);
  }
  for (const BenchSection *s : bench_sections()) {
    std::string section;
    fprintf(stderr, "bench: %s\n", s->name);
    if (!s->run(bopt, &section, &err)) {
      fprintf(stderr, "tiershade bench: %s: %s\n", s->name, err.c_str());
      return 1;
    }
    md << "\n" << section;
  }
  if (!write_atomic(svg1, plot(hl2, n)) || !write_atomic(svg2, plot(ep1, n)) || !write_atomic(out_path, md.str()))
    return 1;
  printf("%s", md.str().c_str());
  printf("wrote %s, %s and %s\n", out_path.c_str(), svg1.c_str(), svg2.c_str());
  return 0;
}

// tiershade: `bench` subcommand: accuracy against time, measured in one run, written
// to docs/accuracy_cost.md (+ an SVG plot). Timings are medians; comparisons are
// ratios of numbers measured in the same run. Not a test: nothing here passes or fails.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "assembler.h"
#include "budget.h"
#include "frame.h"
#include "scene_spheres.h"
#include "selection.h"

namespace {

struct BenchRow {
  const char *label;
  Tier tier;
  const char *variant;
  int max_local;
  const char *precision;  // float precision of the GLSL (mediump only matters on GLES)
  bool c_twin;            // the C twin models this row (not for mediump)
  const char *what;
  // measured
  BudgetCounts slots;
  double gl_ms = 0, gles_ms = 0, cold_ms = 0, c_ms = 0, c1_ms = 0;
  double err_max = 0, err_mean = 0, err_frac = 0, round_max = 0;
  long gl_vs_c_mismatch = -1;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double srgb(double x) {
  x = std::min(1.0, std::max(0.0, x));
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

// Display value (sRGB-encoded, [0,1]) of a variant's output channel.
double display(int output_mode, double v) { return output_mode == 0 ? srgb(v) : std::min(1.0, std::max(0.0, v)); }

}  // namespace

int cmd_bench(int argc, char **argv) {
  Args a("bench", argc, argv, {"--help"}, {"-o", "--size", "--runs"});
  if (a.flag("--help")) {
    puts("usage: tiershade bench [-o docs/accuracy_cost.md] [--size N] [--runs K]\n"
         "Measures, for each tier of each shader family, in one run: instruction slots, llvmpipe\n"
         "milliseconds per N x N frame (median of K draws; OSMesa GL 3.3 and EGL GLES 3.0), the\n"
         "cold first frame (compile + JIT, Mesa's shader cache off), the C fallback's milliseconds\n"
         "per frame (all cores, and one), and the error against the double-precision reference of\n"
         "the full model (every light local, exact sRGB), in 8-bit display code values.\n"
         "Writes the markdown table to -o and an SVG plot next to it. Default N = 1024, K = 7.");
    return 0;
  }
  if (!a.positional().empty()) a.fail("unexpected argument '" + a.positional()[0] + "'");
  const std::string out_path = a.get("-o", "docs/accuracy_cost.md");
  const int n = a.get_int("--size", 1024, 16, 4096);
  const int runs = a.get_int("--runs", 7, 1, 101);
  // Cold compile + JIT for the first-frame column; identical output either way.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);

  Selection sel;
  std::string err;
  if (!load_shader_decls(&sel.decls, &err)) a.fail(err);
  const ShaderFamily *fam = find_family("model_lighting");
  const SphereScene scene = default_sphere_scene();

  std::vector<BenchRow> rows = {
      {"ps20", Tier::PS20, "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=0,NUM_LIGHTS=2", 2, "highp", true,
       "2 local lights with per-vertex attenuation, 4 folded into the ambient cube, linear out (sRGB target)", {}},
      {"ps2b", Tier::PS2B, "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=1,NUM_LIGHTS=4", 4, "highp", true,
       "4 local lights per pixel, 2 folded, gamma 2.2 in the shader", {}},
      {"sm3", Tier::SM3, "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2", 4, "highp", true,
       "4 local lights in a dynamic loop, 2 folded, exact sRGB in the shader", {}},
      {"sm3 mediump", Tier::SM3, "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2", 4, "mediump", false,
       "the sm3 shader at mediump on GLES 3.0 (llvmpipe computes fp16)", {}},
  };

  SphereFrame ref_frame;
  if (!sphere_frame(scene, n, n, 64, &ref_frame, &err)) a.fail(err);
  std::vector<double> ref;
  sphere_reference_linear(scene, ref_frame, &ref);
  long hits = 0;
  for (uint8_t h : ref_frame.hit) hits += h;

  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  ImageF highp_gles;  // the sm3 highp GLES frame, against which mediump's rounding is measured
  for (BenchRow &row : rows) {
    Variant v;
    if (!find_variant(sel.decls, "model_lighting", row.variant, &v, &err)) a.fail(err);
    SphereFrame frame;
    if (!sphere_frame(scene, n, n, row.max_local, &frame, &err)) a.fail(err);
    Assembled fs;
    if (!assemble(v.shader->fragment, Target::GLSL330, Stage::Fragment, variant_defines(v, InputMode::Production), &fs,
                  &err) ||
        !budget_count_fragment(fs.text, &row.slots, &err))
      fprintf(stderr, "tiershade bench: slots of %s: %s\n", row.variant, err.c_str());

    ImageF gl_img;
    struct Cfg { Backend b; Api api; double *ms; };
    std::vector<Cfg> cfgs = {{Backend::EGL, Api::GLES3, &row.gles_ms}};
    if (row.c_twin) cfgs.insert(cfgs.begin(), {Backend::OSMesa, Api::GL33, &row.gl_ms});
    for (const Cfg &c : cfgs) {
      auto ctx = GlContext::create(c.b, c.api, &err);
      if (!ctx) a.fail(err);
      GlRenderer r(*ctx);
      GlFrameProgram fp;
      const double t0 = now_ms();
      if (!gl_frame_setup(r, c.api, *fam, v, frame.in, &fp, &err, row.precision)) a.fail(err);
      ImageF img;
      double ms = 0;
      if (!gl_frame_draw(r, fp, frame.in, &img, &ms, &err)) a.fail(err);
      if (c.b == Backend::OSMesa || !row.c_twin) row.cold_ms = now_ms() - t0;
      std::vector<double> t;
      for (int i = 0; i < runs; ++i) {
        if (!gl_frame_draw(r, fp, frame.in, &img, &ms, &err)) a.fail(err);
        t.push_back(ms);
      }
      *c.ms = median(t);
      gl_frame_release(r, &fp);
      if (gl_img.rgba.empty()) gl_img = img;
      if (c.b == Backend::EGL && row.tier == Tier::SM3 && row.c_twin) highp_gles = img;
    }
    // C fallback on every core, then on one.
    ImageF cpu;
    if (row.c_twin) {
      std::vector<double> t, t1;
      for (int i = 0; i < runs; ++i) {
        double t0 = now_ms();
        cpu_render_frame(*fam, v, frame.in, &cpu, static_cast<int>(cores));
        t.push_back(now_ms() - t0);
      }
      for (int i = 0; i < std::max(1, runs / 2); ++i) {
        double t0 = now_ms();
        cpu_render_frame(*fam, v, frame.in, &cpu, 1);
        t1.push_back(now_ms() - t0);
      }
      row.c_ms = median(t);
      row.c1_ms = median(t1);
      row.gl_vs_c_mismatch = 0;
      for (size_t p = 0; p < cpu.rgba.size(); ++p)
        if (frame.hit[p / 4] && ulp_distance(cpu.rgba[p], gl_img.rgba[p]) != 0) ++row.gl_vs_c_mismatch;
      // float32 rounding alone: the same variant evaluated in double.
      std::vector<double> dbl;
      cpu_render_frame_double(*fam, v, frame.in, &dbl, static_cast<int>(cores));
      const int om = v.value("OUTPUT_MODE");
      for (size_t p = 0; p < frame.hit.size(); ++p) {
        if (!frame.hit[p]) continue;
        for (int c = 0; c < 3; ++c)
          row.round_max = std::max(row.round_max,
                                   255 * std::fabs(display(om, cpu.rgba[p * 4 + c]) - display(om, dbl[p * 4 + c])));
      }
    }
    const int om = v.value("OUTPUT_MODE");
    if (!row.c_twin && highp_gles.rgba.size() == gl_img.rgba.size()) {
      // No C twin at mediump: its rounding is measured against the highp GL frame.
      for (size_t p = 0; p < frame.hit.size(); ++p) {
        if (!frame.hit[p]) continue;
        for (int c = 0; c < 3; ++c)
          row.round_max = std::max(row.round_max, 255 * std::fabs(display(om, gl_img.rgba[p * 4 + c]) -
                                                                  display(om, highp_gles.rgba[p * 4 + c])));
      }
    }
    // Error against the full-model double reference, in display code values.
    double sum = 0;
    long off = 0;
    for (size_t p = 0; p < frame.hit.size(); ++p) {
      if (!frame.hit[p]) continue;
      for (int c = 0; c < 3; ++c) {
        const double e = 255 * std::fabs(display(om, gl_img.rgba[p * 4 + c]) - srgb(ref[p * 3 + c]));
        row.err_max = std::max(row.err_max, e);
        sum += e;
        if (e > 1.0) ++off;
      }
    }
    row.err_mean = sum / (3.0 * std::max(1L, hits));
    row.err_frac = 100.0 * off / (3.0 * std::max(1L, hits));
    fprintf(stderr, "bench: %-12s gl %.2f ms, gles %.2f ms, C %.2f ms, err max %.2f mean %.3f\n", row.label, row.gl_ms,
            row.gles_ms, row.c_ms, row.err_max, row.err_mean);
  }

  const BenchRow &base = rows[2];  // sm3 highp: the ratios' denominator
  std::ostringstream md;
  md << "# Accuracy against cost\n\n"
     << "Written by `make bench` (`tiershade bench`); every number below was measured in one run of the\n"
     << "current code on this machine (" << cores << " cores, Mesa llvmpipe). Do not edit by hand.\n\n"
     << "## model_lighting (HL2 model lighting), " << n << "x" << n << " frame of the sphere grid\n\n"
     << "Scene: 15 spheres covering " << hits << " pixels, 6 lights (directional, spot, 4 points) and an ambient\n"
     << "cube; lights beyond a tier's limit are folded into the cube (docs/light_folding.md). Frames are\n"
     << "deferred-style: a per-pixel G-buffer record plus the production uniforms (docs/conformance.md).\n\n"
     << "- **slots**: DX9-style instruction slots of the production fragment shader (docs/budget_model.md).\n"
     << "- **llvmpipe ms**: median of " << runs << " draws (glFinish included, readback excluded); **cold**: the\n"
     << "  first frame with compile, link and LLVM JIT, Mesa's shader cache off.\n"
     << "- **C ms**: the C fallback (bit-exact float32 twin) on " << cores << " threads and on 1.\n"
     << "- **error**: against the double-precision reference of the full model (all 6 lights local, exact\n"
     << "  sRGB), in 8-bit display code values (sRGB-encoded, x255), over the sphere pixels; **>1 code**: share\n"
     << "  of channels off by more than one code. **rounding max**: the same variant in float32 against\n"
     << "  itself in double (for mediump: against the highp frame), the part of the error that is\n"
     << "  arithmetic precision, not approximation.\n"
     << "- **GL = C**: channels where llvmpipe and the C twin differ (0 = bit-exact frame).\n\n"
     << "| row | what it does | slots alu+tex | llvmpipe ms (GL 3.3) | llvmpipe ms (GLES 3.0) | x sm3 time | cold first frame ms | C ms (" << cores
     << " thr) | C ms (1 thr) | C / llvmpipe | error max | error mean | >1 code | rounding max | GL = C |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char b[1024];
  for (const BenchRow &r : rows) {
    const double t = r.c_twin ? r.gl_ms : r.gles_ms;
    const double tb = r.c_twin ? base.gl_ms : base.gles_ms;
    snprintf(b, sizeof b, "| %s | %s | %d+%d | %s | %.2f | %.2f | %.0f | %s | %s | %s | %.2f | %.3f | %.2f%% | %s | %s |\n",
             r.label, r.what, r.slots.alu, r.slots.tex, r.c_twin ? std::to_string(r.gl_ms).substr(0, 6).c_str() : "-",
             r.gles_ms, tb > 0 ? t / tb : 0, r.cold_ms, r.c_twin ? std::to_string(r.c_ms).substr(0, 6).c_str() : "-",
             r.c_twin ? std::to_string(r.c1_ms).substr(0, 6).c_str() : "-",
             r.c_twin && r.gl_ms > 0 ? std::to_string(r.c_ms / r.gl_ms).substr(0, 4).c_str() : "-", r.err_max,
             r.err_mean, r.err_frac, std::to_string(r.round_max).substr(0, 6).c_str(),
             r.gl_vs_c_mismatch < 0 ? "-" : std::to_string(r.gl_vs_c_mismatch).c_str());
    md << b;
  }
  md << "\n![error against time](accuracy_cost.svg)\n\n"
     << "Reading the table: the time column ratios and the C/llvmpipe ratios are the comparable numbers;\n"
     << "absolute milliseconds move with the machine's load. The ps20 error is dominated by the four\n"
     << "folded lights and the per-vertex attenuation; ps2b's by the gamma-2.2 curve standing in for sRGB\n"
     << "in the darks; sm3 keeps only the error of the two folded lights; mediump adds fp16 rounding.\n";
  // The other families' sections (glue/bench_*.cpp), measured in the same run.
  BenchOptions bopt;
  bopt.size = n;
  bopt.runs = runs;
  for (const BenchSection *s : bench_sections()) {
    std::string section;
    fprintf(stderr, "bench: %s\n", s->name);
    if (!s->run(bopt, &section, &err)) {
      fprintf(stderr, "tiershade bench: %s: %s\n", s->name, err.c_str());
      return 1;
    }
    md << "\n" << section;
  }

  // SVG: mean error (y) against llvmpipe time (x), one labelled point per row.
  std::ostringstream svg;
  const int W = 560, H = 320, L = 60, B = 40;
  double tmax = 0, emax = 0;
  for (const BenchRow &r : rows) {
    tmax = std::max(tmax, r.gles_ms);
    emax = std::max(emax, r.err_mean);
  }
  tmax = tmax > 0 ? tmax * 1.2 : 1;
  emax = emax > 0 ? emax * 1.2 : 1;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H << "' font-family='sans-serif' font-size='12'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n"
      << "<line x1='" << L << "' y1='" << H - B << "' x2='" << W - 20 << "' y2='" << H - B << "' stroke='black'/>\n"
      << "<line x1='" << L << "' y1='20' x2='" << L << "' y2='" << H - B << "' stroke='black'/>\n"
      << "<text x='" << (W / 2) << "' y='" << H - 8 << "' text-anchor='middle'>llvmpipe ms per " << n << "x" << n
      << " frame (GLES 3.0, median)</text>\n"
      << "<text x='14' y='" << H / 2 << "' transform='rotate(-90 14 " << H / 2
      << ")' text-anchor='middle'>mean error (8-bit codes)</text>\n";
  for (int i = 0; i <= 4; ++i) {
    const double tv = tmax * i / 4, ev = emax * i / 4;
    const double x = L + (W - 20 - L) * i / 4.0, y = (H - B) - (H - B - 20) * i / 4.0;
    snprintf(b, sizeof b, "<text x='%.0f' y='%d' text-anchor='middle'>%.1f</text><text x='%d' y='%.0f' text-anchor='end'>%.2f</text>\n",
             x, H - B + 15, tv, L - 4, y + 4, ev);
    svg << b;
  }
  for (const BenchRow &r : rows) {
    const double x = L + (W - 20 - L) * r.gles_ms / tmax, y = (H - B) - (H - B - 20) * r.err_mean / emax;
    snprintf(b, sizeof b, "<circle cx='%.1f' cy='%.1f' r='5' fill='#3366cc'/><text x='%.1f' y='%.1f'>%s</text>\n", x, y,
             x + 8, y - 6, r.label);
    svg << b;
  }
  svg << "</svg>\n";

  auto write_atomic = [&](const std::string &path, const std::string &text) {
    const std::string tmp = path + ".tmp." + std::to_string(getpid());
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    f.close();
    if (!f || std::rename(tmp.c_str(), path.c_str()) != 0) {
      std::remove(tmp.c_str());
      fprintf(stderr, "tiershade bench: cannot write '%s'\n", path.c_str());
      return false;
    }
    return true;
  };
  std::string svg_path = out_path;
  const size_t dot = svg_path.rfind(".md");
  svg_path = (dot != std::string::npos ? svg_path.substr(0, dot) : svg_path) + ".svg";
  if (!write_atomic(svg_path, svg.str()) || !write_atomic(out_path, md.str())) return 1;
  printf("%s", md.str().c_str());
  printf("wrote %s and %s\n", out_path.c_str(), svg_path.c_str());
  return 0;
}

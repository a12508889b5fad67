// tiershade bench: the scenes section of `tiershade bench` (docs/accuracy_cost.md): for each
// shipped scene at 1280x720, what the variant selection saves (variants and compile time
// against every combo of the families used), the frame time on llvmpipe per tier and HDR
// path, the C fallback's frame time and its ratio to llvmpipe's (same run), the first frame
// with Mesa's shader cache off, and the peak memory of `tiershade render`.
// Not a test: nothing here passes or fails.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "conform/conform.h"
#include "families/family.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/frame.h"
#include "base/stats.h"

#include "bench/table_format.h"

namespace {

using bench::Clock;
using bench::f1;
using bench::f2;
using bench::ms_since;

const int kW = 1280, kH = 720;
const char *kScenes[] = {"scenes/model_lighting.gltf", "scenes/world_lighting.gltf", "scenes/hdr_atrium.gltf"};

// This executable's path, for running `tiershade render` as a child.
bool self_exe(std::string *exe, std::string *err) {
  char buf[4096];
  const ssize_t len = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (len <= 0) {
    *err = "cannot find this executable (/proc/self/exe)";
    return false;
  }
  exe->assign(buf, static_cast<size_t>(len));
  return true;
}

// Runs a `tiershade render ... --report-memory` command line and reads the peak resident memory
// (MiB) it reports (VmHWM: wait4's ru_maxrss would carry this large process's high-water mark
// across the exec). False unless the command ran, exited 0 and reported it.
bool run_render_child(const std::string &cmd, const std::string &scene, double *mib, std::string *err) {
  fflush(stdout);
  *mib = -1;
  FILE *p = popen(cmd.c_str(), "r");
  if (p) {
    char line[512];
    while (fgets(line, sizeof line, p)) sscanf(line, "peak memory: %lf MiB", mib);
  }
  if (!p || pclose(p) != 0 || *mib < 0) {
    *err = "tiershade render " + scene + " failed or did not report its memory (" + cmd + ")";
    return false;
  }
  return true;
}

// Peak resident memory (MiB) of a `tiershade render` child process, as it reports it.
bool child_peak_mib(const std::vector<std::string> &args, double *mib, std::string *err) {
  std::string cmd;
  if (!self_exe(&cmd, err)) return false;
  cmd = "'" + cmd + "'";
  for (const std::string &a : args) cmd += " '" + a + "'";
  return run_render_child(cmd + " --report-memory 2>/dev/null", args[1], mib, err);
}

// The first frame as a user gets it: the wall time of a fresh `tiershade render` process with
// an empty shader-cache directory (cold), warm-up on or off, from its start to its exit: process
// start, scene loaded, draws prepared, variants compiled, first frame with JIT, EXR and PNG
// written. One process is noisy (JIT threads, page faults), so the median of 3, each with its
// own empty cache.
bool child_first_frame_once(const std::string &exe, const std::string &scene, Tier tier, const std::string &hdr,
                            bool warmup, double *ms, double *peak_mib, std::string *err) {
  char dir[] = "/tmp/tiershade_cold_cache_XXXXXX";
  if (!mkdtemp(dir)) {
    *err = "mkdtemp failed";
    return false;
  }
  const std::string out = std::string(dir) + "/frame";
  const std::string cmd = std::string("exec env -u MESA_SHADER_CACHE_DISABLE MESA_SHADER_CACHE_DIR='") + dir +
      "/cache' " + (warmup ? "" : "TIERSHADE_NO_WARMUP=1 ") + "'" + exe + "' render '" + scene + "' --tier " +
      tier_name(tier) + " --hdr " + hdr + " --size 1280x720 --quiet --report-memory -o '" + out + "' 2>/dev/null";
  const auto t0 = Clock::now();
  const bool ok = run_render_child(cmd, scene, peak_mib, err);
  *ms = ms_since(t0);
  const std::string rm = std::string("rm -rf '") + dir + "'";
  if (system(rm.c_str()) != 0) {}
  return ok;
}

// Median wall time of 3 cold processes; the largest peak memory of the 3.
bool child_first_frame_ms(const std::string &scene, Tier tier, const std::string &hdr, bool warmup, double *ms,
                          double *peak_mib, std::string *err) {
  std::string exe;
  if (!self_exe(&exe, err)) return false;
  std::vector<double> t(3);
  *peak_mib = 0;
  for (double &v : t) {
    double mib = 0;
    if (!child_first_frame_once(exe, scene, tier, hdr, warmup, &v, &mib, err)) return false;
    *peak_mib = std::max(*peak_mib, mib);
  }
  *ms = median(t);
  return true;
}

struct Row {
  std::string scene, tier, hdr;
  int variants = 0, combos = 0;
  double compile_sel = 0, compile_all = 0;
  double first_ms = 0, first_nowarm_ms = 0;  // a fresh process, empty shader cache, warm-up on / off
  double peak_mib = 0;  // that process's VmHWM (warm-up on)
  double gl_frame = 0, gl_lit = 0;  // medians of warm frames
  double c_frame = 0, c_lit = 0;
  double uber_frame = 0, uber_lit = 0;  // llvmpipe, every feature compiled in (no selection)
};

bool compile_all_ms(const SceneSelection &sel, double *ms, std::string *err) {
  auto ctx = GlContext::create(Backend::EGL, Api::GLES3, err);
  if (!ctx) return false;
  GlRenderer r(*ctx);
  const auto t0 = Clock::now();
  for (const Variant *v : sel.all_variants) {
    const GLuint p = build_production_program(r, Api::GLES3, *v, err);
    if (!p) return false;
    r.delete_program(p);
  }
  ctx->gl().Finish();
  *ms = ms_since(t0);
  return true;
}

bool measure(const Scene &s, Tier tier, const std::string &hdr, int runs, Row *row, std::string *err) {
  SceneSelection sel;
  if (!select_scene_variants(s, tier, hdr, &sel, err)) return false;
  row->variants = static_cast<int>(sel.variants.size());
  row->combos = sel.all_combos;
  SceneRenderConfig cfg;
  cfg.w = kW;
  cfg.h = kH;
  cfg.backend = Backend::EGL;
  cfg.api = Api::GLES3;
  // The selection and the all-features baseline take turns frame by frame, so that a change of
  // load on the machine moves both alike (their ratio is the point). The C fallback runs its
  // frames in a block of its own: between GL frames its caches would start cold every time.
  SceneSelection uber;
  if (!select_scene_variants(s, tier, hdr, &uber, err, true)) return false;
  std::vector<double> frame, lit, uframe, ulit, cframe, clit;
  {
    SceneRenderer gl, gl_uber;
    SceneRenderResult res;
    if (!gl.init(s, sel, cfg, err) || !gl.frame(&res, err)) return false;
    row->compile_sel = gl.compile_ms();
    if (!gl_uber.init(s, uber, cfg, err) || !gl_uber.frame(&res, err)) return false;
    for (int i = 0; i < runs; ++i) {
      if (!gl.frame(&res, err)) return false;
      frame.push_back(res.frame_ms);
      lit.push_back(res.lit_ms);
      if (!gl_uber.frame(&res, err)) return false;
      uframe.push_back(res.frame_ms);
      ulit.push_back(res.lit_ms);
    }
  }
  {
    SceneRenderConfig ccfg = cfg;
    ccfg.backend = Backend::CPU;
    SceneRenderer c;
    SceneRenderResult res;
    if (!c.init(s, sel, ccfg, err) || !c.frame(&res, err)) return false;
    for (int i = 0; i < runs; ++i) {
      if (!c.frame(&res, err)) return false;
      cframe.push_back(res.frame_ms);
      clit.push_back(res.lit_ms);
    }
  }
  row->gl_frame = median(frame);
  row->gl_lit = median(lit);
  row->uber_frame = median(uframe);
  row->uber_lit = median(ulit);
  row->c_frame = median(cframe);
  row->c_lit = median(clit);
  double nowarm_mib = 0;
  return compile_all_ms(sel, &row->compile_all, err) &&
      child_first_frame_ms(s.path, tier, hdr, true, &row->first_ms, &row->peak_mib, err) &&
      child_first_frame_ms(s.path, tier, hdr, false, &row->first_nowarm_ms, &nowarm_mib, err);
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  const int runs = std::max(3, std::min(opt.runs, 7));
  std::vector<Row> rows;
  for (const char *path : kScenes) {
    Scene s;
    if (!load_scene(path, &s, err)) return false;
    for (Tier t : {Tier::PS20, Tier::PS2B, Tier::SM3}) {
      for (const char *hdr : {"integer", "float"}) {
        Row r;
        r.scene = path;
        r.tier = tier_name(t);
        r.hdr = hdr;
        fprintf(stderr, "bench: scenes: %s %s %s\n", path, r.tier.c_str(), hdr);
        if (!measure(s, t, hdr, runs, &r, err)) {
          *err = std::string(path) + " " + r.tier + " " + hdr + ": " + *err;
          return false;
        }
        rows.push_back(r);
      }
    }
  }
  std::ostringstream o;
  o << "## Scenes: only what the scene calls for (1280x720)\n\n"
    << "The shipped glTF scenes (docs/scenes.md) rendered by `tiershade render`'s code: EGL GLES 3.0 on llvmpipe\n"
    << "(forward draws of the selected production variants, then the HDR path and colour correction) and the\n"
    << "C fallback (its own rasteriser and the bit-exact batched twins, "
    << "both cores). Medians of " << runs
    << " warm frames (the selection's and the all-features baseline's taken in turn, then the C fallback's); **first "
       "frame**: the wall time of a fresh `tiershade render` process with an empty\n"
    << "shader-cache directory, from its start to its exit (process start, scene loaded, draws prepared: lightmap\n"
    << "bake, probe cube maps; the selected variants compiled, linked and JIT-compiled by their first draw; EXR and\n"
    << "PNG written), median of 3 processes; with the shader warm-up thread (glue/scene/frame.cpp) and without it\n"
    << "(TIERSHADE_NO_WARMUP=1); **peak MiB**: the largest VmHWM of the 3 (warm-up on). **compile all**:\n"
    << "compiling and linking every combo of the families the scene uses (their JIT would come on top, at\n"
    << "first draw); **selected**: the same for the selected variants. **frame** includes the HDR path and\n"
    << "colour correction; **lit** is the lit pass alone (GL: draws + glFinish; C: rasterise + shade).\n"
    << "**all features**: the same scene on llvmpipe with every draw's variant having every feature compiled\n"
    << "in (what an engine without selection runs; unused features off by uniforms); **lit x saved**: its lit\n"
    << "pass over the selection's.\n\n"
    << "| scene | tier | HDR path | variants / combos | compile ms selected / all | x saved | first frame ms (warm-up "
       "/ none) | peak MiB | "
       "llvmpipe frame ms | llvmpipe lit ms | all features: frame / lit ms | lit x saved | C frame ms | C lit ms | "
       "C / llvmpipe frame | C / llvmpipe lit |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row &r : rows) {
    o << "| " << r.scene.substr(7) << " | " << r.tier << " | " << r.hdr << " | " << r.variants << " / " << r.combos
      << " | " << f1(r.compile_sel) << " / " << f1(r.compile_all) << " | "
      << f1(r.compile_all / std::max(1e-3, r.compile_sel)) << " | " << f1(r.first_ms) << " / " << f1(r.first_nowarm_ms)
      << " | " << f1(r.peak_mib) << " | " << f1(r.gl_frame) << " | " << f1(r.gl_lit) << " | " << f1(r.uber_frame)
      << " / " << f1(r.uber_lit) << " | " << f2(r.uber_lit / std::max(1e-3, r.gl_lit)) << " | " << f1(r.c_frame)
      << " | " << f1(r.c_lit) << " | " << f2(r.c_frame / std::max(1e-3, r.gl_frame)) << " | "
      << f2(r.c_lit / std::max(1e-3, r.gl_lit)) << " |\n";
  }
  o << "\nPeak resident memory of one `tiershade render SCENE --size 1280x720` process (the scene's default tier\n"
    << "sm3 and HDR path), its VmHWM:\n\n| scene | EGL GLES 3.0 MiB | C fallback MiB |\n|---|---|---|\n";
  for (const char *path : kScenes) {
    double gl = 0, c = 0;
    const std::string out = "/tmp/tiershade_bench_mem_" + std::to_string(getpid());
    if (!child_peak_mib({"render", path, "--size", "1280x720", "--quiet", "-o", out}, &gl, err) ||
        !child_peak_mib({"render", path, "--size", "1280x720", "--quiet", "--backend", "cpu", "-o", out}, &c, err))
      return false;
    unlink((out + ".png").c_str());
    unlink((out + ".exr").c_str());
    o << "| " << std::string(path).substr(7) << " | " << f1(gl) << " | " << f1(c) << " |\n";
  }
  *md = o.str();
  return true;
}

const BenchSection kSection = {"scenes", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

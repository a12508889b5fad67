// tiershade bench: the MSAA section of `tiershade bench` (docs/accuracy_cost.md): the integer HDR
// path multisampled (glue/scene/msaa.h) on scenes/model_lighting.gltf at N/2 x N*9/32: edge error
// against a 16x supersampled reference (the same path rendered by the C fallback at 4x the width
// and height, one sample at each sub-pixel centre, box-averaged 4x4 in display codes, in double),
// the lit pass's time per sample count (GL on EGL GLES 3.0 / llvmpipe: 1x and 4x, its only mode;
// the C fallback: 1x, 2x, 4x, 8x), the targets' memory per pixel and the process's peak memory,
// and the float path without MSAA against its own supersampled reference. Not a test.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "base/stats.h"
#include "families/family.h"
#include "scene/frame.h"
#include "scene/msaa.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"

#include "bench/table_format.h"

namespace {

using bench::f1;
using bench::f2;

const char kScene[] = "scenes/model_lighting.gltf";

struct Method {
  const char *label;
  Backend backend;
  const char *path;  // HDR path
  int msaa;
};
const Method kMethods[] = {
    {"integer 1x", Backend::EGL, "integer", 0}, {"integer 4x", Backend::EGL, "integer", 4},
    {"integer 1x", Backend::CPU, "integer", 0}, {"integer 2x", Backend::CPU, "integer", 2},
    {"integer 4x", Backend::CPU, "integer", 4}, {"integer 8x", Backend::CPU, "integer", 8},
    {"float 1x", Backend::EGL, "float", 0},     {"float 1x", Backend::CPU, "float", 0},
};

// The reference: the path's display frame at 4w x 4h (C fallback, no MSAA), averaged over each
// pixel's 4x4 block (RGB codes, double).
bool reference(const Scene &s, const SceneSelection &sel, int w, int h, std::vector<double> *ref, std::string *err) {
  SceneRenderConfig c;
  c.backend = Backend::CPU;
  c.w = 4 * w;
  c.h = 4 * h;
  SceneRenderResult r;
  if (!render_scene(s, sel, c, &r, err)) return false;
  ref->assign(static_cast<size_t>(w) * h * 3, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        double acc = 0;
        for (int j = 0; j < 4; ++j)
          for (int i = 0; i < 4; ++i) acc += r.display[((static_cast<size_t>(4 * y + j) * c.w) + 4 * x + i) * 4 + ch];
        (*ref)[(static_cast<size_t>(y) * w + x) * 3 + ch] = acc / 16.0;
      }
  return true;
}

// Pixel classes: silhouettes (the C fallback's 8x coverage: samples of background and a
// triangle, or of two draws), and the other pixels where the reference's block is not flat (a
// channel of the path's one-sample frame more than 2 codes from its reference: texture and
// shading detail within a triangle, which MSAA does not touch: it shades once per pixel).
struct Err3 {
  double mean_sil = 0, over8 = 0, mean_detail = 0, mean_all = 0;  // codes; share of silhouette pixels beyond 8
  int max = 0;
};
Err3 error_of(const std::vector<uint8_t> &d, const std::vector<double> &ref, const std::vector<uint8_t> &sil,
              const std::vector<bool> &contrast) {
  Err3 e;
  long ns = 0, nd = 0, n = 0, o8 = 0;
  double ss = 0, sd = 0, sa = 0;
  for (size_t i = 0; i < sil.size(); ++i) {
    double m = 0;
    for (int c = 0; c < 3; ++c) m = std::max(m, std::fabs(d[i * 4 + c] - ref[i * 3 + c]));
    sa += m;
    ++n;
    if (sil[i]) {
      ++ns;
      ss += m;
      o8 += m > 8;
      e.max = std::max(e.max, static_cast<int>(std::lround(m)));
    } else if (contrast[i]) {
      ++nd;
      sd += m;
    }
  }
  e.mean_sil = ss / std::max(1L, ns);
  e.over8 = 100.0 * o8 / std::max(1L, ns);
  e.mean_detail = sd / std::max(1L, nd);
  e.mean_all = sa / std::max(1L, n);
  return e;
}

double peak_of_render(const Method &m, int w, int h) {
  char exe[4096];
  const ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (len <= 0) return -1;
  exe[len] = 0;
  const std::string out = "/tmp/tiershade_bench_msaa_" + std::to_string(getpid());
  const std::string cmd = std::string("'") + exe + "' render " + kScene + " --backend " +
      (m.backend == Backend::CPU ? "cpu" : "egl") + " --hdr " + m.path + " --msaa " + std::to_string(std::max(1, m.msaa)) +
      " --size " + std::to_string(w) + "x" + std::to_string(h) + " --quiet --report-memory -o '" + out + "' 2>/dev/null";
  fflush(stdout);
  double mib = -1;
  FILE *pp = popen(cmd.c_str(), "r");
  if (pp) {
    char line[512];
    while (fgets(line, sizeof line, pp)) sscanf(line, "peak memory: %lf MiB", &mib);
    if (pclose(pp) != 0) mib = -1;
  }
  unlink((out + ".png").c_str());
  unlink((out + ".exr").c_str());
  return mib;
}

// Bytes per pixel of the targets an engine allocates for the frame (colour and depth; the
// resolve target; the float path's quarter-size bloom chain: 3 RGBA16F targets at 1/16 the pixels).
double target_bytes(const Method &m) {
  if (std::string(m.path) == "float") return 8 + 4 + 3 * 8 / 16.0;
  const int s = std::max(1, m.msaa);
  return s * (4 + 4) + (s > 1 ? 4 : 0);
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  const int w = std::max(32, opt.size / 2), h = std::max(18, opt.size * 9 / 32);
  const int runs = std::max(1, std::min(opt.runs, 5));
  Scene s;
  SceneSelection sel_int, sel_float;
  if (!load_scene(kScene, &s, err) || !select_scene_variants(s, Tier::SM3, "integer", &sel_int, err) ||
      !select_scene_variants(s, Tier::SM3, "float", &sel_float, err))
    return false;
  std::vector<double> ref_int, ref_float;
  if (!reference(s, sel_int, w, h, &ref_int, err) || !reference(s, sel_float, w, h, &ref_float, err)) return false;
  PreparedScene p;
  if (!prepare_scene(s, sel_int, w, h, Api::GL33, s.hdr.tone_map_scale, &p, err)) return false;
  MsaaFrameC f8;
  scene_render_msaa_cpu(p, 8, &f8);
  long nsil = 0;
  for (uint8_t b : f8.silhouette) nsil += b;
  std::ostringstream rows;
  std::vector<bool> edge_int, edge_float;
  for (const Method &m : kMethods) {
    const bool fl = std::string(m.path) == "float";
    SceneRenderConfig c;
    c.backend = m.backend;
    c.w = w;
    c.h = h;
    c.msaa = m.msaa;
    SceneRenderer r;
    SceneRenderResult res;
    if (!r.init(s, fl ? sel_float : sel_int, c, err) || !r.frame(&res, err)) return false;
    std::vector<double> lit;
    for (int i = 0; i < runs; ++i) {
      SceneRenderResult f;
      if (!r.frame(&f, err)) return false;
      lit.push_back(f.lit_ms + (fl ? f.post_ms : 0));
    }
    const std::vector<double> &ref = fl ? ref_float : ref_int;
    std::vector<bool> &edge = fl ? edge_float : edge_int;
    if (edge.empty()) {  // from the path's first (one-sample) frame
      edge.resize(static_cast<size_t>(w) * h);
      for (size_t i = 0; i < edge.size(); ++i) {
        bool e = false;
        for (int ch = 0; ch < 3; ++ch) e = e || std::fabs(res.display[i * 4 + ch] - ref[i * 3 + ch]) > 2;
        edge[i] = e;
      }
    }
    long ne = 0;
    for (size_t i = 0; i < edge.size(); ++i) ne += edge[i] && !f8.silhouette[i];
    const Err3 e = error_of(res.display, ref, f8.silhouette, edge);
    const double peak = peak_of_render(m, w, h);
    rows << "| " << m.label << " | " << (m.backend == Backend::CPU ? "C fallback" : "EGL GLES 3.0") << " | "
         << (res.msaa_samples > 1 ? res.msaa_samples : 1) << " | " << f2(e.mean_sil) << " | " << f1(e.over8)
         << "% | " << e.max << " | " << ne << " | " << f2(e.mean_detail) << " | " << f2(e.mean_all) << " | "
         << f1(median(lit)) << " | " << f1(target_bytes(m)) << " | " << f1(peak) << " |\n";
  }
  std::ostringstream o;
  o << "## MSAA: the integer path multisampled against the float path without (" << w << "x" << h << ")\n\n"
    << "`" << kScene << "`, sm3. The integer path's lit pass draws into a multisampled RGBA8 target with the shaders'\n"
    << "in-shader tone map and sRGB and is resolved with glBlitFramebuffer (llvmpipe's one multisample mode is 4x,\n"
    << "`lp_sample_pos_4x`; the C fallback rasterises that pattern and the standard 2x and 8x ones, shades each\n"
    << "triangle once per pixel at its centre and resolves as llvmpipe does); the float path (RGBA16F, tone-map pass)\n"
    << "has no MSAA (docs/rendering.md, \"MSAA\"). **Reference**: the same path rendered by the C fallback at\n"
    << 4 * w << "x" << 4 * h << " without MSAA (16 samples per pixel on a 4x4 grid) and box-averaged 4x4 in display codes\n"
    << "(double, not rounded). **error**: the largest channel's |frame - reference| in 8-bit codes, over the\n"
    << nsil << " **silhouette** pixels (by the C fallback's 8x coverage: samples of background and a triangle, or\n"
    << "of two draws: the geometric edges MSAA is for) and over the **detail** pixels (the others where the path's\n"
    << "one-sample frame is more than 2 codes from its reference: texture and shading detail inside a triangle,\n"
    << "which MSAA leaves as it is, shading once per pixel). **lit ms**: the lit pass (MSAA: with its resolve and readback; the float path: with its post\n"
    << "chain), median of " << runs << " warm frames. **target B/px**: what an engine allocates per pixel (colour and\n"
    << "depth per sample, the resolve target; the float path's RGBA16F and depth and its quarter-size bloom chain);\n"
    << "**peak MiB**: VmHWM of one `tiershade render` process (tiershade's own one-sample integer path draws into\n"
    << "RGBA32F, so its 1x peak is not an engine's).\n\n"
    << "| path | backend | samples | silhouette mean error | silhouette > 8 codes | silhouette max | detail pixels | "
       "detail mean error | mean error (all) | lit ms | target B/px | peak MiB |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|\n"
    << rows.str();
  *md = o.str();
  return true;
}

const BenchSection kSection = {"msaa", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

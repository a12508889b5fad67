// tiershade bench: the large-scene section of `tiershade bench` (docs/accuracy_cost.md): the hall of
// scenes/large_hall*.gltf (tools/make_scenes.py large_hall(): world faces, 40 / 160 / 400 instanced
// models, 48 lights, 4 probes) at N x N*9/16, the lit pass's time against the draw count and the
// light count, on EGL GLES 3.0 (llvmpipe) and the C fallback; the per-draw set-up's share of the GL
// pass (program, uniforms, textures, attributes: SceneGl::last_bind_ms), the per-model light choice
// (ts_fold_lights at every model's centre, what prepare_scene runs per model); and the peak memory
// of a `tiershade render` process per draw count. Not a test: nothing here passes or fails.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

#include "base/stats.h"
#include "families/family.h"
#include "gl/context.h"
#include "scene/cpu_renderer.h"
#include "scene/gl_renderer.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"

#include "bench/table_format.h"

namespace {

using bench::Clock;
using bench::f1;
using bench::f2;
using bench::ms_since;

struct Hall {
  const char *path;
  int models;
};
const Hall kHalls[] = {{"scenes/large_hall_40.gltf", 40}, {"scenes/large_hall_160.gltf", 160},
                       {"scenes/large_hall.gltf", 400}};

struct Row {
  int models = 0, draws = 0, lights = 0;
  double prepare_ms = 0, choice_ms = 0;
  double gl_lit = 0, gl_bind = 0;  // medians
  double c_raster = 0, c_shade = 0, c_lit = 0;
  size_t geometry_bytes = 0;  // the prepared draws' vertex arrays, each shared DrawGeometry once
  int geometries = 0;
};

// The per-model light choice of prepare_scene (glue/scene/prepare.cpp model_draw): every model
// draw's lights folded at its instance's centre to the tier's limit.
double light_choice_ms(const Scene &s, const PreparedScene &p, Tier tier) {
  std::vector<ts_light> lights;
  for (const SceneLight &l : s.lights) lights.push_back(l.light);
  std::vector<int> kept(lights.size() + 1);
  const auto t0 = Clock::now();
  for (const PreparedDraw &d : p.draws) {
    if (d.world || lights.empty()) continue;
    const ScenePrimitive &pr = s.primitives[static_cast<size_t>(d.choice->primitive)];
    const double *c = s.instances.at(static_cast<size_t>(pr.instance)).center;
    const float cf[3] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
    float cube[6][3] = {};
    ts_fold_lights(lights.data(), static_cast<int>(lights.size()), max_local_lights(tier), cf,
                   d.variant->value("HALF_LAMBERT"), cube, kept.data());
  }
  return ms_since(t0);
}

bool measure(const Scene &s, int w, int h, int runs, Row *row, std::string *err) {
  const Tier tier = Tier::SM3;
  SceneSelection sel;
  PreparedScene p;
  const auto t0 = Clock::now();
  if (!select_scene_variants(s, tier, "", &sel, err) ||
      !prepare_scene(s, sel, w, h, Api::GLES3, s.hdr.tone_map_scale, &p, err))
    return false;
  row->prepare_ms = ms_since(t0);
  row->draws = static_cast<int>(p.draws.size());
  row->lights = static_cast<int>(s.lights.size());
  row->geometry_bytes = p.geometry_bytes();
  row->geometries = p.geometries();
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) t.push_back(light_choice_ms(s, p, tier));
  row->choice_ms = median(t);
  {
    auto ctx = GlContext::create(Backend::EGL, Api::GLES3, err);
    if (!ctx) return false;
    GlRenderer r(*ctx);
    SceneGl gl(r, Api::GLES3);
    ImageF img;
    double ms = 0;
    if (!gl.init(p, err) || !gl.frame(&img, err, &ms)) return false;  // the first frame JIT-compiles
    std::vector<double> lit, bind;
    for (int i = 0; i < runs; ++i) {
      if (!gl.frame(&img, err, &ms)) return false;
      lit.push_back(ms);
      bind.push_back(gl.last_bind_ms());
    }
    row->gl_lit = median(lit);
    row->gl_bind = median(bind);
  }
  SceneVisibility vis;
  ImageF img;
  scene_rasterize_cpu(p, &vis);
  scene_shade_cpu(p, vis, &img);  // warm: the buffers are reused from here on
  std::vector<double> ra, sh, lit;
  for (int i = 0; i < runs; ++i) {
    const auto a = Clock::now();
    scene_rasterize_cpu(p, &vis);
    const auto b = Clock::now();
    scene_shade_cpu(p, vis, &img);
    ra.push_back(std::chrono::duration<double, std::milli>(b - a).count());
    sh.push_back(ms_since(b));
    lit.push_back(ms_since(a));
  }
  row->c_raster = median(ra);
  row->c_shade = median(sh);
  row->c_lit = median(lit);
  return true;
}

// Peak resident memory (MiB) of `tiershade render SCENE --size WxH --backend B`, as it reports it.
bool render_peak_mib(const std::string &scene, const std::string &backend, int w, int h, double *mib,
                     std::string *err) {
  char exe[4096];
  const ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (len <= 0) {
    *err = "cannot find this executable (/proc/self/exe)";
    return false;
  }
  exe[len] = 0;
  const std::string out = "/tmp/tiershade_bench_large_" + std::to_string(getpid());
  const std::string cmd = std::string("'") + exe + "' render '" + scene + "' --backend " + backend + " --size " +
      std::to_string(w) + "x" + std::to_string(h) + " --quiet --report-memory -o '" + out + "' 2>/dev/null";
  fflush(stdout);
  *mib = -1;
  FILE *pp = popen(cmd.c_str(), "r");
  if (pp) {
    char line[512];
    while (fgets(line, sizeof line, pp)) sscanf(line, "peak memory: %lf MiB", mib);
  }
  const bool ok = pp && pclose(pp) == 0 && *mib >= 0;
  unlink((out + ".png").c_str());
  unlink((out + ".exr").c_str());
  if (!ok) *err = "tiershade render " + scene + " --backend " + backend + " failed or did not report its memory";
  return ok;
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  const int w = opt.size, h = std::max(16, opt.size * 9 / 16);
  const int runs = std::max(1, std::min(opt.runs, 7));
  std::vector<Row> rows;
  for (const Hall &hall : kHalls) {
    Scene s;
    if (!load_scene(hall.path, &s, err)) return false;
    // The light count at 400 models: the hall's first 4 and 16 lights, then all 48.
    std::vector<int> counts = {static_cast<int>(s.lights.size())};
    if (hall.models == 400) counts = {4, 16, static_cast<int>(s.lights.size())};
    for (int nl : counts) {
      Scene sub = s;
      sub.lights.resize(static_cast<size_t>(std::min<int>(nl, static_cast<int>(s.lights.size()))));
      Row r;
      r.models = hall.models;
      fprintf(stderr, "bench: large_scene: %s, %d lights\n", hall.path, nl);
      if (!measure(sub, w, h, runs, &r, err)) {
        *err = std::string(hall.path) + ": " + *err;
        return false;
      }
      rows.push_back(r);
    }
  }
  std::ostringstream o;
  o << "## Large scene: draw count and light count (" << w << "x" << h << ")\n\n"
    << "`scenes/large_hall.gltf` (tools/make_scenes.py `large_hall()`): 46 world faces (floor, ceiling, walls,\n"
    << "8 pillars; lightmaps baked, direct light only), instanced models (three meshes, one glTF node per copy;\n"
    << "`large_hall_40/160.gltf`: the first 40 / 160 of its 400), 48 point and spot lights, 4 probes, 16 ambient\n"
    << "samples; sm3, integer HDR path. **lit**: the lit pass alone, median of " << runs
    << " warm frames (GL: the draws and glFinish on EGL GLES 3.0 / llvmpipe; C: the C fallback's rasteriser and\n"
    << "shading on both cores). **GL set-up**: the host time of the per-draw set-up within the GL pass (program,\n"
    << "uniforms, textures, attribute bindings), summed over the draws, and its share of the pass. **light\n"
    << "choice**: every model's lights chosen and folded at its centre (ts_fold_lights, what prepare_scene runs\n"
    << "per model; an engine with moving models runs it per frame). **prepare**: selection and prepare_scene\n"
    << "(lightmap bake, textures, per-draw slots).\n\n"
    << "| models | draws | lights | GL lit ms | GL set-up ms (share) | C raster ms | C shade ms | C lit ms | "
       "C / GL lit | light choice ms (share of GL lit) | prepare ms |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row &r : rows)
    o << "| " << r.models << " | " << r.draws << " | " << r.lights << " | " << f1(r.gl_lit) << " | " << f2(r.gl_bind)
      << " (" << f1(100.0 * r.gl_bind / std::max(1e-3, r.gl_lit)) << "%) | " << f1(r.c_raster) << " | "
      << f1(r.c_shade) << " | " << f1(r.c_lit) << " | " << f2(r.c_lit / std::max(1e-3, r.gl_lit)) << " | "
      << f2(r.choice_ms) << " (" << f1(100.0 * r.choice_ms / std::max(1e-3, r.gl_lit)) << "%) | " << f1(r.prepare_ms)
      << " |\n";
  o << "\nMemory against the draw count (48 lights): the peak resident memory (VmHWM) of one `tiershade render`\n"
    << "process at " << w << "x" << h << ", and the prepared draws' vertex arrays (PreparedScene::geometry_bytes: each\n"
    << "DrawGeometry once; the instances of a mesh share one). **per draw**: the growth from the row above over\n"
    << "the draws added.\n\n"
    << "| models | draws | geometry KiB (arrays) | EGL GLES 3.0 MiB | per draw KiB | C fallback MiB | per draw KiB |\n"
    << "|---|---|---|---|---|---|---|\n";
  double last_gl = 0, last_c = 0;
  int last_draws = 0;
  for (const Hall &hall : kHalls) {
    double gl = 0, c = 0;
    if (!render_peak_mib(hall.path, "egl", w, h, &gl, err) || !render_peak_mib(hall.path, "cpu", w, h, &c, err))
      return false;
    const Row *r = nullptr;  // the hall's row with all its lights
    for (const Row &x : rows)
      if (x.models == hall.models) r = &x;
    const int draws = r ? r->draws : 0;
    auto per = [&](double now, double before) {
      return last_draws > 0 && draws > last_draws ? f1((now - before) * 1024.0 / (draws - last_draws)) : std::string("-");
    };
    o << "| " << hall.models << " | " << draws << " | " << f1(r ? r->geometry_bytes / 1024.0 : 0) << " ("
      << (r ? r->geometries : 0) << ") | " << f1(gl) << " | " << per(gl, last_gl) << " | " << f1(c) << " | "
      << per(c, last_c) << " |\n";
    last_gl = gl, last_c = c, last_draws = draws;
  }
  *md = o.str();
  return true;
}

const BenchSection kSection = {"large_scene", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

// tiershade bench: the probe_cubes section of `tiershade bench` (docs/accuracy_cost.md): the room's
// world probes' cube maps made each way (glue/scene/probe_render.h): ray traced by the baker per texel
// (the old path, probes[].source "rays"), rendered in-engine by the C fallback and on GL (EGL GLES
// 3.0); their time, their error against a supersampled in-engine render, GL against the C twins,
// and what the choice changes in the room's frame. Not a test: nothing here passes or fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "base/srgb.h"
#include "base/stats.h"
#include "bench/table_format.h"
#include "demo/scene_files.h"
#include "gl/float_target.h"
#include "scene/frame.h"
#include "scene/gl_renderer.h"
#include "scene/prepare.h"
#include "scene/probe_render.h"

namespace {

using bench::Clock;
using bench::ms_since;

struct CubeErr {
  double rel_rms = 0, max_rel = 0, median_rel = 0;
  long texels = 0, exact = 0;
};
// a against ref over every texel's rgb: RMS relative to ref's mean, the largest per-texel relative
// difference (to max(|a|, |b|, 1e-3)), the texels equal to the bit.
CubeErr cube_error(const std::vector<float> &a, const std::vector<float> &ref) {
  CubeErr e;
  double se = 0, sr = 0;
  e.texels = static_cast<long>(a.size() / 4);
  std::vector<double> rel;
  for (size_t i = 0; i < a.size(); i += 4) {
    bool eq = true;
    double r = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = static_cast<double>(a[i + c]) - ref[i + c];
      se += d * d;
      sr += ref[i + c];
      eq = eq && a[i + c] == ref[i + c];
      r = std::max(r, std::fabs(d) / std::max({std::fabs(a[i + c]), std::fabs(ref[i + c]), 1e-3f}));
    }
    e.max_rel = std::max(e.max_rel, r);
    rel.push_back(r);
    e.exact += eq;
  }
  e.median_rel = median(rel);
  e.rel_rms = sr > 0 ? std::sqrt(se / (3.0 * e.texels)) / (sr / (3.0 * e.texels)) : 0;
  return e;
}

// The reference: the C fallback's cube at k x k the edge, each texel the mean of its k x k
// sub-texels (the mean radiance over the texel's footprint, textures and lightmaps filtered).
void supersampled(ProbeView *v, const double pos[3], int n, int k, std::vector<float> *out) {
  std::vector<float> big;
  render_probe_cube_cpu(v, pos, n * k, 0, &big);
  out->assign(static_cast<size_t>(6) * n * n * 4, 1.f);
  const size_t nb = static_cast<size_t>(n) * k;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int c = 0; c < 3; ++c) {
          double s = 0;
          for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i) s += big[((f * nb + y * k + j) * nb + x * k + i) * 4 + c];
          (*out)[((static_cast<size_t>(f) * n + y) * n + x) * 4 + c] = static_cast<float>(s / (k * k));
        }
}

// Display-code error of two frames' lit passes (sRGB x 255) over every pixel.
void frame_error(const ImageF &a, const ImageF &b, double *max, double *mean) {
  double s = 0;
  *max = 0;
  long n = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c, ++n) {
      const double d = 255 * std::fabs(srgb_encode_clamped(a.rgba[i + c]) - srgb_encode_clamped(b.rgba[i + c]));
      *max = std::max(*max, d);
      s += d;
    }
  *mean = n ? s / n : 0;
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  Scene room;
  if (!load_scene(kWorldLightingGltf, &room, err)) return false;
  // Every probe at the largest size: the bake traces every cube at one edge (WorldBakeInput::cube_size).
  int edge = 0;
  for (const SceneProbe &p : room.probes) edge = std::max(edge, p.size);
  for (SceneProbe &p : room.probes) p.size = edge;
  Scene traced = room;
  for (SceneProbe &p : traced.probes) p.traced = true;
  const int runs = std::max(1, opt.runs);
  SceneSelection sel, tsel;
  PreparedScene ps, tps;
  PrepareOptions pending;
  pending.gl_probe_cubes = true;
  if (!select_scene_variants(room, Tier::SM3, "", &sel, err) || !select_scene_variants(traced, Tier::SM3, "", &tsel, err) ||
      !prepare_scene(room, sel, 16, 16, Api::GLES3, 1.f, &ps, err, pending) ||
      !prepare_scene(traced, tsel, 16, 16, Api::GLES3, 1.f, &tps, err))
    return false;
  ProbeView v;
  if (!make_probe_view(room, ps, &v, err)) return false;
  for (const PreparedProbeCube &pc : ps.probe_cubes) v.max_size = std::max(v.max_size, room.probes[pc.probe].size);
  auto ctx = GlContext::create(Backend::EGL, Api::GLES3, err);
  if (!ctx) return false;
  GlRenderer r(*ctx);
  SceneGl g(r, Api::GLES3);
  probe_view_face(&v, room.probes[0].position, v.max_size, 0);
  double compile_ms = 0;
  if (!g.init(v.p, err, &compile_ms, v.max_size, v.max_size)) return false;
  std::ostringstream rows;
  char b[1024];
  double first_gl_ms = 0;
  for (const PreparedProbeCube &pc : ps.probe_cubes) {
    const SceneProbe &pr = room.probes[pc.probe];
    const int n = pr.size;
    std::vector<float> gl, cpu, ref, rays;
    std::vector<double> t_gl, t_c;
    long twin = -1;
    for (int i = 0; i <= runs; ++i) {  // the first GL run JIT-compiles the variants: not in the median
      auto t0 = Clock::now();
      if (!render_probe_cube_gl(&v, &g, pr.position, n, &gl, err)) return false;
      if (i)
        t_gl.push_back(ms_since(t0));
      else
        first_gl_ms = std::max(first_gl_ms, ms_since(t0));
      t0 = Clock::now();
      render_probe_cube_cpu(&v, pr.position, n, 0, &cpu);
      if (i) t_c.push_back(ms_since(t0));
    }
    if (!render_probe_cube_gl(&v, &g, pr.position, n, &gl, err, &twin)) return false;
    supersampled(&v, pr.position, n, 4, &ref);
    for (const PreparedProbeCube &t : tps.probe_cubes)
      if (t.probe == pc.probe) rays = tps.textures.at(t.texture).rgba;
    if (rays.size() != gl.size()) {
      *err = "probe " + pr.name + ": no ray-traced cube to compare";
      return false;
    }
    for (size_t i = 0; i < rays.size(); i += 4) rays[i + 3] = 1.f;
    const CubeErr eg = cube_error(gl, ref), ec = cube_error(cpu, ref), er = cube_error(rays, ref);
    const CubeErr cg = cube_error(cpu, gl), rg = cube_error(rays, gl);
    snprintf(b, sizeof b,
             "| %s | %d | ray traced (baker) | %.4f | %.4f | %.3f | %.1f (the bake's, both probes) | rendered on GL: "
             "relative RMS %.4f, median %.4f |\n"
             "| %s | %d | C fallback | %.4f | %.4f | %.3f | %.2f | GL: %ld of %ld texels bit-identical, median %.2g, "
             "max %.2g relative |\n"
             "| %s | %d | GL (EGL GLES 3.0) | %.4f | %.4f | %.3f | %.2f | C twin on GL's G-buffer: %ld of %ld texels "
             "differ |\n",
             pr.name.c_str(), n, er.rel_rms, er.median_rel, er.max_rel, tps.bake_cubes_ms, rg.rel_rms, rg.median_rel,
             pr.name.c_str(), n, ec.rel_rms, ec.median_rel, ec.max_rel, median(t_c), cg.exact, cg.texels, cg.median_rel,
             cg.max_rel, pr.name.c_str(), n, eg.rel_rms, eg.median_rel, eg.max_rel, median(t_gl), twin, eg.texels);
    rows << b;
    fprintf(stderr, "bench probe_cubes: %s: rays %.4f, C %.4f, GL %.4f relative RMS\n", pr.name.c_str(), er.rel_rms,
            ec.rel_rms, eg.rel_rms);
  }
  // The room's frame (C fallback, sm3) with each: what the envmapped surfaces show.
  SceneRenderConfig cfg;
  cfg.backend = Backend::CPU;
  cfg.w = opt.size;
  cfg.h = std::max(8, opt.size / 2);
  SceneRenderResult fr, ft;
  if (!render_scene(room, sel, cfg, &fr, err) || !render_scene(traced, tsel, cfg, &ft, err)) return false;
  double fmax = 0, fmean = 0;
  frame_error(fr.lit, ft.lit, &fmax, &fmean);

  std::ostringstream o;
  o << "## probe_cubes (world probes' cube maps: ray traced or rendered in-engine)\n\n"
    << "Scene: `" << kWorldLightingGltf << "`, its two world probes, both at " << edge
    << " texels (the bake traces every cube at one edge). **ray traced**: the baker's "
       "old path, one Embree\nray per texel centre (a face's radiance: its flat lightmap x its mean albedo, + "
       "emission; lights as small bulbs;\nthe sky). **rendered**: six 90-degree frames of the scene renderer from "
       "the probe (glue/scene/probe_render.h:\nthe world draws without envmap, fp16 lightmaps, textures, the sky). "
       "**error**: against the C fallback's render at\n4 x 4 the edge box-filtered to the cube's (the mean radiance "
       "over each texel, textures filtered): RMS relative to\nits mean, and the median and largest relative texel difference (of a texel's channels, to max(a, b, 1e-3)). "
       "Times: medians of "
    << runs << " cubes (six faces); GL after a first run that\nJIT-compiled the " << v.variants.size()
    << " cube variants (" << bench::f1(first_gl_ms) << " ms, program build " << bench::f1(compile_ms)
    << " ms). The ray-traced time is the bake's whole cube pass.\n\n"
    << "| probe | edge | made by | error (relative RMS) | median relative | max relative | ms | against |\n"
    << "|---|---|---|---|---|---|---|---|\n"
    << rows.str();
  snprintf(b, sizeof b,
           "\nThe room's %dx%d frame (C fallback, sm3) with the rendered cubes against the ray-traced ones: max %.2f, "
           "mean %.4f display codes\n(the floor's, crate's, pillar's and plinth's reflections).\n",
           cfg.w, cfg.h, fmax, fmean);
  o << b;
  *md = o.str();
  return true;
}

const BenchSection kSection = {"probe_cubes", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

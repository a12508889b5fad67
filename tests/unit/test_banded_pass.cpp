// tiershade tests: the C fallback's banded lit pass (scene_render_cpu, glue/scene/cpu_renderer.h)
// against its two passes (scene_rasterize_cpu then scene_shade_cpu, checked against GL by
// test_scene_render and test_raster_exact) on the shipped scenes: the banded pass rasterises
// without the barycentrics; with scene_render_cpu_force_redo every band is shaded, found to need
// them and rasterised and shaded again with them. All three frames (lit pass, RGBA32F) must be
// equal bit for bit, and the banded pass's linear flags those of the two passes' draws. And the rasteriser without the
// barycentrics (its depth test four pixels at a time) against the one with them, on the scenes'
// triangles each drawn twice (the second copy must lose every depth tie: LESS). No GL context.
#include <cstring>
#include <string>
#include <vector>

#include "scene/cpu_renderer.h"
#include "scene/prepare.h"
#include "scene/lp_interp.h"
#include "scene/raster_tri.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "unit_check.h"

using unit_check::check;

namespace {

long float_diffs(const ImageF &a, const ImageF &b) {
  if (a.rgba.size() != b.rgba.size()) return -1;
  long d = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) d += std::memcmp(&a.rgba[i], &b.rgba[i], 4) != 0;
  return d;
}

void test_scene(const char *name, int w, int h, int threads) {
  const std::string tag = std::string(name) + " " + std::to_string(w) + "x" + std::to_string(h) + " on " +
      std::to_string(threads) + " thread(s)";
  Scene s;
  SceneSelection sel;
  PreparedScene p;
  std::string err;
  if (!load_scene(name, &s, &err) || !select_scene_variants(s, Tier::SM3, "", &sel, &err) ||
      !prepare_scene(s, sel, w, h, Api::GL33, 1.f, &p, &err)) {
    check(false, "banded pass: " + tag + " loads", err);
    return;
  }
  SceneVisibility vis;
  ImageF two, band, redo;
  std::vector<uint8_t> l_band, l_redo;
  scene_rasterize_cpu(p, &vis, threads);
  scene_shade_cpu(p, vis, &two, threads);
  scene_render_cpu(p, &band, &l_band, threads);
  scene_render_cpu_force_redo(true);
  scene_render_cpu(p, &redo, &l_redo, threads);
  scene_render_cpu_force_redo(false);
  long lit = 0;
  std::vector<uint8_t> want(vis.draw.size());
  for (size_t i = 0; i < want.size(); ++i) {
    lit += vis.draw[i] >= 0;
    want[i] = vis.draw[i] >= 0 ? !p.draws[static_cast<size_t>(vis.draw[i])].display_encoded : p.sky.present();
  }
  check(lit > static_cast<long>(w) * h / 8, "banded pass: " + tag + " covers the frame", std::to_string(lit) + " lit pixels");
  check(l_band == want && l_redo == want, "banded pass: " + tag + ": the linear flag of every pixel (from its draw)");
  const long a = float_diffs(band, two), b = float_diffs(redo, two);
  check(a == 0, "banded pass: " + tag + " == the two passes, bit for bit", std::to_string(a) + " floats differ");
  check(b == 0, "banded pass: " + tag + ", every band again with the barycentrics, == the two passes",
        std::to_string(b) + " floats differ");
}

// Every triangle of p twice (the copy as draw + 1000), into a whole-frame buffer with v.bary.
struct Buf {
  std::vector<int32_t> draw, tri;
  std::vector<uint8_t> sub;
  std::vector<float> b1, b2, depth;
};
void raster_twice(const PreparedScene &p, bool bary, Buf *b) {
  const size_t n = static_cast<size_t>(p.w) * p.h;
  b->draw.assign(n, -1), b->tri.assign(n, -1), b->sub.assign(n, 0), b->b1.assign(n, 0.f), b->b2.assign(n, 0.f);
  b->depth.assign(n, kLpDepth24Clear);
  VisRows v;
  v.w = p.w, v.y0 = 0, v.bary = bary;
  v.draw = b->draw.data(), v.tri = b->tri.data(), v.sub = b->sub.data();
  v.b1 = b->b1.data(), v.b2 = b->b2.data(), v.depth = b->depth.data();
  std::vector<float> clip;
  for (size_t di = 0; di < p.draws.size(); ++di) {
    std::vector<ScreenTri> tris;
    scene_clip_stage(p, p.draws[di], &clip);
    scene_tri_setup(p, static_cast<int>(di), clip, &tris);
    for (ScreenTri s : tris) {
      scene_raster_rows(s, v, s.y0, s.y1);
      s.draw += 1000;
      scene_raster_rows(s, v, s.y0, s.y1);
    }
  }
}

void test_depth_ties(const char *name) {
  Scene s;
  SceneSelection sel;
  PreparedScene p;
  std::string err;
  if (!load_scene(name, &s, &err) || !select_scene_variants(s, Tier::SM3, "", &sel, &err) ||
      !prepare_scene(s, sel, 317, 181, Api::GL33, 1.f, &p, &err)) {
    check(false, std::string("raster without barycentrics: ") + name + " loads", err);
    return;
  }
  Buf a, b;
  raster_twice(p, true, &a);
  raster_twice(p, false, &b);
  long copies = 0, lit = 0;
  for (int32_t d : b.draw) copies += d >= 1000, lit += d >= 0;
  const bool same = a.draw == b.draw && a.tri == b.tri && a.sub == b.sub &&
      std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * 4) == 0;
  check(same && copies == 0 && lit > 0, std::string("raster without barycentrics: ") + name +
            ", every triangle twice: the same draw, triangle, sub-triangle, depth; ties kept by the first",
        std::to_string(copies) + " of " + std::to_string(lit) + " lit pixels from the second copy");
}

}  // namespace

int main() {
  ts_math_init();
  for (const char *n : {"scenes/world_lighting.gltf", "scenes/model_lighting.gltf", "scenes/hdr_atrium.gltf"}) {
    test_scene(n, 320, 180, 1);
    test_scene(n, 333, 201, 2);
    test_depth_ties(n);
  }
  return unit_check::finish();
}

// tiershade tests: the C fallback's banded lit pass (scene_render_cpu, glue/scene/cpu_renderer.h)
// against its two passes (scene_rasterize_cpu then scene_shade_cpu, checked against GL by
// test_scene_render and test_raster_exact) on the shipped scenes: the banded pass rasterises
// without the barycentrics; with scene_render_cpu_force_redo every band is shaded, found to need
// them and rasterised and shaded again with them. All three frames (lit pass, RGBA32F) and the
// draw index of every pixel must be equal bit for bit. No GL context.
#include <cstring>
#include <string>
#include <vector>

#include "scene/cpu_renderer.h"
#include "scene/prepare.h"
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
  std::vector<int32_t> d_band, d_redo;
  scene_rasterize_cpu(p, &vis, threads);
  scene_shade_cpu(p, vis, &two, threads);
  const bool banded = scene_render_cpu(p, &vis, &band, &d_band, threads);
  scene_render_cpu_force_redo(true);
  scene_render_cpu(p, &vis, &redo, &d_redo, threads);
  scene_render_cpu_force_redo(false);
  long lit = 0;
  for (int32_t d : d_band) lit += d >= 0;
  check(banded && lit > static_cast<long>(w) * h / 8, "banded pass: " + tag + " takes the banded path",
        std::to_string(lit) + " lit pixels");
  check(d_band == vis.draw && d_redo == vis.draw, "banded pass: " + tag + ": the draw of every pixel");
  const long a = float_diffs(band, two), b = float_diffs(redo, two);
  check(a == 0, "banded pass: " + tag + " == the two passes, bit for bit", std::to_string(a) + " floats differ");
  check(b == 0, "banded pass: " + tag + ", every band again with the barycentrics, == the two passes",
        std::to_string(b) + " floats differ");
}

}  // namespace

int main() {
  ts_math_init();
  for (const char *n : {"scenes/world_lighting.gltf", "scenes/model_lighting.gltf", "scenes/hdr_atrium.gltf"}) {
    test_scene(n, 320, 180, 1);
    test_scene(n, 333, 201, 2);
  }
  return unit_check::finish();
}

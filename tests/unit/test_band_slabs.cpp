// tiershade tests: the banded lit pass's slabs (glue/scene/band_slabs.h; docs/rendering.md,
// "Memory"). On scenes/large_hall_40.gltf (models and world faces, the camera inside the hall: world
// triangles reach behind the eye) and scenes/model_lighting.gltf, at 160x90 and 320x180:
//   - the row bounds are conservative: every triangle scene_tri_setup makes for a draw lies within
//     its draw's slabs (plan_band_slabs) and within its source triangle's rows (triangle_rows);
//   - the lit frame of scene_render_cpu with the slabs' budget forced down (one band a worker a
//     slab, and a budget between) equals, bit for bit, the frame of one slab and the two passes'
//     (scene_rasterize_cpu + scene_shade_cpu), on one and two threads; its linear flags equal
//     those the two passes' draw indices give;
//   - the small budgets do split the frame, with draws live in several slabs (the path is run).
// Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "math/ts_math.h"
#include "scene/band_slabs.h"
#include "scene/cpu_renderer.h"
#include "scene/cpu_vertex.h"
#include "scene/prepare.h"
#include "scene/raster_tri.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "unit_check.h"

namespace {

bool prepare(const char *path, int w, int h, Scene *s, SceneSelection *sel, PreparedScene *p) {
  std::string err;
  if (!load_scene(path, s, &err) || !select_scene_variants(*s, Tier::SM3, "", sel, &err) ||
      !prepare_scene(*s, *sel, w, h, Api::GL33, 1.f, p, &err)) {
    check(false, std::string("band slabs: prepare ") + path, err);
    return false;
  }
  return true;
}

// Every set-up triangle of every draw inside its draw's slabs and its triangle's rows.
void test_bounds(const std::string &name, const PreparedScene &p, size_t budget) {
  const int kBand = 8;
  const BandSlabs sl = plan_band_slabs(p, kBand, budget, sizeof(ScreenTri), 2);
  long tris = 0, outside_slabs = 0, outside_rows = 0, full_rows = 0;
  std::vector<float> clip, win_y;
  std::vector<uint32_t> rows;
  for (size_t di = 0; di < p.draws.size(); ++di) {
    scene_clip_stage(p, p.draws[di], &clip);
    std::vector<ScreenTri> st;
    scene_tri_setup(p, static_cast<int>(di), clip, &st);
    triangle_rows(p, static_cast<int>(di), clip, &win_y, &rows);
    for (uint32_t r : rows) full_rows += r == (static_cast<uint32_t>(p.h - 1) << 16);
    const int f = sl.draw_first[di], l = sl.draw_last[di];
    const int y0 = f < 0 ? 1 : sl.first_band[static_cast<size_t>(f)] * kBand;
    const int y1 = f < 0 ? 0 : sl.first_band[static_cast<size_t>(l) + 1] * kBand - 1;
    for (const ScreenTri &s : st) {
      ++tris;
      outside_slabs += s.y0 < y0 || s.y1 > y1;
      const uint32_t r = rows[static_cast<size_t>(s.tri)];
      outside_rows += s.y0 < static_cast<int>(r & 0xffffu) || s.y1 > static_cast<int>(r >> 16);
    }
  }
  check(tris > 0 && outside_slabs == 0 && outside_rows == 0,
        "band slabs " + name + ": every set-up triangle within its draw's slabs and its triangle's rows",
        std::to_string(tris) + " triangles, " + std::to_string(outside_slabs) + " outside the slabs, " +
            std::to_string(outside_rows) + " outside the rows");
  printf("INFO %s: %zu slabs, %ld set-up triangles, %ld source triangles with every row\n", name.c_str(),
         sl.first_band.size() - 1, tris, full_rows);
}

void test_frames(const char *path, int w, int h) {
  Scene s;
  SceneSelection sel;
  PreparedScene p;
  if (!prepare(path, w, h, &s, &sel, &p)) return;
  const std::string name = std::string(path) + " " + std::to_string(w) + "x" + std::to_string(h);
  // The two passes: the reference.
  SceneVisibility vis;
  ImageF two;
  scene_rasterize_cpu(p, &vis, 2);
  scene_shade_cpu(p, vis, &two, 2);
  std::vector<uint8_t> want(vis.draw.size());
  for (size_t i = 0; i < want.size(); ++i)
    want[i] = vis.draw[i] >= 0 ? !p.draws[static_cast<size_t>(vis.draw[i])].display_encoded : p.sky.present();
  long covered = 0;
  for (int d : vis.draw) covered += d >= 0;
  size_t total = 0;
  for (const PreparedDraw &d : p.draws) total += band_draw_bytes(d, sizeof(ScreenTri));
  const size_t budgets[3] = {total + 1, total / 6, 1};
  for (size_t budget : budgets) {
    const BandSlabs sl = plan_band_slabs(p, 8, budget, sizeof(ScreenTri), 2);
    int spanning = 0;
    for (size_t di = 0; di < p.draws.size(); ++di) spanning += sl.draw_first[di] >= 0 && sl.draw_last[di] > sl.draw_first[di];
    const std::string cfg = name + ", budget " + std::to_string(budget) + " (" +
        std::to_string(sl.first_band.size() - 1) + " slabs, " + std::to_string(spanning) + " draws in several)";
    if (budget == 1)
      check(sl.first_band.size() - 1 > 2 && spanning > 0, "band slabs " + cfg + ": the frame is split");
    if (budget == 1) test_bounds(name, p, budget);
    scene_cpu_band_budget(budget);
    for (int threads : {1, 2}) {
      ImageF got;
      std::vector<uint8_t> linear;
      scene_render_cpu(p, &got, &linear, threads);
      const bool same = got.rgba.size() == two.rgba.size() &&
          std::memcmp(got.rgba.data(), two.rgba.data(), two.rgba.size() * sizeof(float)) == 0;
      check(covered > 0 && same && linear == want,
            "band slabs " + cfg + ", " + std::to_string(threads) +
                " threads: the lit frame and linear flags = the two passes', bit for bit",
            std::to_string(covered) + " pixels covered");
    }
  }
  scene_cpu_band_budget(0);
}

}  // namespace

int main() {
  ts_math_init();
  for (int w : {160, 320}) {
    test_frames("scenes/large_hall_40.gltf", w, w * 9 / 16);
    test_frames("scenes/model_lighting.gltf", w, w * 9 / 16);
  }
  return unit_check::finish();
}

// tiershade tests: the C fallback's own rasteriser against llvmpipe, varying by varying
// (glue/scene/lp_interp.h): the G-buffer records (the 6 pixel slots every production fragment
// shader receives) of a scene drawn by GL and by the C rasteriser, compared bit for bit on the
// pixels both give to the same draw.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "gl/float_target.h"
#include "scene/cpu_renderer.h"
#include "scene/gl_renderer.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "unit_check.h"
#include "unit_gl.h"

using unit_check::check;

namespace {

struct Count {
  long cover_diff = 0, both = 0, exact = 0, floats = 0, float_diff = 0;
};

// GL's and the C fallback's records of one scene at w x h.
// planes false: the C rasteriser's barycentrics alone (the interpolation before lp_interp).
bool compare_scene(const char *name, int w, int h, GlContext &ctx, bool planes, Count *c, std::string *err) {
  Scene s;
  SceneSelection sel;
  PreparedScene p;
  if (!load_scene(name, &s, err) || !select_scene_variants(s, Tier::SM3, "", &sel, err) ||
      !prepare_scene(s, sel, w, h, Api::GL33, 1.f, &p, err))
    return false;
  GlRenderer r(ctx);
  SceneGl g(r, Api::GL33);
  std::vector<int> gd, cd;
  std::vector<float> gs, cs;
  if (!g.init(p, err) || !g.gbuffer(&gd, &gs, err)) return false;
  SceneVisibility vis;
  scene_rasterize_cpu(p, &vis);
  vis.pixel_planes = planes;
  scene_records_cpu(p, vis, &cd, &cs);
  const size_t n = static_cast<size_t>(w) * h;
  for (size_t i = 0; i < n; ++i) {
    if (gd[i] != cd[i]) {
      ++c->cover_diff;
      continue;
    }
    if (gd[i] < 0) continue;
    ++c->both;
    bool same = true;
    for (int k = 0; k < 24; ++k) {
      const float a = gs[i * 24 + k], b = cs[i * 24 + k];
      // A slot the variant does not have is vec4(0) on GL (scene_gbuffer.fs): not compared.
      const float *slot = &gs[i * 24 + (k / 4) * 4];
      if (slot[0] == 0.f && slot[1] == 0.f && slot[2] == 0.f && slot[3] == 0.f) continue;
      ++c->floats;
      if (std::memcmp(&a, &b, 4) != 0) {
        ++c->float_diff;
        same = false;
        if (getenv("TS_RX_DEBUG") && planes)
          fprintf(stderr, "%s px %zu draw %d inst %d slot %d comp %d gl %.9g c %.9g\n", name, i, gd[i],
                  (int)p.draws[gd[i]].instanced, k / 4, k % 4, a, b);
      }
    }
    c->exact += same;
  }
  return true;
}

void test_scenes() {
  std::unique_ptr<GlContext> ctx = open_context(Backend::EGL, Api::GL33, "raster exact: EGL GL 3.3 context");
  if (!ctx) return;
  for (const char *name : {"scenes/model_lighting.gltf", "scenes/world_lighting.gltf", "scenes/hdr_atrium.gltf",
                           "scenes/sphere_grid.gltf", "scenes/phong_sphere.gltf", "scenes/probe_chart.gltf",
                           "scenes/lightmap_charts.gltf", "scenes/hdr_daylight.gltf", "scenes/hdr_dark_room.gltf"}) {
    for (bool planes : {false, true}) {
      Count c;
      std::string err;
      if (!compare_scene(name, 96, 54, *ctx, planes, &c, &err)) {
        check(false, std::string("raster exact: ") + name, err);
        continue;
      }
      printf("INFO %s %s: coverage differs on %ld pixels; %ld of %ld shared pixels bit-identical records, %ld of %ld floats differ\n",
             name, planes ? "planes" : "barycentrics", c.cover_diff, c.exact, c.both, c.float_diff, c.floats);
    }
  }
}

}  // namespace

int main() {
  ts_math_init();
  test_scenes();
  return unit_check::finish();
}

// tiershade scene: a scene's G-buffer as a family's deferred frame (deferred.h).
#include "scene/deferred.h"

#include <algorithm>

#include "scene/cpu_renderer.h"
#include "scene/prepare.h"
#include "scene/reference.h"
#include "scene/selection.h"
#include "twins/model_lighting.h"

// The deferred frames' records carry no derivatives: their textures are sampled at level 0.
static PrepareOptions level_zero_only() {
  PrepareOptions o;
  o.mipmaps = false;
  return o;
}

bool scene_gbuffer_cpu(const Scene &s, Tier tier, int w, int h, bool all_features, SceneGBufferCpu *g,
                       std::string *err) {
  if (!select_scene_variants(s, tier, "", &g->sel, err, all_features) ||
      !prepare_scene(s, g->sel, w, h, Api::GL33, s.hdr.tone_map_scale, &g->p, err, level_zero_only()))
    return false;
  SceneVisibility vis;
  scene_rasterize_cpu(g->p, &vis);
  scene_records_cpu(g->p, vis, &g->draw, &g->slots);
  return true;
}

bool scene_deferred_frame(const Scene &s, Tier tier, int w, int h, SceneDeferredFrame *out, std::string *err,
                          bool all_features, bool with_reference) {
  SceneGBufferCpu g;
  if (!scene_gbuffer_cpu(s, tier, w, h, all_features, &g, err)) return false;
  const PreparedScene &p = g.p;
  const std::vector<int> &draw = g.draw;
  const std::vector<float> &slots = g.slots;
  int only = -1;
  for (int d : draw) {
    if (d < 0 || d == only) continue;
    if (only >= 0 || p.draws[static_cast<size_t>(d)].world) {
      *err = s.path + ": a deferred frame needs one model_lighting draw on screen; " +
          s.primitives[p.draws[static_cast<size_t>(d)].choice->primitive].where + " is another";
      return false;
    }
    only = d;
  }
  if (only < 0) {
    *err = s.path + ": a deferred frame: nothing is on screen at " + std::to_string(w) + "x" + std::to_string(h);
    return false;
  }
  const PreparedDraw &d = p.draws[static_cast<size_t>(only)];
  SceneDeferredFrame f;
  f.in.resize(w, h, ML_PIXEL_SLOTS);
  f.hit.assign(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t q = static_cast<size_t>(y) * w + x;
      if (draw[q] < 0) continue;
      f.hit[q] = 1;
      for (int k = 0; k < ML_PIXEL_SLOTS; ++k) {
        const float *v = &slots[q * 24 + k * 4];
        f.in.set_slot(x, y, k, ts_v4f(v[0], v[1], v[2], v[3]));
      }
    }
  f.in.shared = d.shared;
  for (int k = 0; k < 5; ++k) f.in.textures.push_back(p.texture(d, k));  // u_albedo .. u_envmap
  f.lights_local = d.choice->lights_local;
  f.lights_folded = d.choice->lights_folded;
  if (with_reference && !scene_reference_linear(s, p, draw, slots, &f.reference, err)) return false;
  *out = std::move(f);
  return true;
}

void scene_deferred_mask(const SceneDeferredFrame &f, ImageF *img) {
  for (size_t p = 0; p < f.hit.size(); ++p) {
    if (f.hit[p]) continue;
    img->rgba[p * 4 + 0] = img->rgba[p * 4 + 1] = img->rgba[p * 4 + 2] = 0.f;
    img->rgba[p * 4 + 3] = 1.f;
  }
}

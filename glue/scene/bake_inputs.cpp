// tiershade scene: the bake's inputs from a scene (bake_inputs.h).
#include "scene/bake_inputs.h"

#include <ctime>

#include "bake/bake_dir.h"

void bake_lights_of(const Scene &s, WorldBakeInput *in) {
  for (const SceneLight &l : s.lights) {
    rnm_light r{};
    r.directional = l.light.type == TS_LIGHT_DIRECTIONAL;
    r.pos = ts_v3d(l.light.pos[0], l.light.pos[1], l.light.pos[2]);
    r.dir = ts_v3d(l.light.dir[0], l.light.dir[1], l.light.dir[2]);
    r.color = ts_v3d(l.light.color[0], l.light.color[1], l.light.color[2]);
    for (int k = 0; k < 3; ++k) r.atten[k] = l.light.atten[k];
    if (l.light.type == TS_LIGHT_SPOT) {  // baked with vrad's cone (c_ref/offline/rnm_bake.h)
      r.spot = 1;
      r.spot_dir = r.dir;
      r.cos_inner = l.light.cos_inner;
      r.cos_outer = l.light.cos_outer;
      r.exponent = l.light.spot_exponent;
    }
    in->lights.push_back(r);
    in->light_spread.push_back(l.spread);  // a sun's angular radius: soft shadows
  }
}

bool build_scene_rays(const Scene &s, const std::vector<int> &face_of_draw, RayScene *rays, std::string *err) {
  for (size_t i = 0; i < s.primitives.size(); ++i) {
    const ScenePrimitive &p = s.primitives[i];
    // An instance of shared geometry occludes where its node puts it (scene_world_positions).
    const std::vector<float> world = p.shared ? scene_world_positions(s, p) : std::vector<float>();
    if (!rays->add_mesh(p.shared ? world : p.position, p.shared ? p.shared->indices : p.indices,
                        i < face_of_draw.size() && face_of_draw[i] >= 0 ? face_of_draw[i] : -2, p.where, err)) {
      *err = s.path + ": " + *err;
      return false;
    }
  }
  if (!rays->commit(err)) {
    *err = s.path + ": " + *err;
    return false;
  }
  return true;
}

BakeQuality scene_bake_quality(const Scene &s, std::string *note) {
  BakeQuality quality = s.lightmaps.quality, baked;
  note->clear();
  if (s.lightmaps.bake.empty() || !read_bake_quality(s.lightmaps.bake, &baked)) return quality;
  if (!bake_quality_same(baked, quality))
    *note = s.lightmaps.bake + " was baked at quality " + bake_quality_text(baked) + "; the scene's is " +
        bake_quality_text(quality) + ": the frame shows the bake's";
  return baked;
}

double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

// tiershade scene: the bake's inputs from a scene (bake_inputs.h).
#include "scene/bake_inputs.h"

#include <ctime>

#include "bake/bake_dir.h"
#include "base/srgb.h"

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

glm::dvec3 texture_mean_linear(const Scene &s, const SceneTextureRef &t) {
  if (t.image < 0 || t.image >= static_cast<int>(s.images.size())) return glm::dvec3(1.0);
  const SceneImage &im = s.images[static_cast<size_t>(t.image)];
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i + 3 < im.rgba.size(); i += 4)
    sum += glm::dvec3(srgb_decode<double>(im.rgba[i]), srgb_decode<double>(im.rgba[i + 1]),
                      srgb_decode<double>(im.rgba[i + 2]));
  const size_t n = im.rgba.size() / 4;
  return n ? sum / static_cast<double>(n) : glm::dvec3(1.0);
}

std::vector<ModelEmitter> scene_model_emitters(const Scene &s, const std::vector<int> &face_of_draw,
                                               std::vector<int> *emitter_of) {
  std::vector<ModelEmitter> out;
  emitter_of->assign(s.primitives.size(), -1);
  for (size_t i = 0; i < s.primitives.size(); ++i) {
    const ScenePrimitive &p = s.primitives[i];
    if (i < face_of_draw.size() && face_of_draw[i] >= 0) continue;  // a world face: its own emission
    if (p.material < 0 || p.material >= static_cast<int>(s.materials.size())) continue;
    const SceneMaterial &m = s.materials[static_cast<size_t>(p.material)];
    const glm::dvec3 le = glm::dvec3(m.emission[0], m.emission[1], m.emission[2]) *
        texture_mean_linear(s, m.emissive_texture);
    if (!(le.x > 0 || le.y > 0 || le.z > 0)) continue;
    // Shared geometry: world positions, its front by the winding (mirrored by a negative determinant).
    const float *M = p.model;
    const double det = M[0] * (M[5] * M[10] - M[9] * M[6]) - M[4] * (M[1] * M[10] - M[9] * M[2]) +
        M[8] * (M[1] * M[6] - M[5] * M[2]);
    (*emitter_of)[i] = static_cast<int>(out.size());
    out.push_back(p.shared ? model_emitter(scene_world_positions(s, p), {}, p.shared->indices, det < 0,
                                           ts_v3d(le.x, le.y, le.z), p.where)
                           : model_emitter(p.position, p.normal, p.indices, false, ts_v3d(le.x, le.y, le.z), p.where));
  }
  return out;
}

bool build_scene_rays(const Scene &s, const std::vector<int> &face_of_draw, RayScene *rays, std::string *err,
                      const std::vector<int> *emitter_of) {
  for (size_t i = 0; i < s.primitives.size(); ++i) {
    const ScenePrimitive &p = s.primitives[i];
    // An instance of shared geometry occludes where its node puts it (scene_world_positions).
    const std::vector<float> world = p.shared ? scene_world_positions(s, p) : std::vector<float>();
    const int emitter = emitter_of && i < emitter_of->size() ? (*emitter_of)[i] : -1;
    const int id = i < face_of_draw.size() && face_of_draw[i] >= 0 ? face_of_draw[i]
        : emitter >= 0                                             ? model_emitter_id(static_cast<size_t>(emitter))
                                                                   : -2;
    if (!rays->add_mesh(p.shared ? world : p.position, p.shared ? p.shared->indices : p.indices, id, p.where, err)) {
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

// tiershade scene: the scene's irradiance volume and a model's cube from it (scene_volume.h).
#include "scene/scene_volume.h"

#include <cstring>

#include "bake/content_hash.h"
#include "bake/ray_scene.h"
#include "bake/sky.h"
#include "bake/volume_file.h"

std::vector<std::array<double, 6>> scene_model_regions(const Scene &s) {
  std::vector<std::array<double, 6>> r;
  bool any_reach = false;
  std::vector<uint8_t> seen(s.instances.size(), 0);
  for (const ScenePrimitive &p : s.primitives) {
    if (p.material < 0 || s.materials.at(static_cast<size_t>(p.material)).shader != SceneShader::Model) continue;
    if (p.instance < 0 || static_cast<size_t>(p.instance) >= s.instances.size() || seen[static_cast<size_t>(p.instance)])
      continue;
    seen[static_cast<size_t>(p.instance)] = 1;
    const SceneInstance &in = s.instances[static_cast<size_t>(p.instance)];
    any_reach = any_reach || in.has_reach;
    if (in.has_reach)
      r.push_back({in.reach_lo[0], in.reach_lo[1], in.reach_lo[2], in.reach_hi[0], in.reach_hi[1], in.reach_hi[2]});
    else  // a model that stays where it is: its centre
      r.push_back({in.center[0], in.center[1], in.center[2], in.center[0], in.center[1], in.center[2]});
  }
  if (!any_reach) r.clear();  // no model says where it can go: anywhere in the volume's box
  return r;
}

SceneVolumeSetup scene_volume_setup(const Scene &s, const std::vector<WorldFace> &faces) {
  SceneVolumeSetup u;
  world_faces_bounds(faces, u.lo, u.hi);
  if (s.volume.has_bounds) {
    std::memcpy(u.lo, s.volume.lo, sizeof u.lo);
    std::memcpy(u.hi, s.volume.hi, sizeof u.hi);
  }
  std::memcpy(u.set.spacing, s.volume.spacing, sizeof u.set.spacing);
  u.set.regions = scene_model_regions(s);
  u.set.fit = s.volume.fit == "mean" ? AmbientFit::Mean : AmbientFit::Lsq;
  if (s.sky.image >= 0) {  // a ray that leaves the scene sees the sky (glue/bake/sky.h), as the bake's do
    const SceneImage &si = s.images.at(static_cast<size_t>(s.sky.image));
    // (The sky's bake samples are no input of the volume: its rays each read sky_radiance. The
    // flat lightmaps they shape are hashed with the volume's inputs.)
    const BakeSky sky{si.rgba.data(), si.w, si.h, s.sky.scale};
    ContentHash h;
    h.value(si.w);
    h.value(si.h);
    h.value(s.sky.scale);
    h.values(si.rgba);
    u.sky_hash = h.h;
    u.set.sky_radiance = [sky](const glm::dvec3 &d) {
      const ts_vec3d r = sky_radiance(sky, ts_v3d(d.x, d.y, d.z));
      return glm::dvec3(r.x, r.y, r.z);
    };
  }
  return u;
}

bool bake_scene_volume(const Scene &s, const SceneSelection &sel, const std::vector<WorldFace> &faces,
                       const WorldBake &bake, int page_w, const RayScene &rays, IrradianceVolume *out,
                       std::string *err, const std::vector<ModelEmitter> *model_emitters) {
  *out = IrradianceVolume();
  bool models = false;
  for (const SceneDrawChoice &c : sel.draws) models = models || c.family == "model_lighting";
  if (!models || faces.empty() || !s.ambient.empty() || !s.volume.enabled) return true;  // only what the scene calls for
  SceneVolumeSetup u = scene_volume_setup(s, faces);
  u.set.model_emitters = model_emitters;  // the rays see the emissive models (glue/bake/area_lights.h)
  const std::vector<LuxelGrid> grids = flat_grids_from_page(bake.place, bake.page, page_w);
  const VolumeInputs in = volume_inputs(u.lo, u.hi, u.set, faces, grids, rays.content_hash(), u.sky_hash);
  u.set.threads = s.lightmaps.threads;  // the same bytes for any count
  if (!s.lightmaps.bake.empty())  // the bake directory's volume, refused when stale (glue/bake/volume_file.h)
    return read_volume_dir(s.lightmaps.bake, in, out, err);
  if (!bake_irradiance_volume(u.lo, u.hi, faces, grids, rays, u.set, out, err)) {
    *err = s.path + ": extras.tiershade.volume: " + *err;
    return false;
  }
  out->inputs_hash = volume_inputs_hash(in);
  out->inputs = in;
  return true;
}

void scene_volume_cube(const Scene &s, const IrradianceVolume &v, const double center[3], float cube[6][3]) {
  volume_cube_at(v, center, scene_volume_lookup(s), cube, nullptr);
}

VolumeLookup scene_volume_lookup(const Scene &s) {
  return s.volume.lookup == "inverse_square" ? VolumeLookup::InverseSquare : VolumeLookup::Trilinear;
}

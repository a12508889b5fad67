// tiershade scene: the scene's irradiance volume and a model's cube from it (scene_volume.h).
#include "scene/scene_volume.h"

#include <cstring>

#include "bake/content_hash.h"
#include "bake/ray_scene.h"
#include "bake/sky.h"
#include "bake/volume_file.h"

bool bake_scene_volume(const Scene &s, const SceneSelection &sel, const std::vector<WorldFace> &faces,
                       const WorldBake &bake, int page_w, const RayScene &rays, IrradianceVolume *out,
                       std::string *err) {
  *out = IrradianceVolume();
  bool models = false;
  for (const SceneDrawChoice &c : sel.draws) models = models || c.family == "model_lighting";
  if (!models || faces.empty() || !s.ambient.empty() || !s.volume.enabled) return true;  // only what the scene calls for
  double lo[3], hi[3];
  world_faces_bounds(faces, lo, hi);
  if (s.volume.has_bounds) {
    std::memcpy(lo, s.volume.lo, sizeof lo);
    std::memcpy(hi, s.volume.hi, sizeof hi);
  }
  VolumeSettings vs;
  uint64_t sky_hash = 0;
  std::memcpy(vs.spacing, s.volume.spacing, sizeof vs.spacing);
  vs.fit = s.volume.fit == "mean" ? AmbientFit::Mean : AmbientFit::Lsq;
  if (s.sky.image >= 0) {  // a ray that leaves the scene sees the sky (glue/bake/sky.h), as the bake's do
    const SceneImage &si = s.images.at(static_cast<size_t>(s.sky.image));
    const BakeSky sky{si.rgba.data(), si.w, si.h, s.sky.scale, s.sky.samples};
    ContentHash h;
    h.value(si.w);
    h.value(si.h);
    h.value(s.sky.scale);
    h.value(s.sky.samples);
    h.values(si.rgba);
    sky_hash = h.h;
    vs.sky_radiance = [sky](const glm::dvec3 &d) {
      const ts_vec3d r = sky_radiance(sky, ts_v3d(d.x, d.y, d.z));
      return glm::dvec3(r.x, r.y, r.z);
    };
  }
  const std::vector<LuxelGrid> grids = flat_grids_from_page(bake.place, bake.page, page_w);
  const uint64_t hash = volume_inputs_hash(lo, hi, vs, faces, grids, rays.content_hash(), sky_hash);
  if (!s.lightmaps.bake.empty()) {  // the bake directory's volume, refused when stale (glue/bake/volume_file.h)
    if (!read_volume_dir(s.lightmaps.bake, hash, out, err)) return false;
    return true;
  }
  if (!bake_irradiance_volume(lo, hi, faces, grids, rays, vs, out, err)) {
    *err = s.path + ": extras.tiershade.volume: " + *err;
    return false;
  }
  out->inputs_hash = hash;
  return true;
}

void scene_volume_cube(const Scene &s, const IrradianceVolume &v, const double center[3], float cube[6][3]) {
  volume_cube_at(v, center, scene_volume_lookup(s), cube, nullptr);
}

VolumeLookup scene_volume_lookup(const Scene &s) {
  return s.volume.lookup == "inverse_square" ? VolumeLookup::InverseSquare : VolumeLookup::Trilinear;
}

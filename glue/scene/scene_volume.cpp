// tiershade scene: the scene's irradiance volume and a model's cube from it (scene_volume.h).
#include "scene/scene_volume.h"

#include <cstring>

#include "bake/sky.h"

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
  std::memcpy(vs.spacing, s.volume.spacing, sizeof vs.spacing);
  vs.fit = s.volume.fit == "mean" ? AmbientFit::Mean : AmbientFit::Lsq;
  if (s.sky.image >= 0) {  // a ray that leaves the scene sees the sky (glue/bake/sky.h), as the bake's do
    const SceneImage &si = s.images.at(static_cast<size_t>(s.sky.image));
    const BakeSky sky{si.rgba.data(), si.w, si.h, s.sky.scale, s.sky.samples};
    vs.sky_radiance = [sky](const glm::dvec3 &d) {
      const ts_vec3d r = sky_radiance(sky, ts_v3d(d.x, d.y, d.z));
      return glm::dvec3(r.x, r.y, r.z);
    };
  }
  if (!bake_irradiance_volume(lo, hi, faces, flat_grids_from_page(bake.place, bake.page, page_w), rays, vs, out,
                              err)) {
    *err = s.path + ": extras.tiershade.volume: " + *err;
    return false;
  }
  return true;
}

void scene_volume_cube(const Scene &s, const IrradianceVolume &v, const double center[3], float cube[6][3]) {
  volume_cube_at(v, center, s.volume.lookup == "inverse_square" ? VolumeLookup::InverseSquare : VolumeLookup::Trilinear,
                 cube, nullptr);
}

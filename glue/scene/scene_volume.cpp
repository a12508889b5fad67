// tiershade scene: the scene's irradiance volume and a model's cube from it (scene_volume.h).
#include "scene/scene_volume.h"

#include <cstring>

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

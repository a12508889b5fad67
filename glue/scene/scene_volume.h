// tiershade scene: a scene's irradiance volume (glue/bake/irradiance_volume.h) from its "volume"
// settings, baked when the scene calls for it, and a model's ambient cube from it
// (docs/irradiance_volume.md). Hand-typed "ambient" samples stay an override: no volume then.
#pragma once
#include <string>
#include <vector>

#include "bake/irradiance_volume.h"
#include "bake/world_bake.h"
#include "scene/scene.h"
#include "scene/selection.h"

// What the scene's volume is baked from: its box (volume.bounds or the faces' box), the settings
// (volume.spacing, volume.fit, the sky hook when the scene has a sky) and the sky's hash (0: none),
// as bake_scene_volume uses them (the accuracy bench traces its ground truth with the same sky).
struct SceneVolumeSetup {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  VolumeSettings set;
  uint64_t sky_hash = 0;
};
SceneVolumeSetup scene_volume_setup(const Scene &s, const std::vector<WorldFace> &faces);

// Where the scene's models can be (VolumeSettings::regions): when any model node names its reach
// (extras.tiershade.reach), the union of those boxes and the other models' centres; otherwise empty
// (anywhere in the volume's box: no model says where it can go).
std::vector<std::array<double, 6>> scene_model_regions(const Scene &s);

// Bakes the volume (or, when the scene reads a bake directory, extras.tiershade.lightmaps.bake, reads
// it from there, refused when stale: glue/bake/volume_file.h) when the scene has world faces, model draws, no "ambient" samples and the volume
// enabled; otherwise leaves *out empty (no samples). Bounds: the scene's "bounds" or the faces' box.
bool bake_scene_volume(const Scene &s, const SceneSelection &sel, const std::vector<WorldFace> &faces,
                       const WorldBake &bake, int page_w, const RayScene &rays, IrradianceVolume *out,
                       std::string *err, const std::vector<ModelEmitter> *model_emitters = nullptr);

// The cube at a model's centre with the scene's lookup (trilinear or inverse-square).
void scene_volume_cube(const Scene &s, const IrradianceVolume &v, const double center[3], float cube[6][3]);
// The scene's lookup: volume.lookup "trilinear" (default) or "inverse_square".
VolumeLookup scene_volume_lookup(const Scene &s);

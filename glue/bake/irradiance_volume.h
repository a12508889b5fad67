// tiershade bake: the irradiance volume (the talk: "pre-compute irradiance samples throughout the
// environment, 4'x4'x8' density", each an ambient cube): a grid of samples over a box, each sample an
// ambient cube fitted (glue/bake/ambient_fit.h) to the radiance seen along 162 ray directions through
// the bake's ray scene (fact sheet section 3, vrad's ComputeAmbientFromSphericalSamples): a world
// face's front returns its radiosity (flat lightmap x reflectivity + emission, bounce.h's
// luxel_exitant), a face's back counts as a back-face hit (radiance 0), other geometry (models) is
// passed through to the world behind (as vrad, which never sees dynamic models; with
// VolumeSettings::models_occlude it is a black back-face hit instead), a miss returns the sky hook's
// radiance (0 without one); an emissive model's front returns its emission (VolumeSettings::model_emitters).
// Samples inside the world's solids (most rays on back faces) are invalid.
// A model's cube: trilinear over the valid samples around it, or Source's inverse-square weights
// 1/(d^2 + 1) (d in Source units, inches; fact sheet section 3, Mod_LeafAmbientColorAtPos).
// docs/irradiance_volume.md.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "bake/ambient_fit.h"
#include "bake/bounce.h"
#include "offline/lightmap_page.h"

class RayScene;
struct WorldFace;
struct ModelEmitter;

// Trilinear (the default), Source's inverse-square over the 8 around the point, or the nearest valid
// sample of the whole volume (what a hand-placed sample gives; for the accuracy table).
enum class VolumeLookup { Trilinear, InverseSquare, Nearest };

struct VolumeSettings {
  // Sample spacing along x, y, z in scene units (glTF metres, +Y up): Source's 4 ft x 8 ft (up) x 4 ft.
  double spacing[3] = {1.2192, 2.4384, 1.2192};
  AmbientFit fit = AmbientFit::Lsq;  // Mean, Lsq or LsqRadiance (LsqPixels is for probes only)
  // A sample whose share of back-face hits (back faces, and other geometry when models_occlude) is
  // above this is invalid.
  double max_back_share = 0.5;
  // The sky hook: the radiance of a ray that misses everything (null: 0). The sky bake adds it.
  std::function<glm::dvec3(const glm::dvec3 &dir)> sky_radiance;
  int threads = 0;  // 0: all cores (the result is the same for any count)
  // Whether other geometry (models) stops a ray as a black back-face hit (true) or the ray goes on
  // through it to the world (false, the default: the world alone, as vrad, which never sees dynamic
  // models; a denser volume's samples next to or inside models are not darkened by them; measured by
  // `bench --section ambient`, docs/irradiance_volume.md). The accuracy bench's reference keeps true.
  bool models_occlude = false;
  // Where models can be (the "samples only where models can be"): boxes [lo, hi] that a
  // model's centre may occupy (a static model's box is its centre point). Empty: anywhere in the
  // volume's box. Otherwise only the samples a lookup at a point inside a box can read are baked
  // (volume_needed_samples); the others stay invalid and cost no rays.
  std::vector<std::array<double, 6>> regions;
  // The emissive model primitives (glue/bake/area_lights.h; null: none): a ray that reaches one's
  // front sees its emission, as it sees an emitting face's (they are the world's light fixtures).
  const std::vector<ModelEmitter> *model_emitters = nullptr;
};

// What a volume's samples depend on, in parts (glue/bake/volume_file.h: volume_inputs), so that a
// stale volume in a bake directory can say what changed: hashes of the box, the settings, the
// geometry (world faces' frames and every triangle the rays see), the faces' materials (reflectivity,
// emission), their flat lightmaps and the sky; and the box's and settings' values themselves (the
// manifest records them, a stale volume names the ones that differ).
struct VolumeInputs {
  uint64_t bounds = 0, settings = 0, geometry = 0, materials = 0, lightmaps = 0, sky = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, spacing[3] = {0, 0, 0};
  AmbientFit fit = AmbientFit::Lsq;
  double max_back_share = 0;
  bool models_occlude = false;
  std::vector<std::array<double, 6>> regions;  // VolumeSettings::regions (part of the bounds)
};

struct IrradianceVolume {
  int n[3] = {0, 0, 0};  // samples along x, y, z
  double origin[3] = {0, 0, 0};  // the first sample's position
  double step[3] = {1, 1, 1};  // the grid's actual spacing (the box divided into n cells, samples at cell centres)
  std::vector<std::array<std::array<float, 3>, 6>> cube;  // (k * n[1] + j) * n[0] + i
  std::vector<uint8_t> valid;
  std::vector<float> back_share;
  double bake_ms = 0;
  long rays = 0;
  long baked = 0;  // samples traced (all of them without VolumeSettings::regions)
  // The content hash of what the samples depend on (glue/bake/volume_file.h: volume_inputs_hash): the
  // bake directory's copy is refused when it differs from the scene's; `inputs`: its parts.
  uint64_t inputs_hash = 0;
  VolumeInputs inputs;
  size_t index(int i, int j, int k) const { return (static_cast<size_t>(k) * n[1] + j) * n[0] + i; }
  glm::dvec3 position(int i, int j, int k) const;
  size_t bytes() const;  // the samples' memory (cubes, validity, back-face shares)
};

// Which samples of a grid (n, origin, step as IrradianceVolume holds them) a lookup at a point of one
// of `regions` can read (1) and which it cannot (0): along each axis, the samples whose position lies
// within one step of the box, clamped to the grid, so the 8 samples around any point inside a box
// (volume_cube_at) are all baked. All 1 without regions. The nearest-valid fallback of a lookup with
// none of its 8 valid then searches the baked samples only.
std::vector<uint8_t> volume_needed_samples(const IrradianceVolume &grid, const std::vector<std::array<double, 6>> &regions);

// The 162 ray directions: the vertices of an icosahedron whose faces are split into 4 x 4 triangles,
// projected to the sphere (10 * 4^2 + 2 = 162, the count of vrad's g_anorms; fact sheet section 3).
// Deterministic, nearly uniform; each stands for 4pi / 162 of solid angle.
const std::vector<glm::dvec3> &volume_ray_directions();

// The flat lightmap of every face as a luxel grid (value k = 0 of each luxel) read from a baked page.
std::vector<LuxelGrid> flat_grids_from_page(const std::vector<lm_face_place> &place, const std::vector<float> &page,
                                            int page_w);

// The box of the world faces' corners (the volume's default bounds).
void world_faces_bounds(const std::vector<WorldFace> &faces, double lo[3], double hi[3]);

// Bakes the volume over the box [lo, hi]: n = max(1, round(extent / spacing)) cells per axis, one
// sample at each cell's centre. `faces` and `grids` (flat_grids_from_page) are the world; `rays` has
// every triangle, a face's triangles carrying its index as id (glue/scene/prepare.cpp's scene).
bool bake_irradiance_volume(const double lo[3], const double hi[3], const std::vector<WorldFace> &faces,
                            const std::vector<LuxelGrid> &grids, const RayScene &rays, const VolumeSettings &set,
                            IrradianceVolume *out, std::string *err);

// The radiance a ray from p along unit d sees (what a sample's and the ground truth's rays add up): a
// world face's front: its radiosity at the hit; a miss: the sky hook; a face's back: 0 with *back set
// (may be null); other geometry: passed through (set.models_occlude false, the default) or 0 with
// *back set (true).
glm::dvec3 volume_ray_radiance(const glm::dvec3 &p, const glm::dvec3 &d, const std::vector<WorldFace> &faces,
                               const std::vector<LuxelGrid> &grids, const RayScene &rays, const VolumeSettings &set,
                               bool *back);

// The cube of one sample position (what bake_irradiance_volume computes for each grid point).
// Returns the share of back-face hits.
double volume_sample_cube(const glm::dvec3 &p, const std::vector<WorldFace> &faces,
                          const std::vector<LuxelGrid> &grids, const RayScene &rays, const VolumeSettings &set,
                          float cube[6][3]);

struct VolumeContribution {
  int i = 0, j = 0, k = 0;  // the sample
  double weight = 0;  // its normalised weight
};
// The interpolated cube at p: the valid samples among the 8 around p (p clamped into the grid of
// sample centres), weighted trilinearly or by 1/(d^2 + 1), renormalised over the valid ones; with
// none valid (or with VolumeLookup::Nearest), the nearest valid sample of the whole volume. False (cube zero) when no sample is valid.
// `contrib` (may be null) receives the samples used and their weights (`tiershade light --at`).
bool volume_cube_at(const IrradianceVolume &v, const double p[3], VolumeLookup lookup, float cube[6][3],
                    std::vector<VolumeContribution> *contrib);

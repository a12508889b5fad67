// tiershade bake: diffuse interreflection (radiosity) on the baked luxel grids, by gathering: each
// pass shoots the radiance the previous pass added (the first: the faces' emission plus their
// reflection of the direct light) back into every luxel through cosine-weighted gather rays, until
// the light a pass adds falls below a share of all the light so far or the pass count is reached (vrad's bounces, fact sheet
// section 1). Per basis vector as vrad: each bumped value takes light only from directions on the
// face's front with a positive dot product with its basis vector.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "math/ts_math.h"

class RayScene;
struct WorldFace;

// One face's luxel grid: w x h luxels (grid points, a = i / (w - 1), b = j / (h - 1)), 4 values
// each (flat, b0, b1, b2) as rgb.
struct LuxelGrid {
  int w = 0, h = 0;
  std::vector<ts_vec3d> v;  // (j * w + i) * 4 + k
  ts_vec3d &at(int i, int j, int k) { return v[(static_cast<size_t>(j) * w + i) * 4 + k]; }
  const ts_vec3d &at(int i, int j, int k) const { return v[(static_cast<size_t>(j) * w + i) * 4 + k]; }
};

struct BounceSettings {
  int max_bounces = 0;  // 0: direct light only
  int gather_rays = 64;  // per luxel, pass and value (flat, b0, b1, b2; rounded up to a square: stratified)
  double threshold = 1e-3;  // stop when a pass adds at most this share of the flat light so far (summed over luxels)
  int threads = 0;  // 0: all cores; the result is the same for any count
  uint64_t seed = 0;  // mixed into every luxel's stream: another seed, independent noise
  // The faces' emission already reached the luxels as area lights (glue/bake/area_lights.h): the
  // first pass sends only the light the faces reflect (set by bake_world; docs/baking.md).
  bool emission_sampled = false;
};

struct BounceReport {
  int passes = 0;  // bounces computed
  long rays = 0;
  std::vector<double> added;  // per pass: the largest flat value it added
};

// The radiance face f leaves at (a, b) in [0, 1]^2: its emission + its reflectivity x the flat value,
// bilinear over the grid.
ts_vec3d luxel_exitant(const WorldFace &f, const LuxelGrid &g, double a, double b);

// Adds the interreflected light to `grids` (one per face, the direct light on entry). `rays`: every
// triangle of the scene, a face's triangles carrying its index as id (other geometry: negative ids,
// it occludes and reflects nothing). The faces' reflectivity and emission are WorldFace's.
bool bounce_light(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
                  const RayScene &rays, const BounceSettings &set, std::vector<LuxelGrid> *grids, BounceReport *report,
                  std::string *err);

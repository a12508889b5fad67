// tiershade bake: diffuse interreflection (radiosity) on the baked luxel grids, by gathering: each
// pass shoots the radiance the previous pass added (the first: the faces' emission plus their
// reflection of the direct light) back into every luxel through cosine-weighted gather rays, until
// the light a pass adds falls below a share of all the light so far or the pass count is reached
// (vrad's bounces, fact sheet section 1). The same rays every pass, as vrad iterates its bounces
// over transfers computed once: the first pass keeps each ray's hit, the passes after it read them
// back (docs/baking.md, "Bounces"). Per basis vector as vrad: each bumped value takes light only from
// directions on the face's front with a positive dot product with its basis vector (a ratio
// estimator over the lobe's front share).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bake/bake_quality.h"
#include "math/ts_math.h"

class RayScene;
struct WorldFace;
struct ModelEmitter;

// One face's luxel grid: w x h luxels (grid points, a = i / (w - 1), b = j / (h - 1)), 4 values
// each (flat, b0, b1, b2) as rgb.
struct LuxelGrid {
  int w = 0, h = 0;
  std::vector<ts_vec3d> v;  // (j * w + i) * 4 + k
  ts_vec3d &at(int i, int j, int k) { return v[(static_cast<size_t>(j) * w + i) * 4 + k]; }
  const ts_vec3d &at(int i, int j, int k) const { return v[(static_cast<size_t>(j) * w + i) * 4 + k]; }
};

struct BounceSettings {
  int max_bounces = kBakeDraft.bounces;  // 0: direct light only
  int gather_rays = kBakeDraft.gather_rays;  // per luxel, pass and value (flat, b0, b1, b2; rounded up to a square: stratified)
  double threshold = kBakeDraft.threshold;  // stop when a pass adds at most this share of the flat light so far (summed over luxels)
  int threads = 0;  // 0: all cores; the result is the same for any count
  uint64_t seed = 0;  // mixed into every luxel's stream: another seed, independent noise
  // The faces' emission already reached the luxels as area lights (glue/bake/area_lights.h): the
  // first pass sends only the light the faces reflect (set by bake_world; docs/baking.md).
  bool emission_sampled = false;
  // The emissive model primitives (glue/bake/area_lights.h; null: none): when their emission was not
  // sampled, the first pass's gather rays that reach one's front take its emission (set by bake_world).
  const std::vector<ModelEmitter> *model_emitters = nullptr;
};

struct BounceReport {
  int passes = 0;  // bounces computed
  long rays = 0;  // gather rays traced
  long cached = 0;  // gather rays whose hits a later pass read back (traced once, in the first pass)
  std::vector<double> added;  // per pass: the largest flat value it added
  std::vector<long> pass_rays;  // per pass: its gather rays
  std::vector<double> pass_ms;  // per pass: its time (from the run that computed it)
  long skipped_black = 0;  // luxels of faces of reflectivity 0 that gathered nothing (they show black)
};

// What the bake holds after a pass (0: the direct light; k: bounce k), all that pass k + 1 needs:
// pass k + 1 depends on pass k's state alone (docs/baking.md, "Work units and checkpoints").
struct BakePassState {
  int pass = 0;  // passes done (0: direct only)
  bool stopped = false;  // no pass follows (the threshold or the count was reached)
  std::vector<LuxelGrid> grids;  // every value so far, per face
  std::vector<std::vector<ts_vec3d>> send;  // bounces: the radiance each luxel sends into pass + 1
  double total = 0;  // the flat light so far (the stopping rule's sum)
  double direct_ms = 0;  // the direct pass (from the run that computed it)
  long direct_rays = 0;
  BounceReport report;  // the bounces so far
};

// Hooks of a bake (all optional): a state to resume from and a call after each finished pass
// (checkpoints: glue/bake/bake_dir.h), progress after each face of a pass, on the calling thread.
struct BakeHooks {
  const BakePassState *resume = nullptr;  // bounce_light: start after resume->pass (grids given as *grids)
  std::function<bool(const BakePassState &, std::string *)> on_pass;
  std::function<void(const std::string &pass, long done, long total)> progress;
};

// The radiance face f leaves at (a, b) in [0, 1]^2: its emission + its reflectivity x the flat value,
// bilinear over the grid.
ts_vec3d luxel_exitant(const WorldFace &f, const LuxelGrid &g, double a, double b);

// Adds the interreflected light to `grids` (one per face, the direct light on entry). `rays`: every
// triangle of the scene, a face's triangles carrying its index as id (other geometry: negative ids,
// it occludes and reflects nothing). The faces' reflectivity and emission are WorldFace's.
bool bounce_light(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
                  const RayScene &rays, const BounceSettings &set, std::vector<LuxelGrid> *grids, BounceReport *report,
                  std::string *err, const BakeHooks *hooks = nullptr, BakePassState *state = nullptr);

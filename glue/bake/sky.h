// tiershade bake: the sky's light on the luxels (vrad's emit_skyambient, fact sheet section 1): an
// HDR lat-long image (extras.tiershade.sky, docs/scenes.md) seen through the scene's openings.
// Every luxel sends stratified rays in the cosine lobe of each of its values (the face normal for
// the flat value, each basis vector b_k for the bumped ones, a direction behind the face counting
// 0, exactly as the bounces gather: glue/bake/bounce.h); a ray that leaves the scene returns the
// sky's radiance in its direction, a ray that hits anything returns nothing. The sky is its own
// pass: its light is added to the luxels like the direct light, so the first bounce reflects it
// and the bounces' gather rays that miss return nothing (docs/baking.md, "The sky").
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bake/bounce.h"
#include "math/ts_math.h"

class RayScene;
struct WorldFace;

struct BakeSky {
  // Lat-long radiance (glue's probe convention, glue/scene/textures.cpp cube_from_probe): +Y up,
  // u = atan2(x, -z) / 2pi + 0.5 across, v = acos(y) / pi down, RGBA rows with row 0 the bottom
  // (ImageF). Not owned: it outlives the bake (the scene's image).
  const float *rgba = nullptr;
  int w = 0, h = 0;
  double scale = 1;  // radiance multiplier
  int samples = kBakeDraft.sky_samples;  // rays per luxel and value (rounded up to a square: stratified)
  bool present() const { return rgba != nullptr && w > 0 && h > 0 && scale > 0; }
};

// The sky's radiance towards direction d (non-zero) (bilinear, wrapping in u), times its scale.
ts_vec3d sky_radiance(const BakeSky &sky, const ts_vec3d &d);

struct SkyReport {
  long rays = 0;
  double ms = 0;
};

// Adds the sky's light to `grids` (one per face; all four values of bumped faces, the flat value
// alone of faces the shader reads flat, whose bumped values the shader never reads).
bool sky_light(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
               const RayScene &rays, const BakeSky &sky, int threads, uint64_t seed, std::vector<LuxelGrid> *grids,
               SkyReport *report, std::string *err);

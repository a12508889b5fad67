// tiershade bake: emissive faces as area lights (vrad's emit_surface, fact sheet section 1): every
// luxel samples each emitting world face directly, with shadow rays, so that small bright panels
// light the scene without the noise of finding them by gather rays. The points on a rectangular
// emitter are drawn uniformly in the solid angle it subtends at the luxel (Urena, Fajardo, King,
// "An Area-Preserving Parametrization for Spherical Rectangles", EGSR 2013), stratified, so each
// sample's weight Le x (solid angle) x (a_k . w)+ / pi is bounded even where a luxel touches the
// emitter. The emission thus reaches the luxels here only: bake_world then tells the bounces not to
// send it again (BounceSettings::emission_sampled), their first pass reflecting the light the
// luxels received (docs/baking.md, "Emitters").
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake/bounce.h"
#include "math/ts_math.h"

class RayScene;
struct WorldFace;

struct AreaLightSettings {
  int samples = 16;  // points per luxel and emitter (rounded up to a square: stratified); 0: none
  int threads = 0;
  uint64_t seed = 0;
};

struct AreaLightReport {
  int emitters = 0;  // faces with a non-zero emission
  long rays = 0;
  double ms = 0;
};

// The spherical rectangle of a rectangle (corner c, orthogonal edges ex, ey) seen from o, sampled
// uniformly in solid angle (Urena et al. 2013, section 3). ok false when o lies in its plane.
struct SphericalRect {
  bool ok = false;
  double solid_angle = 0;
  glm::dvec3 o, x, y, z;  // o and the rectangle's frame: x, y along its edges, z towards o's side's opposite
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0, z0 = 0, b0 = 0, b1 = 0, k = 0;
};
SphericalRect spherical_rect(const glm::dvec3 &o, const glm::dvec3 &c, const glm::dvec3 &ex, const glm::dvec3 &ey);
// The point of the rectangle for (u, v) in [0, 1]^2; the map is area-preserving in solid angle.
glm::dvec3 spherical_rect_point(const SphericalRect &r, double u, double v);

// Adds the light of every emitting face to `grids` (all four values; shadow rays through `rays`).
bool area_lights(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
                 const RayScene &rays, const AreaLightSettings &set, std::vector<LuxelGrid> *grids,
                 AreaLightReport *report, std::string *err);

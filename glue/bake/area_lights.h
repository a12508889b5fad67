// tiershade bake: emissive surfaces as area lights (vrad's emit_surface, fact sheet section 1): every
// luxel samples each emitter directly, with shadow rays, so that small bright panels light the
// scene without the noise of finding them by gather rays. Emitters are the emitting world faces
// (planar rectangles and TEXCOORD_1 charts) and the model primitives with an emissive material
// (ModelEmitter: no lightmap of their own, they only light the world). A rectangle's points are
// drawn uniformly in the solid angle it subtends at the luxel (Urena, Fajardo, King, "An
// Area-Preserving Parametrization for Spherical Rectangles", EGSR 2013); a triangle mesh's (a chart,
// a model) uniformly in the solid angle of its triangles that face the luxel: a triangle picked by
// its solid angle, then a point of its spherical triangle (Arvo, "Stratified Sampling of Spherical
// Triangles", SIGGRAPH 1995); both stratified, so each sample's weight Le x (solid angle) x
// (a_k . w)+ / pi is bounded even where a luxel touches the emitter. The emission thus reaches the
// luxels here only: bake_world then tells the bounces not to send it again
// (BounceSettings::emission_sampled), their first pass reflecting the light the luxels received
// (docs/baking.md, "Emitters").
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

// A model primitive with an emissive material (glTF emissiveFactor x the emissive texture's mean x
// KHR_materials_emissive_strength): it lights the world faces as an area light (and the irradiance
// volume's rays see it) but has no lightmap. Its ray-scene id is model_emitter_id(k), k its index in
// WorldBakeInput::model_emitters.
struct ModelEmitter {
  std::string where;  // the primitive, for messages
  // 9 per triangle (world space), in the primitive's triangle order (a ray hit's triangle index),
  // each wound counter-clockwise seen from its front, the side it emits from.
  std::vector<double> tri;
  ts_vec3d emission = {0, 0, 0};  // emitted radiance (linear), in lightmap units (docs/baking.md)
  int triangles() const { return static_cast<int>(tri.size() / 9); }
};
// Ray-scene ids: a world face's is its index, other geometry -2, model emitter k -3 - k.
inline int model_emitter_id(size_t k) { return -3 - static_cast<int>(k); }
inline int model_emitter_of_id(int id) { return -3 - id; }  // >= 0: an emitter's index
// An emitter from a primitive's world-space triangles (positions xyz, indices; normals xyz per vertex
// or empty): each triangle's front is the side its vertex normals face, else its winding's
// (counter-clockwise, glTF's front face), flipped when `mirrored` (a node transform of negative
// determinant, which glTF says flips the winding).
ModelEmitter model_emitter(const std::vector<float> &position, const std::vector<float> &normal,
                           const std::vector<uint32_t> &indices, bool mirrored, const ts_vec3d &emission,
                           const std::string &where);
// The emitter's radiance towards a ray of unit direction d that hit its triangle t: its emission
// from the front, nothing from the back (the ray goes on: a model's back is not the world's).
bool model_emitter_seen(const ModelEmitter &e, int t, const glm::dvec3 &d, glm::dvec3 *radiance);

struct AreaLightReport {
  int emitters = 0;  // faces and model primitives with a non-zero emission
  int meshes = 0;  // of them, triangle meshes (TEXCOORD_1 charts, models): sampled by spherical triangles
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

// A spherical triangle (unit vertices a, b, c seen from a point) sampled uniformly in solid angle
// (Arvo 1995, figure 2): u picks the sub-triangle of area u x its area, v the point along its edge.
struct SphericalTri {
  glm::dvec3 a, b, c;
  double area = 0, alpha = 0, cos_c = 0;  // solid angle, the angle at a, cos of the arc a-b
};
SphericalTri spherical_tri(const glm::dvec3 &a, const glm::dvec3 &b, const glm::dvec3 &c);
glm::dvec3 spherical_tri_dir(const SphericalTri &t, double u, double v);  // a unit direction inside it

// Adds the light of every emitter (the emitting faces and `models`) to `grids` (all four values;
// shadow rays through `rays`).
bool area_lights(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
                 const std::vector<ModelEmitter> &models, const RayScene &rays, const AreaLightSettings &set,
                 std::vector<LuxelGrid> *grids, AreaLightReport *report, std::string *err);

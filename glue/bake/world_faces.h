// tiershade bake: world faces, what a lightmap page holds: a planar quad charted automatically (its
// own front normal, from the winding and the vertex normals) or a mesh's TEXCOORD_1 chart
// (glue/bake/charts.h); points on a face, the frame of a luxel and where a ray hit a face (rays go
// through glue/bake/ray_scene.h).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bake/charts.h"
#include "bake/ray_scene.h"
#include "math/ts_math.h"

struct WorldFace {
  const char *name;
  ts_vec3d origin, u, v;  // corner and unit edge directions (u = the S texture axis, v = T)
  double su, sv;  // edge lengths
  int probe;  // explicit cube-map probe, or -1 for the nearest
  ts_vec3d normal = {0, 0, 0};  // the front normal (the lit side), not necessarily unit; bake_world refuses zero
  ts_vec3d reflectivity = {0, 0, 0};  // diffuse reflectance for bounces (the base colour's mean, linear)
  ts_vec3d emission = {0, 0, 0};  // emitted radiance (linear), in lightmap units (docs/baking.md)
  bool bumped = true;  // the material reads the bumped lightmaps (a normal map): else bounces gather the flat one only
  // A TEXCOORD_1 chart (glue/bake/charts.h): its luxels' own frames; origin, u, v, su, sv then bound
  // the mesh (the probe choice's centre). Null: the planar quad above.
  std::shared_ptr<const WorldChart> chart = nullptr;
};

// A face from one planar quad of world-space triangles (positions xyz, normals xyz, tangents
// xyzw or empty; every index < the vertex count): the front is the side of the first
// triangle's winding normal that its vertex normal faces; u is the first vertex's tangent made
// orthogonal to it (else an axis), v = normal x u times the tangent's handedness. The face
// spans the vertices' extent along u and v; frame_min receives that extent's low corner
// (dot(p, u), dot(p, v)) for the lightmap coordinates of vertex p: ((p.u - min_u) / su, ...).
// False for fewer than 3 indices or a degenerate first triangle.
bool world_face_from_quad(const std::vector<float> &position, const std::vector<float> &normal,
                          const std::vector<float> &tangent, const std::vector<uint32_t> &indices, const char *name,
                          int probe, WorldFace *out, double frame_min[2]);

// A face from a mesh's TEXCOORD_1 chart (glue/bake/charts.h chart_build, its errors naming `where`):
// origin, u, v, su, sv bound the mesh in the frame of its area-weighted normal (normal: that mean,
// else the first triangle's).
bool world_face_from_chart(const std::vector<float> &position, const std::vector<float> &normal,
                           const std::vector<float> &tangent, const std::vector<float> &uv1,
                           const std::vector<uint32_t> &indices, const char *name, int probe, double luxels_per_unit,
                           const std::string &where, WorldFace *out, std::string *err);

ts_vec3d world_face_normal(const WorldFace &f);  // the unit front normal
ts_vec3d world_face_point(const WorldFace &f, double a, double b);  // origin + a su u + b sv v, (a, b) in [0, 1]^2
// Where the bake samples (a, b): world_face_point with (a, b) clamped to the face inset by
// kWorldSampleInset scene units, so that no sample lies on a neighbouring face's plane (a ray from
// a room's corner would otherwise slip out between the faces, or hit the wall it stands on).
const double kWorldSampleInset = 1e-3;
ts_vec3d world_face_sample(const WorldFace &f, double a, double b);


// The frame of luxel (i, j) of face f's w x h grid: a planar face's sample point at (i / (w - 1),
// j / (h - 1)), its normal and its basis `bump`; a chart's luxel its own (lit false: nothing to bake).
LuxelFrame world_luxel_frame(const WorldFace &f, const ts_vec3d bump[3], int i, int j, int w, int h);

// Where the ray of direction d hit face f (at q, hit h of the face's mesh): false when it hit the
// face's back (a face's back sends nothing); else the face's grid coordinates (a, b) in [0, 1].
bool world_face_hit(const WorldFace &f, const glm::dvec3 &q, const RayScene::Hit &h, const glm::dvec3 &d, double *a,
                    double *b);

// tiershade scene: a primitive's geometry in world space whether it is flattened or an instance
// of shared object-space arrays (glue/scene/scene.h), and the bytes a scene's geometry holds.
#include <set>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/scene.h"

namespace {

glm::dmat4 world_of(const Scene &s, const ScenePrimitive &p) {
  return glm::make_mat4(s.instances.at(static_cast<size_t>(p.instance)).world);
}

// p0 through w in double, rounded to float (what the loader does to a flattened primitive's points).
void put_point(const glm::dmat4 &w, const float *p0, float *out) {
  const glm::dvec4 q = w * glm::dvec4(p0[0], p0[1], p0[2], 1.0);
  for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(q[k]);
}

// v through the rotation m in double, rounded to float (a unit vector stays unit to rounding; not
// renormalised, so that the identity leaves it as it is).
void put_direction(const glm::dmat3 &m, const float *v, float *out) {
  const glm::dvec3 q = m * glm::dvec3(v[0], v[1], v[2]);
  for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(q[k]);
}

}  // namespace

std::vector<float> scene_world_positions(const Scene &s, const ScenePrimitive &p) {
  if (!p.shared) return p.position;
  const glm::dmat4 w = world_of(s, p);
  const std::vector<float> &obj = p.shared->position;
  std::vector<float> out(obj.size());
  for (size_t i = 0; i + 2 < obj.size(); i += 3) put_point(w, &obj[i], &out[i]);
  return out;
}

ScenePrimitive scene_flattened(const Scene &s, const ScenePrimitive &p) {
  if (!p.shared) return p;
  ScenePrimitive out = p;
  const SceneGeometry &g = *p.shared;
  out.shared.reset();
  for (int i = 0; i < 16; ++i) out.model[i] = i % 5 == 0 ? 1.f : 0.f;
  out.position = scene_world_positions(s, p);
  const glm::dmat3 m3(world_of(s, p));  // rigid (the loader shares no other): normals take m3 too
  out.normal.resize(g.normal.size());
  for (size_t i = 0; i + 2 < g.normal.size(); i += 3) put_direction(m3, &g.normal[i], &out.normal[i]);
  out.tangent = g.tangent;
  for (size_t i = 0; i + 3 < g.tangent.size(); i += 4) put_direction(m3, &g.tangent[i], &out.tangent[i]);
  out.uv = g.uv;
  out.uv1 = g.uv1;
  out.indices = g.indices;
  return out;
}

size_t scene_geometry_bytes(const Scene &s) {
  size_t bytes = 0;
  std::set<const SceneGeometry *> counted;
  for (const ScenePrimitive &p : s.primitives) {
    bytes += p.bytes();
    if (p.shared && counted.insert(p.shared.get()).second) bytes += p.shared->bytes();
  }
  return bytes;
}

// tiershade bake: world faces (glue/bake/world_faces.h): a face from a mesh's planar quad, points
// on a face and ray casts against faces, in double with GLM.
#include "bake/world_faces.h"

#include <algorithm>

#include <cmath>

#include "bake/glm_ts.h"

namespace {

template <class T>
glm::dvec3 at3(const std::vector<T> &a, size_t i, size_t stride) {
  return glm::dvec3(a[i * stride], a[i * stride + 1], a[i * stride + 2]);
}

// v / |v| (GLM's normalize), or v itself when it has no length.
glm::dvec3 unit(const glm::dvec3 &v) { return glm::dot(v, v) > 0 ? glm::normalize(v) : v; }

}  // namespace

bool world_face_from_quad(const std::vector<float> &position, const std::vector<float> &normal,
                          const std::vector<float> &tangent, const std::vector<uint32_t> &indices, const char *name,
                          int probe, WorldFace *out, double frame_min[2]) {
  if (indices.size() < 3) return false;
  const uint32_t i0 = indices[0];
  const glm::dvec3 p0 = at3(position, i0, 3), p1 = at3(position, indices[1], 3), p2 = at3(position, indices[2], 3);
  const glm::dvec3 sn = normal.size() >= (i0 + 1) * 3 ? at3(normal, i0, 3) : glm::dvec3(0.0);
  glm::dvec3 n = unit(glm::cross(p1 - p0, p2 - p0));
  if (glm::dot(n, n) == 0) n = unit(sn);  // a degenerate first triangle: the vertex normal alone
  if (glm::dot(n, n) == 0) return false;
  if (glm::dot(n, sn) < 0) n = -n;  // the face's front is the side its vertex normals face
  const bool has_tangent = tangent.size() >= (i0 + 1) * 4;
  glm::dvec3 t = has_tangent ? at3(tangent, i0, 4) : glm::dvec3(1, 0, 0);
  t = t - n * glm::dot(n, t);
  if (glm::dot(t, t) < 1e-12) t = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) - n * n.x : glm::dvec3(0, 1, 0) - n * n.y;
  t = unit(t);
  const double hand = has_tangent && tangent[i0 * 4 + 3] < 0 ? -1.0 : 1.0;
  const glm::dvec3 b = glm::cross(n, t) * hand;
  double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
  for (size_t i = 0; i + 2 < position.size(); i += 3) {
    const glm::dvec3 q = at3(position, i / 3, 3);
    amin = std::fmin(amin, glm::dot(q, t));
    amax = std::fmax(amax, glm::dot(q, t));
    bmin = std::fmin(bmin, glm::dot(q, b));
    bmax = std::fmax(bmax, glm::dot(q, b));
  }
  WorldFace f{};
  f.name = name;
  f.origin = to_ts(t * amin + b * bmin + n * glm::dot(p0, n));
  f.u = to_ts(t);
  f.v = to_ts(b);
  f.su = std::fmax(amax - amin, 1e-3);
  f.sv = std::fmax(bmax - bmin, 1e-3);
  f.probe = probe;
  f.normal = to_ts(n);
  *out = f;
  frame_min[0] = amin;
  frame_min[1] = bmin;
  return true;
}

bool world_face_from_chart(const std::vector<float> &position, const std::vector<float> &normal,
                           const std::vector<float> &tangent, const std::vector<float> &uv1,
                           const std::vector<uint32_t> &indices, const char *name, int probe, double luxels_per_unit,
                           const std::string &where, WorldFace *out, std::string *err) {
  auto c = std::make_shared<WorldChart>();
  if (!chart_build(position, normal, tangent, uv1, indices, luxels_per_unit, where, c.get(), err)) return false;
  glm::dvec3 n(0.0), first(0.0);
  for (int t = 0; t < c->triangles(); ++t) {
    const glm::dvec3 p0 = at3(c->pos, t * 3, 3), p1 = at3(c->pos, t * 3 + 1, 3), p2 = at3(c->pos, t * 3 + 2, 3);
    glm::dvec3 a = glm::cross(p1 - p0, p2 - p0);
    if (glm::dot(a, at3(c->nrm, t * 3, 3)) < 0) a = -a;  // the vertex normals' side
    n += a;
    if (t == 0) first = a;
  }
  n = glm::length(n) > 1e-9 * glm::length(first) * c->triangles() ? unit(n) : unit(first);
  glm::dvec3 t = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) - n * n.x : glm::dvec3(0, 1, 0) - n * n.y;
  t = unit(t);
  const glm::dvec3 b = glm::cross(n, t);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (size_t k = 0; k < c->pos.size() / 3; ++k) {
    const glm::dvec3 q = at3(c->pos, k, 3), l(glm::dot(q, t), glm::dot(q, b), glm::dot(q, n));
    lo = glm::min(lo, l);
    hi = glm::max(hi, l);
  }
  WorldFace f{};
  f.name = name;
  f.origin = to_ts(t * lo.x + b * lo.y + n * (0.5 * (lo.z + hi.z)));
  f.u = to_ts(t);
  f.v = to_ts(b);
  f.su = std::fmax(hi.x - lo.x, 1e-3);
  f.sv = std::fmax(hi.y - lo.y, 1e-3);
  f.probe = probe;
  f.normal = to_ts(n);
  f.chart = std::move(c);
  *out = f;
  return true;
}

ts_vec3d world_face_normal(const WorldFace &f) { return to_ts(glm::normalize(to_glm(f.normal))); }

ts_vec3d world_face_point(const WorldFace &f, double a, double b) {
  return to_ts(to_glm(f.origin) + (to_glm(f.u) * (a * f.su) + to_glm(f.v) * (b * f.sv)));
}

ts_vec3d world_face_sample(const WorldFace &f, double a, double b) {
  const double ia = std::min(0.5, kWorldSampleInset / f.su), ib = std::min(0.5, kWorldSampleInset / f.sv);
  return world_face_point(f, std::clamp(a, ia, 1 - ia), std::clamp(b, ib, 1 - ib));
}

LuxelFrame world_luxel_frame(const WorldFace &f, const ts_vec3d bump[3], int i, int j, int w, int h) {
  if (f.chart) return f.chart->at(i, j);
  LuxelFrame r;
  r.p = world_face_sample(f, static_cast<double>(i) / (w - 1), static_cast<double>(j) / (h - 1));
  r.n = world_face_normal(f);
  for (int k = 0; k < 3; ++k) r.bump[k] = bump[k];
  r.lit = true;
  return r;
}

bool world_face_hit(const WorldFace &f, const glm::dvec3 &q, const RayScene::Hit &h, const glm::dvec3 &d, double *a,
                    double *b) {
  if (f.chart) {
    // The luxel the hit lies in; its front from the luxel's own normal (a curved mesh's side).
    chart_hit_ab(*f.chart, h.triangle, h.u, h.v, a, b);
    const int i = static_cast<int>(std::lround(*a * (f.chart->w - 1))), j = static_cast<int>(std::lround(*b * (f.chart->h - 1)));
    return glm::dot(to_glm(f.chart->at(i, j).n), d) < 0;
  }
  if (glm::dot(to_glm(world_face_normal(f)), d) >= 0) return false;
  const glm::dvec3 r = q - to_glm(f.origin);
  *a = glm::dot(r, to_glm(f.u)) / f.su;
  *b = glm::dot(r, to_glm(f.v)) / f.sv;
  return true;
}

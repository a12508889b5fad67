// tiershade bake: the ray-tracing scene of the baker: one Embree 3 BVH of every triangle of a scene
// (world and model primitives alike), queried for visibility (shadow rays) and nearest hits. The
// queries are thread-safe; each answer depends only on the ray and the triangles, never on the
// thread that asks or on how the BVH was built (a shadow ray's answer is hit / no hit; a nearest
// hit is the smallest t, ties resolved by Embree's watertight test).
// Coordinates beyond 1e18 (Embree's range) are refused: such a mesh is an error, such a ray hits nothing.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

class RayScene {
 public:
  RayScene();
  // Adds a triangle mesh (3 floats per vertex, 3 indices per triangle); `id` is returned by hits
  // on it. Call before commit(). An index out of range is an error naming `what`.
  bool add_mesh(const std::vector<float> &position, const std::vector<uint32_t> &indices, int id, const std::string &what,
                std::string *err);
  // Builds the BVH; queries after this only.
  bool commit(std::string *err);

  // Whether anything lies on the segment origin + t dir, t in (tnear, tfar) (dir need not be unit;
  // t is in units of |dir|).
  bool occluded(const glm::dvec3 &origin, const glm::dvec3 &dir, double tnear, double tfar) const;

  struct Hit {
    double t = 0;
    int id = -1;  // the mesh's id (-1: no hit)
    int triangle = -1;  // index of the triangle in its mesh
    double u = 0, v = 0;  // barycentrics of vertices 1 and 2
    glm::dvec3 normal{0.0};  // the triangle's geometric normal (unit; its winding's side)
  };
  // The nearest hit on origin + t dir, t in (tnear, tfar).
  Hit intersect(const glm::dvec3 &origin, const glm::dvec3 &dir, double tnear, double tfar) const;

  long triangles() const { return triangles_; }
  // The CPU time spent inside Embree's queries (rtcOccluded1 / rtcIntersect1), over every thread and
  // ray scene, for the bench's "Embree's share" (docs/accuracy_cost.md): the share of SIGPROF samples
  // (ITIMER_PROF, every 1 ms of the process's CPU time, at the kernel's tick at most) that land inside
  // a query, times the process's CPU time since timing started (sampled_ms), so other work on the
  // machine does not count. Off by default; set_timing(true) starts the counts from 0 (the process's
  // SIGPROF handler is ours until set_timing(false)).
  static void set_timing(bool on);
  static double timed_ms();
  static double sampled_ms();
  // A hash of every mesh added (ids, positions, indices, in order; glue/bake/content_hash.h): what
  // the rays see, for the bake directory's staleness check (glue/bake/bake_dir.h).
  uint64_t content_hash() const { return hash_; }
  ~RayScene();
  RayScene(const RayScene &) = delete;
  RayScene &operator=(const RayScene &) = delete;

 private:
  struct Impl;
  Impl *impl_;
  long triangles_ = 0;
  uint64_t hash_ = 0xcbf29ce484222325ull;
};

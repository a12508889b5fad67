// tiershade tests: glue/bake (world faces from quads, their own front normals, the
// bake's refusal of a face without a normal), glue/base (the thread pool's row assignment, the
// cube face table) and the one host-side attenuation formula (ts_packed_light_attenuation).
#include <atomic>
#include <cmath>
#include <vector>

#include "bake/world_bake.h"
#include "base/cube_faces.h"
#include "base/parallel_rows.h"
#include "offline/light_folding.h"
#include "unit_check.h"

namespace {

std::string vec(ts_vec3d v) {
  char b[96];
  snprintf(b, sizeof b, "(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
  return b;
}
bool near(ts_vec3d a, double x, double y, double z) {
  return std::fabs(a.x - x) < 1e-12 && std::fabs(a.y - y) < 1e-12 && std::fabs(a.z - z) < 1e-12;
}

// A 2 x 3 quad in the plane y = h, x in [1, 3], z in [-4, -1], wound counter-clockwise seen
// from +y, every vertex normal (0, ny, 0), tangent +x.
void quad(double h, float ny, std::vector<float> *pos, std::vector<float> *nrm, std::vector<float> *tan,
          std::vector<uint32_t> *idx) {
  const float y = static_cast<float>(h);
  *pos = {1, y, -1, 3, y, -1, 3, y, -4, 1, y, -4};
  *nrm = {0, ny, 0, 0, ny, 0, 0, ny, 0, 0, ny, 0};
  *tan = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  *idx = {0, 1, 2, 0, 2, 3};
}

void faces() {
  std::vector<float> pos, nrm, tan;
  std::vector<uint32_t> idx;
  WorldFace f;
  double lo[2];
  // A floor high above everything, its normals up: the front is +y wherever any room would be.
  quad(10, 1, &pos, &nrm, &tan, &idx);
  bool ok = world_face_from_quad(pos, nrm, tan, idx, "up", -1, &f, lo);
  check(ok && near(world_face_normal(f), 0, 1, 0),
        "a face's front is its winding normal where the vertex normals agree", vec(world_face_normal(f)));
  check(ok && std::fabs(f.su - 2) < 1e-12 && std::fabs(f.sv - 3) < 1e-12, "the face spans the quad (2 x 3)",
        std::to_string(f.su) + " x " + std::to_string(f.sv));
  const ts_vec3d far = world_face_point(f, 1, 1), first = world_face_point(f, 0, 0);
  check(std::fabs(far.y - 10) < 1e-12 && std::fabs(first.y - 10) < 1e-12 &&
            std::fabs(std::fabs(far.x - first.x) - 2) < 1e-12 && std::fabs(std::fabs(far.z - first.z) - 3) < 1e-12,
        "world_face_point(0, 0) and (1, 1) are opposite corners", vec(first) + " " + vec(far));
  // The same winding with the vertex normals down: the front turns round with them.
  quad(0, -1, &pos, &nrm, &tan, &idx);
  ok = world_face_from_quad(pos, nrm, tan, idx, "down", -1, &f, lo);
  check(ok && near(world_face_normal(f), 0, -1, 0), "vertex normals against the winding turn the front round",
        vec(world_face_normal(f)));
  // A degenerate quad (every corner the same, no normal) is refused.
  std::vector<float> zero(12, 0.f);
  check(!world_face_from_quad(zero, zero, {}, idx, "point", -1, &f, lo), "a quad without area or normal is refused");
  // bake_world refuses a face without a front normal, naming it.
  WorldBakeInput in;
  WorldFace bad{"nameless wall", ts_v3d(0, 0, 0), ts_v3d(1, 0, 0), ts_v3d(0, 1, 0), 1, 1, -1};
  in.faces = {bad};
  in.probes = {ts_v3d(0, 0, 1)};
  WorldBake out;
  std::string err;
  check(!bake_world(in, &out, &err) && err.find("nameless wall") != std::string::npos,
        "bake_world refuses a face without a front normal and names it", err);
}

void pool() {
  for (int threads : {1, 3, 8}) {
    const int h = 37;
    std::vector<std::atomic<int>> seen(h);
    std::vector<int> worker(h, -1);
    parallel_rows_by_worker(h, threads, [&](int t, int y) {
      ++seen[y];
      worker[y] = t;
    });
    bool once = true, mod = true;
    const int n = parallel_workers(h, threads);
    for (int y = 0; y < h; ++y) once = once && seen[y] == 1, mod = mod && worker[y] == y % n;
    check(once && mod && n == threads,
          "parallel_rows_by_worker: every row once, row y on worker y mod " + std::to_string(n));
  }
  check(parallel_workers(2, 8) == 2 && parallel_workers(0, 4) == 1, "parallel_workers: no more workers than rows");
}

void cube() {
  const glm::dvec3 px = cube_face_direction(0, 0, 0), ny = cube_face_direction(3, 0, 0),
                   c = cube_face_direction(4, 1, 1);
  check(px == glm::dvec3(1, 0, 0) && ny == glm::dvec3(0, -1, 0), "cube face centres: +X, -Y");
  check(std::fabs(glm::length(c) - 1) < 1e-15 && c.x > 0 && c.y < 0 && c.z > 0,
        "+Z face corner (sc, tc) = (1, 1) is (x, -y) and unit length (GL table 8.19)");
}

void attenuation() {
  ts_light l{};
  l.type = TS_LIGHT_POINT;
  l.color[0] = l.color[1] = l.color[2] = 2.f;
  l.pos[1] = 2.f;
  l.atten[0] = 0.f, l.atten[1] = 0.f, l.atten[2] = 1.f;
  float pk[5][4];
  char msg[128] = "";
  check(ts_light_pack(&l, pk, msg, sizeof msg) == 1, "point light packs", msg);
  const double p[3] = {0, 0, 0};
  double to[3];
  const double a = ts_packed_light_attenuation(pk, p, to);
  check(a == 0.25 && to[1] == 1.0, "1 / d^2 at d = 2, towards the light", std::to_string(a));
  double rgb[3], dir[3];
  const float pf[3] = {0, 0, 0};
  ts_light_incident(&l, pf, rgb, dir);
  check(rgb[0] == 2.0 * a && dir[1] == to[1], "ts_light_incident = colour x ts_packed_light_attenuation");
  // The clamps of common_lights.glsl: a light on the point (d^2 clamped at 1e-30) stays finite.
  const double on[3] = {0, 2, 0};
  check(std::isfinite(ts_packed_light_attenuation(pk, on, nullptr)), "a light on the point: finite (the 1e-30 clamp)");
}

}  // namespace

int main() {
  ts_math_init();
  for (void (*part)() : {faces, pool, cube, attenuation}) part();
  return finish();
}

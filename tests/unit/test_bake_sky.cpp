// tiershade tests: the bake's sky (glue/bake/sky.h) and area lights (glue/bake/area_lights.h)
// against closed forms, on a 4 x 4 floor (33 x 33 luxels) facing +y:
//   - a uniform sky of radiance L over the open floor: E = pi L, i.e. every flat lightmap value is
//     L (docs/baking.md: a value is E / pi); each bumped value L (1 + cos a) / 2 with cos a =
//     b_k . n = 1/sqrt(3) (the sky view factor of a plane tilted by a: the half-space the face
//     sees, cut out of b_k's hemisphere);
//   - beside a long wall of height H: the visible share of the sky, (1 + x / sqrt(x^2 + H^2)) / 2 at
//     distance x (the view factor of a differential strip to an infinitely long wall,
//     (1 - sin phi) / 2; Howell, "A catalog of radiation heat transfer configuration factors", 2D
//     configurations), so the flat value is L times that;
//   - an emissive square above the floor: every luxel's flat value is Le F with F the view factor
//     of a differential element to a parallel rectangle (Howell's catalog, B-3: the corner formula
//     F = (1/2pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))], summed
//     over the four rectangles around the point's foot);
//   - the spherical-rectangle sampler (Urena et al. 2013) reproduces the rectangle's solid angle;
//   - no sky, no sky ray; the same bytes for 1 and 2 threads.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bake/ray_scene.h"
#include "bake/world_bake.h"
#include "unit_check.h"

namespace {

const ts_vec3d kL = {0.5, 1.0, 2.0};  // the sky's radiance, per channel

WorldFace floor_face() {
  return {"floor", ts_v3d(-2, 0, 2), ts_v3d(1, 0, 0), ts_v3d(0, 0, -1), 4, 4, -1, ts_v3d(0, 1, 0)};
}

WorldBakeInput floor_input(const std::vector<float> *sky, int samples) {
  WorldBakeInput in;
  in.faces = {floor_face()};
  in.probes = {ts_v3d(0, 1, 0)};
  in.luxels_per_unit = 8;
  in.page_w = 256;
  in.page_h = 64;
  in.cube_size = 4;
  if (sky) {
    in.sky.rgba = sky->data();
    in.sky.w = 8;
    in.sky.h = 4;
    in.sky.samples = samples;
  }
  return in;
}

std::vector<float> uniform_sky() {
  std::vector<float> t;
  for (int i = 0; i < 8 * 4; ++i) t.insert(t.end(), {static_cast<float>(kL.x), static_cast<float>(kL.y), static_cast<float>(kL.z), 1.f});
  return t;
}

ts_vec3d value(const WorldBakeInput &in, const WorldBake &b, int face, int k, int i, int j) {
  int tx, ty;
  lm_page_texel(&b.place[static_cast<size_t>(face)], k, i, j, &tx, &ty);
  const float *t = &b.page[(static_cast<size_t>(ty) * in.page_w + tx) * 4];
  return ts_v3d(t[0], t[1], t[2]);
}

void open_sky() {
  const std::vector<float> sky = uniform_sky();
  WorldBakeInput in = floor_input(&sky, 256);
  WorldBake b;
  std::string err;
  if (!bake_world(in, &b, &err)) return check(false, "bake the open floor", err);
  // Every flat ray leaves the scene and returns L: the estimate is L exactly (no variance), up to
  // float rounding of the page.
  double worst = 0, bumped_mean = 0, bumped_worst = 0;
  const double bumped = (1 + 1 / std::sqrt(3.0)) / 2;
  for (int j = 0; j < 33; ++j)
    for (int i = 0; i < 33; ++i) {
      const ts_vec3d v = value(in, b, 0, 0, i, j);
      worst = std::max({worst, std::fabs(v.x / kL.x - 1), std::fabs(v.y / kL.y - 1), std::fabs(v.z / kL.z - 1)});
      for (int k = 1; k < 4; ++k) {
        const double r = value(in, b, 0, k, i, j).y / (kL.y * bumped) - 1;
        bumped_mean += r / (33 * 33 * 3);
        bumped_worst = std::max(bumped_worst, std::fabs(r));
      }
    }
  check(worst < 1e-7, "uniform sky over an open plane: flat value L (E = pi L)", "worst relative " + std::to_string(worst));
  // The bumped lobes lose their rays below the face: a share 1 - (1 + 1/sqrt3)/2 = 21 % of 256
  // stratified rays, a binary outcome only in the strata the horizon's curve crosses: measured
  // 3.5 % at most per luxel, 0.016 % on the mean over the 3267 values (unbiased); tolerances 5 %
  // per luxel, 0.1 % on the mean.
  check(bumped_worst < 0.05 && std::fabs(bumped_mean) < 1e-3,
        "uniform sky: each bumped value L (1 + b.n) / 2 (the sky view factor of b's tilt)",
        "mean relative " + std::to_string(bumped_mean) + ", worst " + std::to_string(bumped_worst));
  // 256 flat rays per luxel, and the bumped lobes' rays in front of the face (79 % of 3 x 256).
  check(b.sky.rays > 33L * 33 * 256 * 3 && b.sky.rays < 33L * 33 * 256 * 4, "the sky pass counts its rays",
        std::to_string(b.sky.rays));
  WorldBakeInput none = floor_input(nullptr, 256);
  WorldBake nb;
  if (bake_world(none, &nb, &err))
    check(nb.sky.rays == 0 && value(none, nb, 0, 0, 16, 16).y == 0, "no sky: no sky ray, no sky light");
  // The same bytes for 1 and 2 threads.
  WorldBakeInput one = floor_input(&sky, 16), two = floor_input(&sky, 16);
  one.bounce.threads = 1;
  two.bounce.threads = 2;
  WorldBake b1, b2;
  if (bake_world(one, &b1, &err) && bake_world(two, &b2, &err))
    check(b1.page == b2.page, "sky pass: the same page bytes for 1 and 2 threads");
}

void beside_a_wall() {
  // A wall x = -2, 0 <= y <= H = 1, 200 long in z (its ends 100 away: they hide less than 1e-4 of
  // the sky the infinite wall's formula counts), not a world face (id -2).
  const std::vector<float> sky = uniform_sky();
  WorldBakeInput in = floor_input(&sky, 256);
  RayScene rays;
  std::string err;
  const std::vector<float> fp = {-2, 0, 2, 2, 0, 2, 2, 0, -2, -2, 0, -2};
  const std::vector<float> wp = {-2, 0, -100, -2, 1, -100, -2, 1, 100, -2, 0, 100};
  if (!rays.add_mesh(fp, {0, 1, 2, 0, 2, 3}, 0, "floor", &err) || !rays.add_mesh(wp, {0, 1, 2, 0, 2, 3}, -2, "wall", &err) ||
      !rays.commit(&err))
    return check(false, "the wall's ray scene", err);
  in.rays = &rays;
  WorldBake b;
  if (!bake_world(in, &b, &err)) return check(false, "bake beside the wall", err);
  double worst = 0, worst_row = 0;
  for (int i = 0; i < 33; ++i) {
    const double x = world_face_sample(in.faces[0], i / 32.0, 0.5).x + 2, H = 1;
    const double share = (1 + x / std::sqrt(x * x + H * H)) / 2;
    double row = 0;
    for (int j = 4; j < 29; ++j) {  // away from the floor's ends in z (the wall is longer anyway)
      const double r = value(in, b, 0, 0, i, j).y / kL.y - share;
      worst = std::max(worst, std::fabs(r));
      row += r / 25;
    }
    worst_row = std::max(worst_row, std::fabs(row));
  }
  // 256 stratified cosine rays, a binary outcome (sky or wall) in the strata the wall's top edge
  // crosses: measured 2.3 % of L at most per luxel, 0.31 % at most on the mean of the 25 luxels at
  // one distance (no trend with the distance: unbiased); tolerances 4 % and 0.6 %.
  check(worst < 0.04 && worst_row < 6e-3, "beside a wall: the flat value is L x the visible sky share (1 + x / sqrt(x^2 + H^2)) / 2",
        "worst " + std::to_string(worst) + " of L, rows' means " + std::to_string(worst_row));
}

// Howell's B-3: a differential element to a parallel rectangle a x b at height c, its normal
// through a corner: A = a / c, B = b / c.
double corner_factor(double a, double b, double c) {
  const double A = std::fabs(a) / c, B = std::fabs(b) / c;
  const double f = (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                    B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
      (2 * M_PI);
  return (a < 0) != (b < 0) ? -f : f;
}
// The rectangle [x0, x1] x [z0, z1] at height c over the point (x, z): the signed corner rectangles.
double rect_factor(double x, double z, double x0, double x1, double z0, double z1, double c) {
  return corner_factor(x1 - x, z1 - z, c) - corner_factor(x0 - x, z1 - z, c) - corner_factor(x1 - x, z0 - z, c) +
      corner_factor(x0 - x, z0 - z, c);
}

void emissive_square() {
  // The sampler alone: a unit square at height h over the point, its solid angle
  // 4 asin(a b / sqrt((a^2 + 4h^2)(b^2 + 4h^2))) for a centred a x b rectangle.
  double sa_worst = 0;
  for (double h : {0.05, 0.3, 1.0, 3.0}) {
    const SphericalRect r = spherical_rect(glm::dvec3(0.0), glm::dvec3(-0.5, h, -0.5), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1));
    sa_worst = std::max(sa_worst, std::fabs(r.solid_angle / (4 * std::asin(1 / (1 + 4 * h * h))) - 1));
  }
  check(sa_worst < 1e-9, "spherical rectangle: the solid angle of a centred square", std::to_string(sa_worst));
  // A 1 x 1 panel, emission Le, 1 above the floor, facing down.
  const double h = 1.0, le = 3.0;
  WorldBakeInput in = floor_input(nullptr, 0);
  WorldFace panel{"panel", ts_v3d(-0.5, h, -0.5), ts_v3d(1, 0, 0), ts_v3d(0, 0, 1), 1, 1, -1, ts_v3d(0, -1, 0)};
  panel.emission = ts_v3d(le, le, le);
  in.faces.push_back(panel);
  in.area_samples = 16;
  WorldBake b;
  std::string err;
  if (!bake_world(in, &b, &err)) return check(false, "bake the panel over the floor", err);
  double worst = 0, centre = 0;
  for (int j = 0; j < 33; ++j)
    for (int i = 0; i < 33; ++i) {
      const ts_vec3d p = world_face_sample(in.faces[0], i / 32.0, j / 32.0);
      const double F = rect_factor(p.x, p.z, -0.5, 0.5, -0.5, 0.5, h - 1e-4);  // the luxel sits 1e-4 above the floor
      const double r = value(in, b, 0, 0, i, j).x / (le * F) - 1;
      worst = std::max(worst, std::fabs(r));
      if (i == 16 && j == 16) centre = r;
    }
  // Nothing occludes the panel: every luxel takes Le times the exact form factor (Lambert's formula
  // in glue/bake/area_lights.cpp; the shadow rays only scale it by the visible share, here 1), so
  // the only error is the page's float32: tolerance 1e-6 relative.
  check(std::fabs(centre) < 1e-6, "emissive square: the centre's value = Le F (Howell B-3, F = " +
                                      std::to_string(4 * corner_factor(0.5, 0.5, h)) + ")",
        "relative " + std::to_string(centre));
  check(worst < 1e-6, "emissive square: every luxel = Le F(x, z) of the four corner rectangles", "worst relative " + std::to_string(worst));
  check(b.area.emitters == 1 && b.area.rays > 0, "the area-light pass counts its emitters and rays",
        std::to_string(b.area.emitters) + " emitters, " + std::to_string(b.area.rays) + " rays");
  // An occluder between: a luxel under the middle of a bigger slab sees nothing of the panel.
  RayScene rays;
  const std::vector<float> fp = {-2, 0, 2, 2, 0, 2, 2, 0, -2, -2, 0, -2};
  const std::vector<float> pp = {-0.5f, 1, -0.5f, 0.5f, 1, -0.5f, 0.5f, 1, 0.5f, -0.5f, 1, 0.5f};
  const std::vector<float> op = {-1, 0.5f, -1, 1, 0.5f, -1, 1, 0.5f, 1, -1, 0.5f, 1};
  if (!rays.add_mesh(fp, {0, 1, 2, 0, 2, 3}, 0, "floor", &err) || !rays.add_mesh(pp, {0, 1, 2, 0, 2, 3}, 1, "panel", &err) ||
      !rays.add_mesh(op, {0, 1, 2, 0, 2, 3}, -2, "slab", &err) || !rays.commit(&err))
    return check(false, "the slab's ray scene", err);
  in.rays = &rays;
  WorldBake s;
  if (bake_world(in, &s, &err))
    check(value(in, s, 0, 0, 16, 16).x == 0 && value(in, s, 0, 0, 0, 0).x > 0,
          "emissive square: shadow rays (a slab hides the panel from the luxels below it)");
}

}  // namespace

int main() {
  ts_math_init();
  for (void (*test)() : {open_sky, beside_a_wall, emissive_square}) test();
  return finish();
}

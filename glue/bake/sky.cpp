// tiershade bake: the sky pass (sky.h).
#include "bake/sky.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bake/glm_ts.h"
#include "bake/luxel_rng.h"
#include "bake/ray_scene.h"
#include "bake/world_faces.h"
#include "base/parallel_rows.h"

ts_vec3d sky_radiance(const BakeSky &sky, const ts_vec3d &dir) {
  const double len = std::sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
  const ts_vec3d d = ts_v3d(dir.x / len, dir.y / len, dir.z / len);
  // The probe convention of cube_from_probe (glue/scene/textures.cpp): u = atan2(x, -z) / 2pi + 0.5,
  // v = acos(y) / pi, texel centres at half-integers, row 0 the bottom (v = 1).
  const double u = std::atan2(d.x, -d.z) / (2 * M_PI) + 0.5;
  const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / M_PI;
  const double fx = u * sky.w - 0.5, fy = (1 - v) * sky.h - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double wx = fx - x0, wy = fy - y0;
  glm::dvec3 r(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int xx = ((x0 + i) % sky.w + sky.w) % sky.w, yy = std::clamp(y0 + j, 0, sky.h - 1);
      const float *t = &sky.rgba[(static_cast<size_t>(yy) * sky.w + xx) * 4];
      r += glm::dvec3(t[0], t[1], t[2]) * ((i ? wx : 1 - wx) * (j ? wy : 1 - wy));
    }
  return to_ts(r * sky.scale);
}

bool sky_light(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
               const RayScene &rays, const BakeSky &sky, int threads, uint64_t seed, std::vector<LuxelGrid> *grids,
               SkyReport *report, std::string *err) {
  *report = SkyReport();
  if (!sky.present()) return true;  // no sky work without a sky
  if (grids->size() != faces.size() || bump.size() != faces.size()) {
    *err = "sky: " + std::to_string(grids->size()) + " luxel grids for " + std::to_string(faces.size()) + " faces";
    return false;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(sky.samples)))));
  const int m = side * side;
  for (size_t f = 0; f < faces.size(); ++f) {
    const WorldFace &face = faces[f];
    LuxelGrid &g = (*grids)[f];
    std::vector<long> traced_rows(static_cast<size_t>(g.h), 0);
    parallel_rows(g.h, threads, [&](int j) {
      long traced = 0;
      for (int i = 0; i < g.w; ++i) {
        LuxelRng rng = LuxelRng::of(0x536B79 /* "Sky" */, f, static_cast<uint64_t>(j), static_cast<uint64_t>(i), 0, seed);
        const LuxelFrame lf = world_luxel_frame(face, bump[f].data(), i, j, g.w, g.h);
        if (!lf.lit) continue;  // a chart's luxel no triangle touches
        const glm::dvec3 n = to_glm(lf.n), p = to_glm(lf.p) + n * 1e-4;
        // Value k = (1/pi) integral of L_sky (a_k . w)+ over the directions of the face's front that
        // leave the scene (docs/baking.md): the mean of L over the cosine lobe of a_k, as bounce.cpp.
        for (int k = 0; k < (face.bumped ? 4 : 1); ++k) {
          const glm::dvec3 ax = k == 0 ? n : to_glm(lf.bump[static_cast<size_t>(k - 1)]);
          glm::dvec3 au, av, sum(0.0);
          frame_of(ax, &au, &av);
          for (int s = 0; s < m; ++s) {
            double r1, r2;
            stratum(s, side, &rng, &r1, &r2);
            const glm::dvec3 d = cosine_dir(ax, au, av, r1, r2);
            if (!(glm::dot(d, n) > 0)) continue;  // behind the face: it feeds none of the values
            ++traced;
            if (rays.occluded(p, d, 0.0, INFINITY)) continue;  // a hit: the bounces carry that light
            sum += to_glm(sky_radiance(sky, to_ts(d)));
          }
          g.at(i, j, k) = to_ts(to_glm(g.at(i, j, k)) + sum / static_cast<double>(m));
        }
      }
      traced_rows[static_cast<size_t>(j)] = traced;
    });
    for (long t : traced_rows) report->rays += t;
  }
  report->ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return true;
}

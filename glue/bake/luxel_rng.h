// tiershade bake: the random streams of the sky, area-light and soft-shadow passes: splitmix64
// (Steele, Lea, Flood 2014) seeded per luxel and pass, so every luxel's rays are the same on any
// thread count (docs/baking.md, "Deterministic"); and the stratified directions drawn from it.
#pragma once
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

struct LuxelRng {
  uint64_t s;
  // A stream for (pass tag, face, luxel i, j, extra), mixed with the bake's seed.
  static LuxelRng of(uint64_t tag, uint64_t face, uint64_t j, uint64_t i, uint64_t extra, uint64_t seed) {
    uint64_t h = tag * 0x9E3779B97F4A7C15ull;
    for (uint64_t v : {face, j, i, extra, seed}) h = (h ^ v) * 0xBF58476D1CE4E5B9ull + 0x94D049BB133111EBull;
    return LuxelRng{h};
  }
  double next() {  // uniform in [0, 1)
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

// An orthonormal frame (u, v) around the unit axis a.
inline void frame_of(const glm::dvec3 &a, glm::dvec3 *u, glm::dvec3 *v) {
  const glm::dvec3 side = std::fabs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  *u = glm::normalize(glm::cross(side, a));
  *v = glm::cross(a, *u);
}

// Sample s of side x side strata, jittered by the stream: a point of [0, 1)^2.
inline void stratum(int s, int side, LuxelRng *rng, double *r1, double *r2) {
  *r1 = (s % side + rng->next()) / side;
  *r2 = (s / side + rng->next()) / side;
}

// A direction in the cosine lobe about the unit axis a (Malley: the disc point lifted to the
// hemisphere), from (r1, r2) in [0, 1)^2: pdf (a . w) / pi.
inline glm::dvec3 cosine_dir(const glm::dvec3 &a, const glm::dvec3 &u, const glm::dvec3 &v, double r1, double r2) {
  const double rad = std::sqrt(r1), phi = 2 * M_PI * r2;
  return u * (rad * std::cos(phi)) + v * (rad * std::sin(phi)) + a * std::sqrt(std::max(0.0, 1 - r1));
}

// A direction uniform in solid angle within the cone of half-angle acos(cos_max) about the unit
// axis a, from (r1, r2) in [0, 1)^2: cos theta uniform in [cos_max, 1] (the cone's area is
// 2 pi (1 - cos_max)).
inline glm::dvec3 cone_dir(const glm::dvec3 &a, const glm::dvec3 &u, const glm::dvec3 &v, double cos_max, double r1,
                           double r2) {
  const double ct = 1 - r1 * (1 - cos_max), st = std::sqrt(std::max(0.0, 1 - ct * ct)), phi = 2 * M_PI * r2;
  return u * (st * std::cos(phi)) + v * (st * std::sin(phi)) + a * ct;
}

// tiershade bake: Probulator's irradiance reference (probulator_reference.h).
#include "bake/probulator_reference.h"

#include <cmath>
#include <random>
#include <utility>

#include "bake/ambient_fit.h"
#include "offline/ambient_cube_fit.h"

namespace {
constexpr float kPiF = 3.14159265358979323846f;

// Probulator's lat-long convention (Math.h, the USC probe layout): u in [0, 1] from theta =
// pi (2u - 1), v from the top: direction (sin v pi sin theta, cos v pi, -sin v pi cos theta); float.
void uv_direction(float u, float v, float d[3]) {
  const float theta = kPiF * (u * 2.f - 1.f), phi = kPiF * v;
  d[0] = std::sin(phi) * std::sin(theta);
  d[1] = std::cos(phi);
  d[2] = -std::sin(phi) * std::cos(theta);
}

// Probulator's texel area (its latLongTexelArea, row `yt` counted from the top): delta azimuth x
// |sin of the latitude bounds' difference|, in float.
float texel_area(int x, int yt, int w, int h) {
  const float u0 = static_cast<float>(x) / w, u1 = static_cast<float>(x + 1) / w;
  const float v0 = static_cast<float>(yt) / h, v1 = static_cast<float>(yt + 1) / h;
  const float t0 = kPiF * (u0 * 2.f - 1.f), t1 = kPiF * (u1 * 2.f - 1.f);
  const float p0 = kPiF * (v0 - 0.5f), p1 = kPiF * (v1 - 0.5f);
  return std::fabs(t1 - t0) * std::fabs(std::sin(p1) - std::sin(p0));
}

// The grid's directions and solid angles, pixels in Probulator's order (top row first): index
// yt * w + x. Our layout stores row yt at bottom-up row h - 1 - yt.
void grid(ProbulatorReference *r) {
  const size_t n = static_cast<size_t>(r->w) * r->h;
  r->dir.assign(n * 3, 0.0);
  r->solid_angle.assign(n, 0.0);
  for (int yt = 0; yt < r->h; ++yt)
    for (int x = 0; x < r->w; ++x) {
      float d[3];
      uv_direction((x + 0.5f) / static_cast<float>(r->w - 1), (yt + 0.5f) / static_cast<float>(r->h - 1), d);
      const size_t i = static_cast<size_t>(r->h - 1 - yt) * r->w + x;
      for (int k = 0; k < 3; ++k) r->dir[i * 3 + k] = d[k];
      double td[3], dw;
      latlong_texel(r->w, r->h, x, r->h - 1 - yt, td, &dw);
      r->solid_angle[i] = dw;
    }
}
}  // namespace

ProbulatorReference probulator_reference(const ImageF &probe, int samples) {
  ProbulatorReference r;
  r.w = probe.w;
  r.h = probe.h;
  grid(&r);
  const int w = probe.w, h = probe.h, n = w * h;
  // Texels in Probulator's order (top row first): radiance, area, weight = mean intensity x area.
  std::vector<float> rad(static_cast<size_t>(n) * 3), area(n), weight(n), dir(static_cast<size_t>(n) * 3);
  float sum = 0.f;
  for (int yt = 0; yt < h; ++yt)
    for (int x = 0; x < w; ++x) {
      const int t = yt * w + x;
      const float *p = &probe.rgba[(static_cast<size_t>(h - 1 - yt) * w + x) * 4];
      for (int k = 0; k < 3; ++k) rad[t * 3 + k] = p[k];
      area[t] = texel_area(x, yt, w, h);
      const float intensity = (1.f / 3.f) * p[0] + (1.f / 3.f) * p[1] + (1.f / 3.f) * p[2];
      weight[t] = intensity * area[t];
      sum += weight[t];
      const size_t i = static_cast<size_t>(h - 1 - yt) * w + x;
      for (int k = 0; k < 3; ++k) dir[t * 3 + k] = static_cast<float>(r.dir[i * 3 + k]);
    }
  // Walker's alias table (Vose's construction; each cell keeps its own probability and an alias).
  std::vector<std::pair<float, int>> small, large;
  for (int t = 0; t < n; ++t) {
    const float q = weight[t] * n / sum;
    (q < 1.f ? small : large).push_back({q, t});
  }
  std::vector<float> keep(n, 0.f);
  std::vector<int> alias(n, 0);
  while (!small.empty() && !large.empty()) {
    const std::pair<float, int> s = small.back();
    small.pop_back();
    std::pair<float, int> l = large.back();
    large.pop_back();
    keep[s.second] = s.first;
    alias[s.second] = l.second;
    l.first = (s.first + l.first) - 1.f;
    (l.first < 1.f ? small : large).push_back(l);
  }
  for (const auto &c : large) keep[c.second] = 1.f;
  for (const auto &c : small) keep[c.second] = 1.f;
  // Jitter off: one generator seeded 0 per pixel, so every pixel sees the same texels.
  std::mt19937 rng(0);
  std::vector<int> drawn(static_cast<size_t>(samples));
  for (int s = 0; s < samples; ++s) {
    const int cell = static_cast<int>(rng() % static_cast<uint32_t>(n));
    std::uniform_real_distribution<float> uniform;
    drawn[s] = uniform(rng) <= keep[cell] ? cell : alias[cell];
  }
  r.e.assign(static_cast<size_t>(n) * 3, 0.0);
  for (int i = 0; i < n; ++i) {
    const float nx = static_cast<float>(r.dir[i * 3]), ny = static_cast<float>(r.dir[i * 3 + 1]),
                nz = static_cast<float>(r.dir[i * 3 + 2]);
    float acc[3] = {0.f, 0.f, 0.f};
    for (int s = 0; s < samples; ++s) {
      const int t = drawn[s];
      const float p = weight[t] / sum;
      const float c = std::fmax(0.f, nx * dir[t * 3] + ny * dir[t * 3 + 1] + nz * dir[t * 3 + 2]);
      for (int k = 0; k < 3; ++k) acc[k] += rad[t * 3 + k] * area[t] * c / p;
    }
    for (int k = 0; k < 3; ++k) r.e[static_cast<size_t>(i) * 3 + k] = acc[k] / (static_cast<float>(samples) * kPiF);
  }
  return r;
}

ProbulatorReference exact_reference_on_probulator_grid(const ImageF &probe, int threads) {
  ProbulatorReference r;
  r.w = probe.w;
  r.h = probe.h;
  grid(&r);
  r.e = probe_irradiance_at(probe, r.dir, threads);
  return r;
}

void fit_cube_to_reference(const ProbulatorReference &r, bool solid_angle, float cube[6][3]) {
  double g[6][6] = {}, b[6][3] = {};
  for (size_t i = 0; i < r.solid_angle.size(); ++i) {
    double a[6];
    ts_ac_basis(&r.dir[i * 3], a);
    const double wt = solid_angle ? r.solid_angle[i] : 1.0;
    for (int p = 0; p < 6; ++p) {
      for (int q = 0; q < 6; ++q) g[p][q] += wt * a[p] * a[q];
      for (int k = 0; k < 3; ++k) b[p][k] += wt * a[p] * r.e[i * 3 + k];
    }
  }
  for (int k = 0; k < 3; ++k) {
    double bk[6], xk[6];
    for (int p = 0; p < 6; ++p) bk[p] = b[p][k];
    ts_ac_nnls6(g, bk, xk);
    for (int p = 0; p < 6; ++p) cube[p][k] = static_cast<float>(xk[p]);
  }
}

ReferenceError cube_reference_error(const float cube[6][3], const ProbulatorReference &r) {
  double px = 0, sa = 0, total = 0;
  for (size_t i = 0; i < r.solid_angle.size(); ++i) {
    double rgb[3], e2 = 0;
    ts_ac_eval(cube, &r.dir[i * 3], rgb);
    for (int k = 0; k < 3; ++k) e2 += (rgb[k] - r.e[i * 3 + k]) * (rgb[k] - r.e[i * 3 + k]);
    px += e2 / 3;
    sa += r.solid_angle[i] * e2 / 3;
    total += r.solid_angle[i];
  }
  ReferenceError out;
  out.rms_pixels = std::sqrt(px / static_cast<double>(r.solid_angle.size()));
  out.rms_solid_angle = std::sqrt(sa / total);
  return out;
}

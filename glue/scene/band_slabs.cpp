// tiershade scene: the banded lit pass's slabs (glue/scene/band_slabs.h).
#include "scene/band_slabs.h"

#include <algorithm>
#include <cmath>

#include "base/parallel_rows.h"
#include "scene/cpu_vertex.h"
#include "scene/lp_interp.h"
#include "scene/raster_tri.h"

size_t band_draw_bytes(const PreparedDraw &d, size_t tri_bytes) {
  return d.geo->vertices() * kVStride * sizeof(float) + d.geo->indices.size() / 3 * tri_bytes;
}

namespace {

// Draw d's window rows [*y0, *y1] (false: off the frame). Clipping keeps a triangle inside the
// convex hull of its vertices, and with every w > 0 the window positions of that hull lie within
// those of the vertices (a projective map keeps convex hulls in front of the eye); the set-up
// (scene_tri_setup) takes rows floor(y) - 1 .. floor(y) + 1 of its vertices' y: 2 rows either side
// hold them and the float roundings of clipped vertices.
bool draw_rows(const PreparedScene &p, const PreparedDraw &d, std::vector<float> *clip, int *y0, int *y1) {
  scene_clip_stage(p, d, clip);
  const size_t n = clip->size() / 4;
  if (n == 0 || d.geo->indices.empty()) return false;
  const float W = static_cast<float>(p.w), H = static_cast<float>(p.h);
  float lo = INFINITY, hi = -INFINITY, xlo = INFINITY, xhi = -INFINITY;
  for (size_t i = 0; i < n; ++i) {
    const float *c = &(*clip)[i * 4];
    if (!(c[3] > 0.f) || !std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[3])) {
      *y0 = 0, *y1 = p.h - 1;
      return true;
    }
    float win[4];
    lp_window_pos(c, W, H, win);
    if (!std::isfinite(win[0]) || !std::isfinite(win[1])) {  // the set-up drops such triangles
      *y0 = 0, *y1 = p.h - 1;
      return true;
    }
    lo = std::min(lo, win[1]), hi = std::max(hi, win[1]);
    xlo = std::min(xlo, win[0]), xhi = std::max(xhi, win[0]);
  }
  if (!(hi >= -2.f) || !(lo <= H + 2.f) || !(xhi >= -2.f) || !(xlo <= W + 2.f)) return false;
  *y0 = std::max(0, static_cast<int>(std::floor(std::max(lo, -4.f))) - 2);
  *y1 = std::min(p.h - 1, static_cast<int>(std::floor(std::min(hi, H + 4.f))) + 2);
  return *y0 <= *y1;
}

}  // namespace

BandSlabs plan_band_slabs(const PreparedScene &p, int band, size_t budget, size_t tri_bytes, int threads) {
  const int nd = static_cast<int>(p.draws.size());
  const int bands = std::max(1, (p.h + band - 1) / band);
  BandSlabs s;
  std::vector<size_t> bytes(static_cast<size_t>(nd));
  size_t total = 0;
  for (int di = 0; di < nd; ++di) total += bytes[static_cast<size_t>(di)] = band_draw_bytes(p.draws[di], tri_bytes);
  if (total <= budget) {
    s.first_band = {0, bands};
    s.draw_first.assign(static_cast<size_t>(nd), 0);
    s.draw_last.assign(static_cast<size_t>(nd), 0);
    s.peak_bytes = total;
    return s;
  }
  // Each draw's bands, on every core.
  std::vector<int> fb(static_cast<size_t>(nd), -1), lb(static_cast<size_t>(nd), -1);
  std::vector<std::vector<float>> clip(static_cast<size_t>(parallel_workers(nd, threads)));
  parallel_rows_by_worker(nd, threads, [&](int t, int di) {
    int y0 = 0, y1 = 0;
    if (draw_rows(p, p.draws[di], &clip[static_cast<size_t>(t)], &y0, &y1))
      fb[static_cast<size_t>(di)] = y0 / band, lb[static_cast<size_t>(di)] = y1 / band;
  });
  // A draw held across its bands: its vertex outputs, clip positions and triangle rows
  // (fixed); its set-up triangles a slab at a time, spread evenly over its bands (tri).
  // live(b): the fixed bytes of the draws whose bands hold b; starts(b): of those that start at b.
  std::vector<size_t> starts(static_cast<size_t>(bands) + 1, 0), ends(static_cast<size_t>(bands) + 1, 0);
  std::vector<double> tri_step(static_cast<size_t>(bands) + 1, 0.0);
  for (int di = 0; di < nd; ++di) {
    const int a = fb[static_cast<size_t>(di)], z = lb[static_cast<size_t>(di)];
    if (a < 0) continue;
    const PreparedDraw &d = p.draws[static_cast<size_t>(di)];
    const size_t tris = d.geo->indices.size() / 3;
    const size_t fixed = d.geo->vertices() * (kVStride + 4) * sizeof(float) + tris * sizeof(uint32_t);
    starts[static_cast<size_t>(a)] += fixed;
    ends[static_cast<size_t>(z) + 1] += fixed;
    const double per_band = static_cast<double>(tris * tri_bytes) / (z - a + 1);
    tri_step[static_cast<size_t>(a)] += per_band;
    tri_step[static_cast<size_t>(z) + 1] -= per_band;
  }
  std::vector<size_t> live(static_cast<size_t>(bands)), tri(static_cast<size_t>(bands));
  size_t run = 0;
  double trun = 0.0;
  for (int b = 0; b < bands; ++b) {
    live[static_cast<size_t>(b)] = run = run + starts[static_cast<size_t>(b)] - ends[static_cast<size_t>(b)];
    trun += tri_step[static_cast<size_t>(b)];
    tri[static_cast<size_t>(b)] = static_cast<size_t>(std::max(0.0, trun));
  }
  // A slab from band b holds live(b); each band added brings the draws that start there and
  // its share of the triangles. A slab has a band a worker at least (its bands are shared
  // among the workers).
  const int min_bands = parallel_workers(bands, threads);
  for (int b = 0; b < bands;) {
    s.first_band.push_back(b);
    size_t cost = live[static_cast<size_t>(b)] + tri[static_cast<size_t>(b)];
    int e = b + 1;
    while (e < bands && (e - b < min_bands || cost + starts[static_cast<size_t>(e)] + tri[static_cast<size_t>(e)] <= budget)) {
      cost += starts[static_cast<size_t>(e)] + tri[static_cast<size_t>(e)];
      ++e;
    }
    s.peak_bytes = std::max(s.peak_bytes, cost);
    b = e;
  }
  s.first_band.push_back(bands);
  const int slabs = static_cast<int>(s.first_band.size()) - 1;
  auto slab_of = [&](int b) {
    return static_cast<int>(std::upper_bound(s.first_band.begin(), s.first_band.end(), b) - s.first_band.begin()) - 1;
  };
  s.draw_first.assign(static_cast<size_t>(nd), -1);
  s.draw_last.assign(static_cast<size_t>(nd), -1);
  for (int di = 0; di < nd; ++di)
    if (fb[static_cast<size_t>(di)] >= 0) {
      s.draw_first[static_cast<size_t>(di)] = slab_of(fb[static_cast<size_t>(di)]);
      s.draw_last[static_cast<size_t>(di)] = std::min(slabs - 1, slab_of(lb[static_cast<size_t>(di)]));
    }
  return s;
}

void triangle_rows(const PreparedScene &p, int di, const std::vector<float> &clip, std::vector<float> *win_y,
                   std::vector<uint32_t> *rows) {
  const float W = static_cast<float>(p.w), H = static_cast<float>(p.h);
  const size_t n = clip.size() / 4;
  win_y->resize(n);
  for (size_t i = 0; i < n; ++i) {  // NaN: not in front, or not finite
    const float *c = &clip[i * 4];
    float win[4];
    lp_window_pos(c, W, H, win);
    const bool ok = c[3] > 0.f && std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[3]) &&
        std::isfinite(win[0]) && std::isfinite(win[1]);
    (*win_y)[i] = ok ? win[1] : NAN;
  }
  const std::vector<uint32_t> &idx = p.draws[static_cast<size_t>(di)].geo->indices;
  rows->resize(idx.size() / 3);
  const uint32_t all = static_cast<uint32_t>(p.h - 1) << 16, none = 0xffffu;
  for (size_t t = 0; t < rows->size(); ++t) {
    const float a = (*win_y)[idx[3 * t]], b = (*win_y)[idx[3 * t + 1]], c = (*win_y)[idx[3 * t + 2]];
    if (std::isnan(a) || std::isnan(b) || std::isnan(c)) {
      (*rows)[t] = all;
      continue;
    }
    const float lo = std::min({a, b, c}), hi = std::max({a, b, c});
    if (hi < -2.f || lo > H + 2.f) {
      (*rows)[t] = none;
      continue;
    }
    const int y0 = std::max(0, static_cast<int>(std::floor(std::max(lo, -4.f))) - 2);
    const int y1 = std::min(p.h - 1, static_cast<int>(std::floor(std::min(hi, H + 4.f))) + 2);
    (*rows)[t] = y0 <= y1 ? static_cast<uint32_t>(y0) | static_cast<uint32_t>(y1) << 16 : none;
  }
}

// tiershade scene: the C fallback's one-sample rasteriser (glue/scene/cpu_renderer.h): the clip
// stage, triangle set-up and the visibility buffer, in batches of triangles in draw order.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include <immintrin.h>

#include "base/parallel_rows.h"
#include "scene/cpu_renderer.h"
#include "scene/raster_tri.h"
#include "scene/lp_interp.h"

namespace {

// ---- rasteriser -----------------------------------------------------------------------

bool top_left(int64_t dx, int64_t dy) { return dy < 0 || (dy == 0 && dx > 0); }

void finish_setup(ScreenTri *s) {
  s->inv_area = 1.0 / static_cast<double>(s->area);
  s->small = true;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    s->dx[k] = s->X[b] - s->X[a];
    s->dy[k] = s->Y[b] - s->Y[a];
    s->bias[k] = top_left(s->dx[k], s->dy[k]) ? 0 : 1;
    s->small = s->small && std::llabs(s->X[k]) < (1LL << 27) && std::llabs(s->Y[k]) < (1LL << 27);
  }
  s->unit = true;
  for (int j = 0; j < 3; ++j) {
    s->ui[j] = -1;
    for (int k = 0; k < 3; ++k) {
      const double v = s->bary[k][j];
      if (v == 1.0 && !std::signbit(v))
        s->ui[j] = s->ui[j] < 0 ? k : 3;
      else if (!(v == 0.0 && !std::signbit(v)))
        s->unit = false;
    }
    if (s->ui[j] < 0 || s->ui[j] > 2) s->unit = false;
  }
}

}  // namespace

// The clip coordinates alone (what the rasteriser needs), as vertex_stage computes them.
void scene_clip_stage(const PreparedScene &p, const PreparedDraw &d, std::vector<float> *clip) {
  const DrawGeometry &g = *d.geo;
  const size_t n = g.vertices();
  clip->resize(n * 4);
  const float *m = p.view_proj;
  for (size_t i = 0; i < n; ++i) {
    const float *P = &g.position[i * 3];
    float Pw[3];
    if (d.instanced) {
      model_point(d.model, P, Pw);
      P = Pw;
    }
    float *c = &(*clip)[i * 4];
    for (int r = 0; r < 4; ++r) c[r] = m[r] * P[0] + m[4 + r] * P[1] + m[8 + r] * P[2] + m[12 + r];
  }
}

namespace {

// The set-up of the triangle whose first index is indices[t] (t a multiple of 3).
void setup_tri(const PreparedScene &p, int di, const std::vector<float> &clip, size_t t, std::vector<ScreenTri> *out) {
  const float W = static_cast<float>(p.w), H = static_cast<float>(p.h);
  const std::vector<uint32_t> &indices = p.draws[di].geo->indices;
  {
    // The triangles llvmpipe draws for this one (glue/scene/lp_interp.h): the draw module's
    // window positions, its clipper against all six planes (no guard band), the fan in its
    // order; the barycentrics of the original vertices ride along as attributes 0..2.
    LpVert in[3], poly[kLpMaxPoly];
    int m[3];
    for (int k = 0; k < 3; ++k) {
      std::memcpy(in[k].clip, &clip[indices[t + k] * 4], sizeof in[k].clip);
      lp_window_pos(in[k].clip, W, H, in[k].win);
      for (int j = 0; j < 3; ++j) in[k].attr[j] = j == k ? 1.f : 0.f;
      m[k] = lp_clipmask(in[k].clip);
    }
    int np = 3;
    const LpVert *fan[kLpMaxPoly] = {&in[0], &in[1], &in[2]};
    if (m[0] | m[1] | m[2]) {
      np = lp_clip_tri(in, m, W, H, poly);
      for (int k = 0; k < np; ++k) fan[k] = &poly[k];
    }
    for (int f = 2; f < np; ++f) {
      // emit_poly (provoking vertex last): (f - 1, f, 0); an unclipped triangle as it is.
      const LpVert *v[3] = {fan[f - 1], fan[f], fan[0]};
      if (np == 3 && !(m[0] | m[1] | m[2])) v[0] = fan[0], v[1] = fan[1], v[2] = fan[2];
      ScreenTri s;
      s.draw = di;
      s.tri = static_cast<int>(t / 3);
      s.sub = f - 2;
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        if (!(v[k]->win[3] > 0.f) || !std::isfinite(v[k]->win[0]) || !std::isfinite(v[k]->win[1])) ok = false;
        // lp_setup_tri.c calc_fixed_position: (x - 0.5) * 256 rounded to nearest even, whose
        // pixel centres are the multiples of 256: here + 128, the centres at 256 x + 128.
        s.X[k] = static_cast<int64_t>(std::nearbyint((v[k]->win[0] - 0.5f) * 256.0f)) + kSub / 2;
        s.Y[k] = static_cast<int64_t>(std::nearbyint((v[k]->win[1] - 0.5f) * 256.0f)) + kSub / 2;
        s.z[k] = v[k]->win[2];
        s.invw[k] = v[k]->win[3];
        for (int j = 0; j < 3; ++j) s.bary[k][j] = v[k]->attr[j];
      }
      if (!ok) continue;
      int order[3];
      if (!lp_tri_order(v[0]->win, v[1]->win, v[2]->win, order)) continue;  // zero area for llvmpipe
      {
        LpPlanes zp;
        const float *const po[3] = {v[order[0]]->win, v[order[1]]->win, v[order[2]]->win};
        lp_tri_planes(po, po, nullptr, 0, &zp);
        s.z0 = zp.z0, s.zdx = zp.zdx, s.zdy = zp.zdy;
      }
      s.area = static_cast<__int128>(s.X[1] - s.X[0]) * (s.Y[2] - s.Y[0]) -
          static_cast<__int128>(s.Y[1] - s.Y[0]) * (s.X[2] - s.X[0]);
      if (s.area == 0) continue;
      if (s.area < 0) {  // both windings are drawn (no culling): make it counter-clockwise
        std::swap(s.X[1], s.X[2]);
        std::swap(s.Y[1], s.Y[2]);
        std::swap(s.z[1], s.z[2]);
        std::swap(s.invw[1], s.invw[2]);
        for (int j = 0; j < 3; ++j) std::swap(s.bary[1][j], s.bary[2][j]);
        s.area = -s.area;
      }
      const int64_t xmin = std::min({s.X[0], s.X[1], s.X[2]}), xmax = std::max({s.X[0], s.X[1], s.X[2]});
      const int64_t ymin = std::min({s.Y[0], s.Y[1], s.Y[2]}), ymax = std::max({s.Y[0], s.Y[1], s.Y[2]});
      s.x0 = static_cast<int>(std::max<int64_t>(0, xmin / kSub - 1));
      s.x1 = static_cast<int>(std::min<int64_t>(p.w - 1, xmax / kSub + 1));
      s.y0 = static_cast<int>(std::max<int64_t>(0, ymin / kSub - 1));
      s.y1 = static_cast<int>(std::min<int64_t>(p.h - 1, ymax / kSub + 1));
      if (s.x0 > s.x1 || s.y0 > s.y1) continue;
      finish_setup(&s);
      out->push_back(s);
    }
  }
}

}  // namespace

void scene_tri_setup(const PreparedScene &p, int di, const std::vector<float> &clip, std::vector<ScreenTri> *out) {
  const size_t n = p.draws[di].geo->indices.size();
  for (size_t t = 0; t + 2 < n; t += 3) setup_tri(p, di, clip, t, out);
}

void scene_tri_setup_list(const PreparedScene &p, int di, const std::vector<float> &clip, const uint32_t *tris,
                          size_t count, std::vector<ScreenTri> *out) {
  for (size_t i = 0; i < count; ++i) setup_tri(p, di, clip, static_cast<size_t>(tris[i]) * 3, out);
}

namespace {

// floor(a / b) and ceil(a / b) for b > 0.
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

// The visible pixel i of s with edge values l (double, normalised) and llvmpipe's depth value
// zq: depth test LESS against the 24-bit values, then (kBary) the perspective-correct
// barycentrics (the C rasteriser's own, for what is not interpolated with llvmpipe's planes).
template <bool kBary>
inline void shade_pixel(const ScreenTri &s, const VisRows &vis, size_t i, float zq, double l0, double l1,
                        double l2) {
  if (!(zq < vis.depth[i])) return;
  vis.depth[i] = zq;
  vis.draw[i] = s.draw;
  vis.tri[i] = s.tri;
  vis.sub[i] = static_cast<uint8_t>(s.sub);
  if (!kBary) return;
  double B1, B2;
  scene_tri_bary(s, l0, l1, l2, &B1, &B2);
  vis.b1[i] = static_cast<float>(B1);
  vis.b2[i] = static_cast<float>(B2);
}

// llvmpipe's depth values of pixels x0 .. x0 + n - 1 of row y of s (in chunks of kZChunk).
const int kZChunk = 64;
inline void depth_chunk(const ScreenTri &s, int x0, int y, int n, float *out) {
  LpPlanes zp;
  zp.z0 = s.z0, zp.zdx = s.zdx, zp.zdy = s.zdy;
  lp_depth24_span(zp, x0, y, n, out);
}

// shade_pixel<false> for pixels i .. i + n - 1 of the buffer with depth values zq[0 .. n - 1],
// four at a time without branches (SSE2; the same comparisons and stores).
inline void depth_test_span(const ScreenTri &s, const VisRows &vis, size_t i, const float *zq, int n) {
  float *dep = vis.depth + i;
  int32_t *dr = vis.draw + i, *tr = vis.tri + i;
  uint8_t *sb = vis.sub + i;
  const __m128i D = _mm_set1_epi32(s.draw), T = _mm_set1_epi32(s.tri);
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m128 z = _mm_loadu_ps(zq + k), old = _mm_loadu_ps(dep + k);
    const __m128 m = _mm_cmplt_ps(z, old);  // zq < depth (false for a NaN)
    const int bits = _mm_movemask_ps(m);
    if (!bits) continue;
    const __m128i mi = _mm_castps_si128(m);
    _mm_storeu_ps(dep + k, _mm_or_ps(_mm_and_ps(m, z), _mm_andnot_ps(m, old)));
    const __m128i od = _mm_loadu_si128(reinterpret_cast<const __m128i *>(dr + k));
    const __m128i ot = _mm_loadu_si128(reinterpret_cast<const __m128i *>(tr + k));
    _mm_storeu_si128(reinterpret_cast<__m128i *>(dr + k), _mm_or_si128(_mm_and_si128(mi, D), _mm_andnot_si128(mi, od)));
    _mm_storeu_si128(reinterpret_cast<__m128i *>(tr + k), _mm_or_si128(_mm_and_si128(mi, T), _mm_andnot_si128(mi, ot)));
    if (bits == 15) {
      std::memset(sb + k, s.sub, 4);
      continue;
    }
    for (int j = 0; j < 4; ++j)
      if (bits & (1 << j)) sb[k + j] = static_cast<uint8_t>(s.sub);
  }
  for (; k < n; ++k) shade_pixel<false>(s, vis, i + static_cast<size_t>(k), zq[k], 0, 0, 0);
}

// Rows ya..yb of a triangle with 64-bit edge values: per row, the covered span from the
// three edge inequalities (exact integer division), then the edge values stepped along x (for
// the barycentrics: kBary).
template <bool kBary>
void raster_small(const ScreenTri &s, const VisRows &vis, int ya, int yb) {
  const int w = vis.w;
  int64_t A[3], C[3];  // e_k(x) = C_k(y) + A_k x at the pixel centre (x, y)
  for (int k = 0; k < 3; ++k) A[k] = -s.dy[k] * kSub;
  for (int y = ya; y <= yb; ++y) {
    const int64_t py = static_cast<int64_t>(y) * kSub + kSub / 2;
    int64_t lo = s.x0, hi = s.x1;
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3;
      C[k] = s.dx[k] * (py - s.Y[a]) - s.dy[k] * (kSub / 2 - s.X[a]);
      // covered: e > 0, or e == 0 on a top-left edge: e >= bias
      if (A[k] > 0)
        lo = std::max(lo, ceil_div(s.bias[k] - C[k], A[k]));
      else if (A[k] < 0)
        hi = std::min(hi, floor_div(C[k] - s.bias[k], -A[k]));
      else if (C[k] < s.bias[k])
        hi = lo - 1;
    }
    if (lo > hi) continue;
    int64_t e0 = C[0] + A[0] * lo, e1 = C[1] + A[1] * lo, e2 = C[2] + A[2] * lo;
    const size_t row = static_cast<size_t>(y - vis.y0) * w;
    float zq[kZChunk];
    if (!kBary) {
      for (int64_t x = lo; x <= hi; x += kZChunk) {
        const int n = static_cast<int>(std::min<int64_t>(kZChunk, hi - x + 1));
        depth_chunk(s, static_cast<int>(x), y, n, zq);
        depth_test_span(s, vis, row + static_cast<size_t>(x), zq, n);
      }
      continue;
    }
    for (int64_t x = lo; x <= hi; ++x) {
      const int64_t zi = (x - lo) % kZChunk;
      if (zi == 0) depth_chunk(s, static_cast<int>(x), y, static_cast<int>(std::min<int64_t>(kZChunk, hi - x + 1)), zq);
      shade_pixel<kBary>(s, vis, row + static_cast<size_t>(x), zq[zi], static_cast<double>(e0) * s.inv_area,
                  static_cast<double>(e1) * s.inv_area, static_cast<double>(e2) * s.inv_area);
      e0 += A[0];
      e1 += A[1];
      e2 += A[2];
    }
  }
}

// The general case (coordinates up to 1e9 * 256): 128-bit edge values per pixel.
void raster_wide(const ScreenTri &s, const VisRows &vis, int ya, int yb) {
  for (int y = ya; y <= yb; ++y) {
    const int64_t py = static_cast<int64_t>(y) * kSub + kSub / 2;
    for (int x = s.x0; x <= s.x1; ++x) {
      const int64_t px = static_cast<int64_t>(x) * kSub + kSub / 2;
      double l[3];
      bool in = true;
      for (int k = 0; k < 3 && in; ++k) {
        const int a = (k + 1) % 3;
        const __int128 e =
            static_cast<__int128>(s.dx[k]) * (py - s.Y[a]) - static_cast<__int128>(s.dy[k]) * (px - s.X[a]);
        in = e >= s.bias[k];
        l[k] = static_cast<double>(e) * s.inv_area;
      }
      if (in) {
        float zq;
        depth_chunk(s, x, y, 1, &zq);
        shade_pixel<true>(s, vis, static_cast<size_t>(y - vis.y0) * vis.w + x, zq, l[0], l[1], l[2]);
      }
    }
  }
}

}  // namespace

void scene_raster_rows(const ScreenTri &s, const VisRows &v, int ya, int yb) {
  if (s.small && !v.bary)
    raster_small<false>(s, v, ya, yb);
  else if (s.small)
    raster_small<true>(s, v, ya, yb);
  else
    raster_wide(s, v, ya, yb);
}

void scene_rasterize_cpu(const PreparedScene &p, SceneVisibility *vis, int threads) {
  const size_t n = static_cast<size_t>(p.w) * p.h;
  vis->w = p.w;
  vis->h = p.h;
  vis->pixel_planes = true;
  // A buffer of this size is reset by the bands below; a new one is made on two threads (its
  // page faults are most of the cost), next to the vertex stage and triangle setup.
  const bool reuse = vis->draw.size() == n && vis->tri.size() == n && vis->b1.size() == n && vis->b2.size() == n &&
      vis->depth.size() == n && vis->sub.size() == n;
  std::thread maker;
  if (!reuse) {
    maker = std::thread([vis, n] {
      fresh_buffer<int32_t>(&vis->draw, n, -1);
      fresh_buffer<int32_t>(&vis->tri, n, -1);
      fresh_buffer(&vis->b1, n, 0.f);
    });
    fresh_buffer(&vis->b2, n, 0.f);
    fresh_buffer<uint8_t>(&vis->sub, n, 0);
    fresh_buffer(&vis->depth, n, kLpDepth24Clear);
  }
  // The draws' triangles are set up and rasterised in batches of about kBatch triangles, in draw
  // order (a band takes its triangles in that order, batch after batch, so that equal depths keep
  // the first draw, as GL_LESS does: the same visibility as one batch): the set-up triangles'
  // memory is bounded by the batch, not by the scene's draw count.
  const size_t kBatch = 16384;
  const int kBand = 8;
  const int bands = (p.h + kBand - 1) / kBand;
  // The set-up triangles and clip coordinates of a batch, kept by the calling thread across
  // frames (at most a batch of triangles): made again each frame, their pages were a tenth of
  // the C fallback's frame time on a small frame.
  static thread_local std::vector<ScreenTri> kept_tris;
  static thread_local std::vector<float> kept_clip;
  std::vector<ScreenTri> &tris = kept_tris;  // a local reference: the workers below see this thread's
  std::vector<float> &clip = kept_clip;
  std::vector<std::vector<int>> band_tris(static_cast<size_t>(bands));
  VisRows rows;  // the whole buffer (its pointers taken once the maker has made it)
  rows.w = p.w;
  size_t total = 0;
  bool first = true;
  size_t di = 0;
  while (first || di < p.draws.size()) {
    tris.clear();
    for (; di < p.draws.size() && tris.size() < kBatch; ++di) {
      scene_clip_stage(p, p.draws[di], &clip);
      scene_tri_setup(p, static_cast<int>(di), clip, &tris);
    }
    total += tris.size();
    if (first && maker.joinable()) maker.join();
    rows.draw = vis->draw.data(), rows.tri = vis->tri.data(), rows.sub = vis->sub.data();
    rows.b1 = vis->b1.data(), rows.b2 = vis->b2.data(), rows.depth = vis->depth.data();
    // Bands of kBand rows, each with the batch's triangles that reach it (in draw order);
    // workers take whole bands.
    for (std::vector<int> &b : band_tris) b.clear();
    for (size_t i = 0; i < tris.size(); ++i)
      for (int b = tris[i].y0 / kBand; b <= tris[i].y1 / kBand; ++b)
        band_tris[static_cast<size_t>(b)].push_back(static_cast<int>(i));
    const bool reset = first && reuse;
    parallel_rows(bands, threads, [&](int band) {
      const int ra = band * kBand, rb = std::min(p.h, ra + kBand);
      if (reset) {
        const size_t i0 = static_cast<size_t>(ra) * p.w, i1 = static_cast<size_t>(rb) * p.w;
        std::fill(vis->draw.begin() + i0, vis->draw.begin() + i1, -1);
        std::fill(vis->tri.begin() + i0, vis->tri.begin() + i1, -1);
        std::fill(vis->b1.begin() + i0, vis->b1.begin() + i1, 0.f);
        std::fill(vis->b2.begin() + i0, vis->b2.begin() + i1, 0.f);
        std::fill(vis->depth.begin() + i0, vis->depth.begin() + i1, kLpDepth24Clear);
      }
      for (int ti : band_tris[static_cast<size_t>(band)]) {
        const ScreenTri &s = tris[static_cast<size_t>(ti)];
        const int ya = std::max(s.y0, ra), yb = std::min(s.y1, rb - 1);
        scene_raster_rows(s, rows, ya, yb);
      }
    });
    first = false;
  }
  if (getenv("TS_DRAW_MS")) fprintf(stderr, "C raster setup: %zu triangles\n", total);
}


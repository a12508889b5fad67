// tiershade scene: the C fallback's banded lit pass (scene_render_cpu, glue/scene/cpu_renderer.h):
// bands of rows rasterised into a band-sized visibility buffer and shaded at once, the draws'
// vertex outputs and set-up triangles held a slab of bands at a time (glue/scene/band_slabs.h).
#include <algorithm>
#include <atomic>
#include <vector>

#include "base/parallel_rows.h"
#include "scene/band_slabs.h"
#include "scene/cpu_renderer.h"
#include "scene/cpu_shade.h"
#include "scene/cpu_vertex.h"
#include "scene/raster_tri.h"
#include "scene/skybox_pass.h"

namespace {
size_t g_band_budget = 0;  // scene_cpu_band_budget (0: the default)
std::atomic<bool> g_force_redo{false};
}  // namespace

void scene_render_cpu_force_redo(bool on) { g_force_redo = on; }

void scene_cpu_band_budget(size_t bytes) { g_band_budget = bytes; }

namespace {
// Whether s's box (its fixed-point vertices; pixel centres at 256 x + 128, raster_tri.h) holds a
// pixel centre of the frame, on its edges included: else s covers no pixel.
bool box_holds_centre(const ScreenTri &s) {
  auto any = [](const int64_t *v, int x0, int x1) {
    const int64_t lo = std::min({v[0], v[1], v[2]}) - kSub / 2, hi = std::max({v[0], v[1], v[2]}) - kSub / 2;
    const int64_t a = std::max<int64_t>(x0, lo >= 0 ? (lo + kSub - 1) / kSub : -((-lo) / kSub));
    const int64_t b = std::min<int64_t>(x1, hi >= 0 ? hi / kSub : -((-hi + kSub - 1) / kSub));
    return a <= b;
  };
  return any(s.X, s.x0, s.x1) && any(s.Y, s.y0, s.y1);
}
}  // namespace

void scene_render_cpu(const PreparedScene &p, ImageF *out, std::vector<uint8_t> *linear, int threads,
                      const std::function<void(double)> &progress) {
  const size_t n = static_cast<size_t>(p.w) * p.h;
  // Bands of kBand rows, each with the triangles that reach it in draw order (equal depths keep
  // the first draw, as GL_LESS does); a worker takes bands t, t + n, ... and holds one band's
  // visibility (21 bytes a pixel) at a time. The bands in slabs (glue/scene/band_slabs.h) whose
  // draws' vertex outputs and set-up triangles take at most 4 bytes a pixel of the frame or 32 MiB:
  // one slab unless the scene is large (docs/rendering.md, "Memory").
  const int kBand = 8;
  const int bands = (p.h + kBand - 1) / kBand;
  const size_t budget = g_band_budget ? g_band_budget : std::max<size_t>(8u << 20, n * 2);
  const BandSlabs slabs = plan_band_slabs(p, kBand, budget, sizeof(ScreenTri), threads);
  const int nslabs = static_cast<int>(slabs.first_band.size()) - 1;
  // Kept by the calling thread across frames (their capacity; FTZ/DAZ set as llvmpipe computes).
  static thread_local std::vector<std::vector<ScreenTri>> kept_draw_tris;
  static thread_local std::vector<std::vector<float>> kept_vary;
  std::vector<std::vector<float>> &vary = kept_vary;
  std::vector<std::vector<ScreenTri>> &draw_tris = kept_draw_tris;
  const int nd = static_cast<int>(p.draws.size());
  vary.resize(p.draws.size());
  draw_tris.resize(p.draws.size());
  std::vector<DrawCtx> ctx;
  make_ctx(p, &ctx);
  out->w = p.w;
  out->h = p.h;
  if (out->rgba.size() != n * 4) fresh_buffer(&out->rgba, n * 4, 0.f);  // every pixel is written below
  if (linear && linear->size() != n) fresh_buffer<uint8_t>(linear, n, 0);
  const uint8_t bg = p.sky.present() ? 1 : 0;
  const int workers = parallel_workers(bands, threads);
  struct Worker {
    std::vector<int32_t> draw, tri;
    std::vector<uint8_t> sub;
    std::vector<float> b1, b2, depth;
    std::vector<ts_vec4f> pix;
    PlaneCache cache;
  };
  std::vector<Worker> wk(static_cast<size_t>(workers));
  const size_t bn = static_cast<size_t>(kBand) * p.w;
  std::atomic<int> done{0};
  const size_t nw = static_cast<size_t>(parallel_workers(nd, threads));
  std::vector<std::vector<float>> clip(nw), win_y(nw);
  std::vector<std::vector<ScreenTri>> setup(nw);
  std::vector<std::vector<uint32_t>> pick(nw);
  // Several slabs: a draw's clip positions and triangle rows, kept with its outputs.
  std::vector<std::vector<float>> clips(nslabs > 1 ? p.draws.size() : 0);
  std::vector<std::vector<uint32_t>> tri_rows(clips.size());
  // The buffers of the draws done with, for the next slab's (their capacity: no allocator churn
  // between slabs, whose freed blocks the allocator would keep resident).
  std::vector<std::vector<float>> pool_vary, pool_clip;
  std::vector<std::vector<uint32_t>> pool_rows;
  auto take = [](auto *pool, auto *v) {
    if (!pool->empty() && v->capacity() == 0) v->swap(pool->back()), pool->pop_back();
  };
  // Only the triangles whose box holds a pixel centre can cover one: the distant models' many
  // triangles between the centres are not kept (or rasterised).
  auto keep = [](const std::vector<ScreenTri> &all, std::vector<ScreenTri> *out) {
    out->clear();
    size_t n = 0;
    for (const ScreenTri &s : all) n += box_holds_centre(s);
    out->reserve(n);  // exactly (a freed buffer: several slabs free them after each)
    for (const ScreenTri &s : all)
      if (box_holds_centre(s)) out->push_back(s);
  };
  for (int sl = 0; sl < nslabs; ++sl) {
    const int b0 = slabs.first_band[static_cast<size_t>(sl)], b1 = slabs.first_band[static_cast<size_t>(sl) + 1];
    const int ya = b0 * kBand, yb = std::min(p.h, b1 * kBand) - 1;
    // The draws whose first slab this is: their vertex stage (one slab: and set-up), shared
    // among the workers; each is kept until its last slab.
    std::vector<int> enter, live;
    for (int di = 0; di < nd; ++di) {
      const size_t i = static_cast<size_t>(di);
      if (slabs.draw_first[i] < 0 || slabs.draw_first[i] > sl || slabs.draw_last[i] < sl) continue;
      live.push_back(di);
      if (slabs.draw_first[i] != sl) continue;
      enter.push_back(di);
      take(&pool_vary, &vary[i]);
      if (nslabs > 1) take(&pool_clip, &clips[i]), take(&pool_rows, &tri_rows[i]);
    }
    parallel_rows_by_worker(static_cast<int>(enter.size()), threads, [&](int t, int k) {
      const int di = enter[static_cast<size_t>(k)];
      const size_t i = static_cast<size_t>(di), ti = static_cast<size_t>(t);
      if (nslabs == 1) {
        vertex_stage(p, p.draws[i], &clip[ti], &vary[i]);
        setup[ti].clear();
        scene_tri_setup(p, di, clip[ti], &setup[ti]);
        keep(setup[ti], &draw_tris[i]);
      } else {
        vertex_stage(p, p.draws[i], &clips[i], &vary[i]);
        triangle_rows(p, di, clips[i], &win_y[ti], &tri_rows[i]);
      }
    });
    if (nslabs > 1)  // the live draws' triangles whose rows reach the slab, set up for it
      parallel_rows_by_worker(static_cast<int>(live.size()), threads, [&](int t, int k) {
        const int di = live[static_cast<size_t>(k)];
        const size_t i = static_cast<size_t>(di), ti = static_cast<size_t>(t);
        pick[ti].clear();
        for (size_t tr = 0; tr < tri_rows[i].size(); ++tr)
          if (rows_reach(tri_rows[i][tr], ya, yb)) pick[ti].push_back(static_cast<uint32_t>(tr));
        setup[ti].clear();
        scene_tri_setup_list(p, di, clips[i], pick[ti].data(), pick[ti].size(), &setup[ti]);
        keep(setup[ti], &draw_tris[i]);
      });
    std::vector<std::vector<const ScreenTri *>> band_tris(static_cast<size_t>(b1 - b0));
    for (int di : live)  // in draw order
      for (const ScreenTri &s : draw_tris[static_cast<size_t>(di)])
        for (int b = std::max(b0, s.y0 / kBand); b <= std::min(b1 - 1, s.y1 / kBand); ++b)
          band_tris[static_cast<size_t>(b - b0)].push_back(&s);
    parallel_rows_by_worker(b1 - b0, threads, [&](int t, int bi) {
      Worker &k = wk[static_cast<size_t>(t)];
      const int band = b0 + bi;
      const int ra = band * kBand, rb = std::min(p.h, ra + kBand);
      const size_t m = static_cast<size_t>(rb - ra) * p.w;
      // Only the depth and draw are reset: the triangle, sub-triangle and barycentrics of a pixel
      // are read only where a draw covers it (written with it).
      if (k.draw.size() != bn) {
        k.draw.resize(bn), k.tri.resize(bn), k.sub.resize(bn), k.b1.resize(bn), k.b2.resize(bn), k.depth.resize(bn);
      }
      VisRows v;
      v.w = p.w, v.y0 = ra;
      v.draw = k.draw.data(), v.tri = k.tri.data(), v.sub = k.sub.data();
      v.b1 = k.b1.data(), v.b2 = k.b2.data(), v.depth = k.depth.data();
      // Every pixel is interpolated with llvmpipe's planes of its triangle (the set-up here and in
      // interp_run is the same for the same clip positions): first without the barycentrics; a
      // band where a pixel needs them is rasterised and shaded again with them.
      for (int pass = 0; pass < 2; ++pass) {
        v.bary = pass == 1;
        std::fill(k.draw.begin(), k.draw.end(), -1);
        std::fill(k.depth.begin(), k.depth.end(), kLpDepth24Clear);
        for (const ScreenTri *s : band_tris[static_cast<size_t>(bi)])
          scene_raster_rows(*s, v, std::max(s->y0, ra), std::min(s->y1, rb - 1));
        bool ok = true;
        for (int y = ra; y < rb && ok; ++y) {
          const size_t o = static_cast<size_t>(y - ra) * p.w, row = static_cast<size_t>(y) * p.w;
          const RowVis r = {v.draw + o, v.tri + o, v.sub + o, v.bary ? v.b1 + o : nullptr, v.b2 + o, nullptr};
          float *orow = &out->rgba[row * 4];
          ok = shade_row(p, ctx, vary, nullptr, true, true, y, r, k.pix, &k.cache, orow);
          if (pass == 0 && y == rb - 1 && g_force_redo) ok = false;
          if (ok) skybox_shade_row(p.sky, p.w, y, r.draw, orow);  // skybox_pass.h
        }
        if (ok) break;
      }
      if (linear)
        for (size_t i = 0; i < m; ++i) {
          const int d = k.draw[i];
          (*linear)[static_cast<size_t>(ra) * p.w + i] = d >= 0 ? !p.draws[static_cast<size_t>(d)].display_encoded : bg;
        }
      const int d = ++done;
      if (progress && t == 0) progress(static_cast<double>(d) / bands);
    });
    if (nslabs > 1)  // the slab's triangles freed; the draws done with give their buffers to the next slab's
      for (int di : live) {
        const size_t i = static_cast<size_t>(di);
        std::vector<ScreenTri>().swap(draw_tris[i]);
        if (slabs.draw_last[i] != sl) continue;
        pool_vary.emplace_back(), pool_vary.back().swap(vary[i]);
        pool_clip.emplace_back(), pool_clip.back().swap(clips[i]);
        pool_rows.emplace_back(), pool_rows.back().swap(tri_rows[i]);
      }
  }
  if (nslabs > 1)  // a large scene's buffers are not kept past its frame
    for (size_t i = 0; i < vary.size(); ++i) std::vector<float>().swap(vary[i]), std::vector<ScreenTri>().swap(draw_tris[i]);
}


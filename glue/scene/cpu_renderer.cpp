// tiershade scene: the C fallback's scene frames (glue/scene/cpu_renderer.h): vertex stage and shading
// (the rasteriser: cpu_raster.cpp).
#include "scene/cpu_renderer.h"
#include "scene/cpu_shade.h"
#include "scene/cpu_vertex.h"
#include "scene/raster_tri.h"
#include "scene/lp_interp.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/parallel_rows.h"
#include "families/family.h"
#include "families/model_lighting.h"
#include "families/world_lighting.h"
#include "offline/light_folding.h"
#include "twins/model_lighting.h"
#include "twins/model_lighting_batch.h"
#include "twins/world_lighting_batch.h"
#include "twins/world_lighting.h"

// The draws' contexts (cpu_shade.h).
void make_ctx(const PreparedScene &p, std::vector<DrawCtx> *out) {
  out->resize(p.draws.size());
  for (size_t i = 0; i < p.draws.size(); ++i) {
    const PreparedDraw &d = p.draws[i];
    DrawCtx &c = (*out)[i];
    c.world = d.world;
    for (int k = 0; k < 4; ++k) {
      const int idx = k < 3 ? k : 3;
      c.t2[k] = tex2d_of(p.texture(d, idx));
    }
    c.cube = texcube_of(p.texture(d, 4));
    if (d.world) {
      c.wl = wl_variant_of(*d.variant);
      // u_base u_normalmap u_lightmap u_envmap_mask u_envmap
      c.wt = {&c.t2[0], &c.t2[1], &c.t2[2], &c.t2[3], &c.cube, nullptr, 0};
    } else {
      c.ml = ml_variant_of(*d.variant);
      // u_albedo u_normal_map u_exponent_map u_light_warp u_envmap
      c.mt = {&c.t2[0], &c.t2[1], &c.t2[2], &c.t2[3], &c.cube, nullptr, 0};
    }
    c.rec = d.shared;
    c.uv_slot = d.world ? static_cast<int>(WL_SLOT_UV) : static_cast<int>(ML_SLOT_UV);
    // the textures sampled at the uv (model: albedo, normal, exponent; world: base, normal, mask)
    for (int k : d.world ? std::vector<int>{0, 1, 3} : std::vector<int>{0, 1, 2})
      c.mips = c.mips || c.t2[k].mip_levels > 1;
    c.nused = 0;
    for (int k = 0; k < 6; ++k) {
      bool use = true;
      if (d.world && !c.wl.envmap) use = k == WL_SLOT_UV || k == WL_SLOT_LM_OFFSET;
      if (d.world && c.wl.envmap && c.wl.bumpmap == WL_BUMP_NONE) use = k != WL_SLOT_TANGENT && k != WL_SLOT_BINORMAL;
      if (use) c.used[c.nused++] = k;
    }
  }
}

namespace {

const int kChunk = 64;  // pixels per batched call of scene_shade_cpu (a multiple of 8)

// Four floats as one vector (GCC vector extension: SSE on x86; each lane an IEEE float op).
typedef float F4 __attribute__((vector_size(16)));
inline F4 load4(const float *p) {
  F4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline F4 splat4(float s) { return F4{s, s, s, s}; }

// llvmpipe's set-up of the triangle of vertex records v[0..2] (layout above).
void setup_planes(const float *const v[3], float W, float H, const int *used, int nused, LpTriSet *out) {
  LpVert in[3];
  int m[3];
  for (int k = 0; k < 3; ++k) {
    std::memcpy(in[k].clip, v[k] + kClip, sizeof in[k].clip);
    std::memcpy(in[k].win, v[k] + kWin, sizeof in[k].win);
    std::memcpy(in[k].attr, v[k], sizeof in[k].attr);
    m[k] = static_cast<int>(v[k][kClipMask]);
  }
  lp_setup_tri(in, m, W, H, used, nused, out);
}

// Triangle t of draw d's set-up from the worker's cache, made (setup_planes) on a miss.
const LpTriSet &cached_planes(PlaneCache *pc, const float *vd, const uint32_t *indices, int d, int t, float W,
                              float H, const int *used, int nused) {
  PlaneCache::Entry &ce = pc->at(d, t);
  if (ce.draw != d || ce.tri != t) {
    const uint32_t *idx = &indices[static_cast<size_t>(t) * 3];
    const float *v[3] = {&vd[idx[0] * kVStride], &vd[idx[1] * kVStride], &vd[idx[2] * kVStride]};
    ce.draw = d;
    ce.tri = t;
    setup_planes(v, W, H, used, nused, &ce.set);
  }
  return ce.set;
}

// The pixel slots used[] of pixels x0 .. x0 + n - 1 of row y (one draw d; tri, b1, b2: the
// visibility buffer's row) into pp[k * pitch + i]: with llvmpipe's plane equations of the
// triangle as llvmpipe sets it up (planes: the buffer's pixels are the frame's), else (or where
// no triangle of a clipped one's fan covers the pixel in llvmpipe's snapping) from the C
// rasteriser's barycentrics (v0 b0 + v1 b1 + v2 b2, float, unfused). vb1 == nullptr: no
// barycentrics (the banded pass); false where a pixel would need them (nothing else is wrong).
bool interp_run(const float *vd, const uint32_t *indices, const int32_t *tri, const uint8_t *sub, const float *vb1,
                const float *vb2, int d, int y, int x0, int n, const int *used, int nused, ts_vec4f *pp, int pitch,
                bool planes, float W, float H, int one_w, const int32_t *at, PlaneCache *pc) {
  int i = 0;
  while (i < n) {
    const int t = tri[x0 + i];
    const int sb = sub ? sub[x0 + i] : 0;
    int j = i + 1;
    while (j < n && tri[x0 + j] == t && (!sub || sub[x0 + j] == sb)) ++j;
    const uint32_t *idx = &indices[static_cast<size_t>(t) * 3];
    const float *v[3] = {&vd[idx[0] * kVStride], &vd[idx[1] * kVStride], &vd[idx[2] * kVStride]};
    PlaneCache::Entry &ce = pc->at(d, t);
    if (planes && (ce.draw != d || ce.tri != t)) {
      ce.draw = d;
      ce.tri = t;
      setup_planes(v, W, H, used, nused, &ce.set);
    }
    const LpTriSet &ts = ce.set;
    const int nsub = planes ? ts.n : 0;
    // One triangle for the run (unclipped, or the rasteriser's sub-triangle) at the run's own
    // pixels: a span.
    if (nsub > 0 && !at && (!ts.clipped || sub) && sb < nsub && ts.valid[sb]) {
      lp_interp_span(ts.pl[sb], x0 + i, y, j - i, used, nused, pp, pitch, i);
      i = j;
      continue;
    }
    for (int q = i; q < j; ++q) {
      // The pixel the record is interpolated at: its own, or at[] (MSAA's layers).
      const int w = static_cast<int>(W);
      const int px = at ? at[x0 + q] % w : x0 + q, py = at ? at[x0 + q] / w : y;
      int s = -1;
      if (nsub > 0) s = sub ? (sb < nsub && ts.valid[sb] ? sb : -1) : lp_covering(ts, px, py);
      if (s >= 0) {
        lp_interp_span(ts.pl[s], px, py, 1, used, nused, pp, pitch, q);
        continue;
      }
      if (!vb1) return false;
      const float b1 = vb1[x0 + q], b2 = vb2[x0 + q], b0 = 1.f - b1 - b2;
      const F4 B0 = splat4(b0), B1 = splat4(b1), B2 = splat4(b2);
      for (int u = 0; u < nused; ++u) {
        const int k = used[u];
        const F4 r = load4(v[0] + k * 4) * B0 + load4(v[1] + k * 4) * B1 + load4(v[2] + k * 4) * B2;
        std::memcpy(&pp[static_cast<size_t>(k) * pitch + q], &r, sizeof r);
      }
    }
    i = j;
  }
  // The model family's position slot is vec4(v_position, 1.0) (model_lighting.fs): its w is the
  // constant, not an interpolated 1.
  if (one_w >= 0)
    for (int q = 0; q < n; ++q) pp[static_cast<size_t>(one_w) * pitch + q].w = 1.f;
  return true;
}

// The quad derivatives of the uv (pixel slot uv_slot, .xy) of pixels x0 .. x0 + n - 1 of row y,
// as llvmpipe's sampler takes them (lp_bld_quad.c lp_build_packed_ddx_ddy_twocoord: per 2x2 quad
// at even (x, y), top-right minus top-left and bottom-left minus top-left, for every pixel of
// the quad): the pixel's triangle's planes evaluated at the quad's pixels, covered or not (the
// helper pixels llvmpipe shades with the triangle's planes). Out: (ds/dx, ds/dy, dt/dx, dt/dy).
// A pixel interpolated without llvmpipe's planes (interp_run's fallback) gets 0: level 0.
void uv_grad_run(const float *vd, const uint32_t *indices, const int32_t *tri, const uint8_t *sub, int d, int y,
                 int x0, int n, const int *used, int nused, int uv_slot, float W, float H, const int32_t *at,
                 PlaneCache *pc, ts_vec4f *grad) {
  ts_vec4f tmp[2 * kPixelSlots];
  const int w = static_cast<int>(W);
  int last_t = -1, last_s = -1, last_qx = -1, last_qy = -1;
  ts_vec4f last{0, 0, 0, 0};
  // Runs of one triangle and sub-triangle at their own pixels (the banded pass): the quads of
  // the run at once (lp_quad_grad_span).
  for (int q = 0; sub && !at && q < n;) {
    const int t = tri[x0 + q], sb = sub[x0 + q];
    int j = q + 1;
    while (j < n && tri[x0 + j] == t && sub[x0 + j] == sb) ++j;
    const LpTriSet &ts = cached_planes(pc, vd, indices, d, t, W, H, used, nused);
    if (sb < ts.n && ts.valid[sb])
      lp_quad_grad_span(ts.pl[sb], uv_slot, x0 + q, y, j - q, grad + q);
    else
      std::fill(grad + q, grad + j, ts_v4f(0, 0, 0, 0));
    q = j;
  }
  for (int q = 0; !(sub && !at) && q < n; ++q) {
    const int t = tri[x0 + q];
    const int sb = sub ? sub[x0 + q] : 0;
    const int px = at ? at[x0 + q] % w : x0 + q, py = at ? at[x0 + q] / w : y;
    const LpTriSet &ts = cached_planes(pc, vd, indices, d, t, W, H, used, nused);
    int s = -1;
    if (ts.n > 0) s = sub ? (sb < ts.n && ts.valid[sb] ? sb : -1) : lp_covering(ts, px, py);
    if (s < 0) {
      grad[q] = ts_v4f(0, 0, 0, 0);
      continue;
    }
    const int qx = px & ~1, qy = py & ~1;
    if (t != last_t || s != last_s || qx != last_qx || qy != last_qy) {
      lp_interp_span(ts.pl[s], qx, qy, 2, &uv_slot, 1, tmp, 2, 0);  // TL, TR at tmp[uv_slot * 2 + 0, 1]
      const ts_vec4f tl = tmp[uv_slot * 2], tr = tmp[uv_slot * 2 + 1];
      lp_interp_span(ts.pl[s], qx, qy + 1, 1, &uv_slot, 1, tmp, 1, 0);  // BL at tmp[uv_slot]
      const ts_vec4f bl = tmp[uv_slot];
      last = ts_v4f(tr.x - tl.x, bl.x - tl.x, tr.y - tl.y, bl.y - tl.y);
      last_t = t, last_s = s, last_qx = qx, last_qy = qy;
    }
    grad[q] = last;
  }
}

// Shades n pixels of one draw with the batched twin: pixel slot k of pixel i at
// pix[k * pitch + i], the shared slots from the draw's record.
template <class BatchInput>
BatchInput batch_input(const DrawCtx &c, const ts_vec4f *pix, int pitch, int slots) {
  BatchInput in;
  for (int k = 0; k < slots; ++k) {
    const bool px = k < kPixelSlots;
    in.slot[k] = px ? &pix[static_cast<size_t>(k) * pitch] : &c.rec[k];
    in.stride[k] = px ? 1 : 0;
  }
  return in;
}

// grad: the pixels' uv derivatives (uv_grad_run), or nullptr (level 0).
void shade_run(const DrawCtx &c, const ts_vec4f *pix, int pitch, int n, ts_vec4f *res,
               const ts_vec4f *grad = nullptr) {
  if (c.world) {
    const wl_batch_input in = batch_input<wl_batch_input>(c, pix, pitch, WL_SLOTS);
    wl_textures wt = c.wt;
    wt.uv_grad = grad;
    wt.uv_grad_stride = 1;
    world_lighting_f_batch(&c.wl, &in, &wt, res, n);
  } else {
    const ml_batch_input in = batch_input<ml_batch_input>(c, pix, pitch, ML_SLOTS);
    ml_textures mt = c.mt;
    mt.uv_grad = grad;
    mt.uv_grad_stride = 1;
    model_lighting_f_batch(&c.ml, &in, &mt, res, n);
  }
}

}  // namespace

// Shades row y of the frame into orow (RGBA floats): runs of pixels of one draw are shaded together
// by the batched twins (8 pixels per instruction where the host has AVX2; the same bits as one
// pixel at a time). in_group (nullptr: every draw): the draws shaded by this pass; first: the
// background (draw < 0) is written as 0 here. False when a pixel needs the rasteriser's
// barycentrics and r has none (r.b1 == nullptr): the row is not finished.
bool shade_row(const PreparedScene &p, const std::vector<DrawCtx> &ctx, const std::vector<std::vector<float>> &vary,
               const char *in_group, bool first, bool planes, int y, const RowVis &r, std::vector<ts_vec4f> &pix,
               PlaneCache *cache, float *orow) {
  // the pixel slots of a chunk, then its pixels' uv derivatives (mipmaps: uv_grad_run)
  pix.resize(static_cast<size_t>(kPixelSlots + 1) * kChunk);
  ts_vec4f *grad = pix.data() + static_cast<size_t>(kPixelSlots) * kChunk;
  const float W = static_cast<float>(p.w), H = static_cast<float>(p.h);
  int x = 0;
  while (x < p.w) {
    const int d = r.draw[x];
    if (d < 0 || (in_group && !in_group[static_cast<size_t>(d)])) {  // background: written by the first pass
      if (d < 0 && first) std::memset(orow + static_cast<size_t>(x) * 4, 0, 4 * sizeof(float));
      ++x;
      continue;
    }
    int x1 = x;
    while (x1 < p.w && r.draw[x1] == d) ++x1;
    ts_vec4f *orow_px = reinterpret_cast<ts_vec4f *>(orow) + x;
    // In chunks of kChunk pixels, so that the slots stay in L1 between the two loops.
    const DrawCtx &c = ctx[d];
    int used[kPixelSlots];  // locals: the slot stores below cannot alias them
    const int nused = c.nused;
    std::copy(c.used, c.used + nused, used);
    const float *vd = vary[d].data();
    const uint32_t *indices = p.draws[d].geo->indices.data();
    ts_vec4f *pp = pix.data();
    for (int c0 = x; c0 < x1; c0 += kChunk) {
      const int n = std::min(kChunk, x1 - c0);
      if (!interp_run(vd, indices, r.tri, r.sub, r.b1, r.b2, d, y, c0, n, used, nused, pp, kChunk, planes, W, H,
                      c.world ? -1 : ML_SLOT_POSITION, r.at, cache))
        return false;
      const bool mips = c.mips && planes;
      if (mips) uv_grad_run(vd, indices, r.tri, r.sub, d, y, c0, n, used, nused, c.uv_slot, W, H, r.at, cache, grad);
      shade_run(c, pp, kChunk, n, orow_px + (c0 - x), mips ? grad : nullptr);
    }
    x = x1;
  }
  return true;
}

namespace {

// The draws that own a pixel of vis (a hidden or off-screen draw costs neither the vertex stage
// nor its outputs' memory).
std::vector<char> visible_draws(const PreparedScene &p, const SceneVisibility &vis) {
  std::vector<char> seen(p.draws.size(), 0);
  for (int32_t d : vis.draw)
    if (d >= 0 && static_cast<size_t>(d) < seen.size()) seen[static_cast<size_t>(d)] = 1;
  return seen;
}

// The vertex outputs of the visible draws.
void visible_vertex_stage(const PreparedScene &p, const SceneVisibility &vis, std::vector<std::vector<float>> *vary) {
  const std::vector<char> seen = visible_draws(p, vis);
  vary->assign(p.draws.size(), {});
  std::vector<float> clip;
  for (size_t di = 0; di < p.draws.size(); ++di)
    if (seen[di]) vertex_stage(p, p.draws[di], &clip, &(*vary)[di]);
}

// The shading pass holds the vertex outputs of at most this many bytes of draws at a time (at
// least one draw): the visible draws in draw order, in groups, each group's pixels shaded in a
// pass over the frame, so that the outputs' memory does not grow with the draw count.
const size_t kVaryBudget = 4u << 20;

}  // namespace

void scene_shade_cpu(const PreparedScene &p, const SceneVisibility &vis, ImageF *out, int threads,
                     const std::function<void(double)> &progress) {
  std::vector<DrawCtx> ctx;
  make_ctx(p, &ctx);
  const std::vector<char> seen = visible_draws(p, vis);
  std::vector<std::vector<size_t>> groups(1);  // visible draws, kVaryBudget bytes of outputs a group
  size_t bytes = 0;
  for (size_t di = 0; di < p.draws.size(); ++di) {
    if (!seen[di]) continue;
    const size_t b = p.draws[di].geo->vertices() * kVStride * sizeof(float);
    if (!groups.back().empty() && bytes + b > kVaryBudget) groups.emplace_back(), bytes = 0;
    groups.back().push_back(di);
    bytes += b;
  }
  std::vector<std::vector<float>> vary(p.draws.size());
  std::vector<char> in_group(p.draws.size(), 0);
  out->w = p.w;
  out->h = p.h;
  if (out->rgba.size() != static_cast<size_t>(p.w) * p.h * 4)  // every pixel is written below
    fresh_buffer(&out->rgba, static_cast<size_t>(p.w) * p.h * 4, 0.f);
  std::atomic<int> rows{0};
  // Per thread: the run's pixel slots and results (kept across rows).
  std::vector<std::vector<ts_vec4f>> pix_of(static_cast<size_t>(parallel_workers(p.h, threads)));
  std::vector<PlaneCache> cache(pix_of.size());
  std::vector<float> clip;
  for (size_t gi = 0; gi < groups.size(); ++gi) {
    const bool first = gi == 0;
    for (size_t di : groups[gi]) {
      vertex_stage(p, p.draws[di], &clip, &vary[di]);
      in_group[di] = 1;
    }
    parallel_rows_by_worker(p.h, threads, [&](int t, int y) {
      const size_t row = static_cast<size_t>(y) * p.w;
      const RowVis r = {vis.draw.data() + row,
                        vis.tri.data() + row,
                        vis.sub.size() == vis.tri.size() ? vis.sub.data() + row : nullptr,
                        vis.b1.data() + row,
                        vis.b2.data() + row,
                        vis.at.empty() ? nullptr : vis.at.data() + row};
      shade_row(p, ctx, vary, in_group.data(), first, vis.pixel_planes, y, r, pix_of[static_cast<size_t>(t)], &cache[static_cast<size_t>(t)],
                &out->rgba[row * 4]);
      const int done = ++rows;
      if (progress && t == 0) progress(static_cast<double>(done) / (static_cast<double>(p.h) * groups.size()));
    });
    for (size_t di : groups[gi]) {  // the group's outputs freed before the next group's are made
      std::vector<float>().swap(vary[di]);
      in_group[di] = 0;
    }
  }
  skybox_shade_background(p.sky, p.w, p.h, vis.draw.data(), out->rgba.data(), threads);  // skybox_pass.h
}

void scene_shade_records(const PreparedScene &p, const std::vector<int> &draw, const std::vector<float> &slots,
                         ImageF *out, int threads, const std::vector<float> *grads) {
  std::vector<DrawCtx> ctx;
  make_ctx(p, &ctx);
  out->w = p.w;
  out->h = p.h;
  out->rgba.assign(static_cast<size_t>(p.w) * p.h * 4, 0.f);
  parallel_rows(p.h, threads, [&](int y) {
    std::vector<ts_vec4f> pix(static_cast<size_t>(kPixelSlots) * p.w);
    std::vector<ts_vec4f> res(static_cast<size_t>(p.w));
    const size_t row = static_cast<size_t>(y) * p.w;
    const ts_vec4f *grow = grads ? reinterpret_cast<const ts_vec4f *>(grads->data()) + row : nullptr;
    int x = 0;
    while (x < p.w) {
      const int d = draw[row + x];
      if (d < 0 || d >= static_cast<int>(ctx.size())) {
        ++x;
        continue;
      }
      int x1 = x;
      while (x1 < p.w && draw[row + x1] == d) ++x1;
      const int n = x1 - x;
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < kPixelSlots; ++k)
          std::memcpy(&pix[static_cast<size_t>(k) * p.w + i], &slots[(row + x + i) * 24 + k * 4], 4 * sizeof(float));
      shade_run(ctx[d], pix.data(), p.w, n, res.data(), grow ? grow + x : nullptr);
      std::memcpy(&out->rgba[(row + x) * 4], res.data(), static_cast<size_t>(n) * sizeof(ts_vec4f));
      x = x1;
    }
  });
  skybox_shade_background(p.sky, p.w, p.h, draw.data(), out->rgba.data(), threads);  // skybox_pass.h
}

void scene_records_cpu(const PreparedScene &p, const SceneVisibility &vis, std::vector<int> *draw,
                       std::vector<float> *slots, int threads, std::vector<float> *grads) {
  std::vector<std::vector<float>> vary;
  visible_vertex_stage(p, vis, &vary);
  const size_t n = static_cast<size_t>(p.w) * p.h;
  draw->assign(vis.draw.begin(), vis.draw.end());
  slots->assign(n * kVary, 0.f);
  if (grads) grads->assign(n * 4, 0.f);
  const int all[kPixelSlots] = {0, 1, 2, 3, 4, 5};
  std::vector<PlaneCache> caches(static_cast<size_t>(parallel_workers(p.h, threads)));
  parallel_rows_by_worker(p.h, threads, [&](int t, int y) {
    PlaneCache &cache = caches[static_cast<size_t>(t)];
    std::vector<ts_vec4f> pix(static_cast<size_t>(kPixelSlots) * p.w);
    const size_t row = static_cast<size_t>(y) * p.w;
    int x = 0;
    while (x < p.w) {
      const int d = vis.draw[row + x];
      if (d < 0) {
        ++x;
        continue;
      }
      int x1 = x;
      while (x1 < p.w && vis.draw[row + x1] == d) ++x1;
      interp_run(vary[d].data(), p.draws[d].geo->indices.data(), vis.tri.data() + row,
                 vis.sub.size() == vis.tri.size() ? vis.sub.data() + row : nullptr, vis.b1.data() + row,
                 vis.b2.data() + row, d, y, x, x1 - x, all, kPixelSlots, pix.data(), p.w, vis.pixel_planes,
                 static_cast<float>(p.w), static_cast<float>(p.h), p.draws[d].world ? -1 : ML_SLOT_POSITION,
                 vis.at.empty() ? nullptr : vis.at.data() + row, &cache);
      for (int i = 0; i < x1 - x; ++i)
        for (int k = 0; k < kPixelSlots; ++k)
          std::memcpy(&(*slots)[(row + x + i) * kVary + k * 4], &pix[static_cast<size_t>(k) * p.w + i],
                      sizeof(ts_vec4f));
      if (grads && vis.pixel_planes)
        uv_grad_run(vary[d].data(), p.draws[d].geo->indices.data(), vis.tri.data() + row,
                    vis.sub.size() == vis.tri.size() ? vis.sub.data() + row : nullptr, d, y, x, x1 - x, all,
                    kPixelSlots, p.draws[d].world ? static_cast<int>(WL_SLOT_UV) : static_cast<int>(ML_SLOT_UV),
                    static_cast<float>(p.w), static_cast<float>(p.h), vis.at.empty() ? nullptr : vis.at.data() + row,
                    &cache, reinterpret_cast<ts_vec4f *>(grads->data()) + row + x);
      x = x1;
    }
  });
}

// tiershade scene: the C fallback's scene frames (glue/scene/cpu_renderer.h): rasteriser and shading.
#include "scene/cpu_renderer.h"
#include "scene/raster_tri.h"

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

namespace {

// A new buffer of n copies of v in *out (made aside, then swapped in: the old one is freed).
template <class T>
void fresh_buffer(std::vector<T> *out, size_t n, T v) {
  std::vector<T> b(n, v);
  out->swap(b);
}

// Per draw: the twin's variant, texture views and the record's shared slots.
struct DrawCtx {
  bool world = false;
  ml_variant ml;
  wl_variant wl;
  ts_tex2d t2[4];
  ts_texcube cube;
  ml_textures mt;
  wl_textures wt;
  std::vector<ts_vec4f> rec;  // shared slots (pixel slots overwritten per pixel)
  // The pixel slots the variant reads (world_lighting_impl.h: the normal, tangent, binormal
  // and eye vectors only for ENVMAP, the tangent frame only with a bump map); the others are
  // not interpolated.
  int used[6];
  int nused = 0;
};

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
      c.wt = {&c.t2[0], &c.t2[1], &c.t2[2], &c.t2[3], &c.cube};
    } else {
      c.ml = ml_variant_of(*d.variant);
      // u_albedo u_normal_map u_exponent_map u_light_warp u_envmap
      c.mt = {&c.t2[0], &c.t2[1], &c.t2[2], &c.t2[3], &c.cube};
    }
    c.rec = d.shared;
    c.nused = 0;
    for (int k = 0; k < 6; ++k) {
      bool use = true;
      if (d.world && !c.wl.envmap) use = k == WL_SLOT_UV || k == WL_SLOT_LM_OFFSET;
      if (d.world && c.wl.envmap && c.wl.bumpmap == WL_BUMP_NONE) use = k != WL_SLOT_TANGENT && k != WL_SLOT_BINORMAL;
      if (use) c.used[c.nused++] = k;
    }
  }
}

// ---- vertex stage ----------------------------------------------------------------------

const int kVary = 24;  // 6 slots x 4
const int kPixelSlots = 6;  // ML_PIXEL_SLOTS == WL_PIXEL_SLOTS
const int kChunk = 64;  // pixels per batched call of scene_shade_cpu (a multiple of 8)

// u_model * vec4(X, 1) (a point) or vec4(X, 0) (a direction) in float, summed left to right as
// llvmpipe's vertex shader sums a mat4 * vec4 (model_lighting.vs); the constant w's term is
// folded by the compiler (x * 1 = x; x * 0 and + 0 dropped, no signed zeros kept by GLSL).
inline void model_point(const float *m, const float *X, float *out) {
  for (int r = 0; r < 3; ++r) out[r] = m[r] * X[0] + m[4 + r] * X[1] + m[8 + r] * X[2] + m[12 + r];
}
inline void model_direction(const float *m, const float *X, float *out) {
  for (int r = 0; r < 3; ++r) out[r] = m[r] * X[0] + m[4 + r] * X[1] + m[8 + r] * X[2];
}

// The production vertex shaders' outputs (model_lighting.vs, world_lighting.vs) in float.
void vertex_stage(const PreparedScene &p, const PreparedDraw &d, std::vector<float> *clip, std::vector<float> *vary) {
  const DrawGeometry &g = *d.geo;
  const size_t n = g.vertices();
  clip->assign(n * 4, 0.f);
  vary->assign(n * kVary, 0.f);
  const float *m = p.view_proj;
  const bool ps20 = !d.world && d.variant->tier == Tier::PS20;
  const int nl = ps20 ? d.variant->value("NUM_LIGHTS") : 0;
  for (size_t i = 0; i < n; ++i) {
    const float *P = &g.position[i * 3], *N = &g.normal[i * 3], *T = &g.tangent[i * 4], *UV = &g.uv[i * 2];
    float Pw[3], Nw[3], Tw[4];
    if (d.instanced) {  // object space: the world vectors as u_model makes them
      model_point(d.model, P, Pw);
      model_direction(d.model, N, Nw);
      model_direction(d.model, T, Tw);
      Tw[3] = T[3];
      P = Pw, N = Nw, T = Tw;
    }
    float *c = &(*clip)[i * 4];
    // u_view_proj * vec4(P, 1) in float, summed left to right as llvmpipe's vertex shader
    // does (the visibility must match GL's): not glm's mat4 * vec4, which sums in pairs.
    for (int r = 0; r < 4; ++r) c[r] = m[r] * P[0] + m[4 + r] * P[1] + m[8 + r] * P[2] + m[12 + r];
    float *v = &(*vary)[i * kVary];
    const glm::vec3 B = glm::cross(glm::make_vec3(N), glm::make_vec3(T)) * T[3];  // cross(N, T) * w: the same products
    auto put = [&](int slot, float x, float y, float z, float w) {
      v[slot * 4 + 0] = x;
      v[slot * 4 + 1] = y;
      v[slot * 4 + 2] = z;
      v[slot * 4 + 3] = w;
    };
    if (d.world) {
      const float *L = &g.lightmap[i * 4];
      put(WL_SLOT_UV, UV[0], UV[1], L[0], L[1]);
      put(WL_SLOT_LM_OFFSET, L[2], L[3], c[3], 0);
      put(WL_SLOT_NORMAL, N[0], N[1], N[2], 0);
      put(WL_SLOT_TANGENT, T[0], T[1], T[2], 0);
      put(WL_SLOT_BINORMAL, B[0], B[1], B[2], 0);
      put(WL_SLOT_EYE, p.eye[0] - P[0], p.eye[1] - P[1], p.eye[2] - P[2], 0);
    } else {
      put(ML_SLOT_NORMAL, N[0], N[1], N[2], 0);
      put(ML_SLOT_POSITION, P[0], P[1], P[2], 1);
      put(ML_SLOT_UV, UV[0], UV[1], 0, 0);
      put(ML_SLOT_TANGENT, T[0], T[1], T[2], 0);
      put(ML_SLOT_BITANGENT, B[0], B[1], B[2], 0);
      float att[4] = {0, 0, 0, 0};
      for (int l = 0; l < nl && l < 2; ++l) {
        // The per-vertex value: ts_light_attenuation of common_lights.glsl in double.
        const ts_vec4f *L = &d.shared[ML_SLOT_LIGHT0 + 5 * l];
        float pk[5][4];
        for (int k = 0; k < 5; ++k) pk[k][0] = L[k].x, pk[k][1] = L[k].y, pk[k][2] = L[k].z, pk[k][3] = L[k].w;
        const double pd[3] = {P[0], P[1], P[2]};
        const double a = ts_packed_light_attenuation(pk, pd, nullptr);
        att[l] = static_cast<float>(a);
      }
      put(ML_SLOT_VERTEX_ATTEN, att[0], att[1], att[2], att[3]);
    }
  }
}

// Four floats as one vector (GCC vector extension: SSE on x86; each lane an IEEE float op).
typedef float F4 __attribute__((vector_size(16)));
inline F4 load4(const float *p) {
  F4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline F4 splat4(float s) { return F4{s, s, s, s}; }

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

void shade_run(const DrawCtx &c, const ts_vec4f *pix, int pitch, int n, ts_vec4f *res) {
  if (c.world) {
    const wl_batch_input in = batch_input<wl_batch_input>(c, pix, pitch, WL_SLOTS);
    world_lighting_f_batch(&c.wl, &in, &c.wt, res, n);
  } else {
    const ml_batch_input in = batch_input<ml_batch_input>(c, pix, pitch, ML_SLOTS);
    model_lighting_f_batch(&c.ml, &in, &c.mt, res, n);
  }
}

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

void scene_tri_setup(const PreparedScene &p, int di, const std::vector<float> &clip, std::vector<ScreenTri> *out) {
  const PreparedDraw &d = p.draws[di];
  const double W = p.w, H = p.h;
  const std::vector<uint32_t> &indices = d.geo->indices;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    ClipVert in[3];
    for (int k = 0; k < 3; ++k) {
      const float *c = &clip[indices[t + k] * 4];
      for (int j = 0; j < 4; ++j) in[k].c[j] = c[j];
      for (int j = 0; j < 3; ++j) in[k].bary[j] = j == k ? 1.0 : 0.0;
    }
    // Clip against the near plane z >= -w (and w > 0).
    ClipVert poly[4];
    int np = 0;
    for (int k = 0; k < 3; ++k) {
      const ClipVert &a = in[k], &b = in[(k + 1) % 3];
      const double da = a.c[2] + a.c[3], db = b.c[2] + b.c[3];
      if (da >= 0) poly[np++] = a;
      if ((da >= 0) != (db >= 0)) {
        const double s = da / (da - db);
        ClipVert m;
        for (int j = 0; j < 4; ++j) m.c[j] = a.c[j] + (b.c[j] - a.c[j]) * s;
        for (int j = 0; j < 3; ++j) m.bary[j] = a.bary[j] + (b.bary[j] - a.bary[j]) * s;
        if (np < 4) poly[np++] = m;
      }
    }
    for (int f = 1; f + 1 < np; ++f) {
      const ClipVert *v[3] = {&poly[0], &poly[f], &poly[f + 1]};
      ScreenTri s;
      s.draw = di;
      s.tri = static_cast<int>(t / 3);
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        const double w = v[k]->c[3];
        if (!(w > 1e-12)) ok = false;
        const double sx = (v[k]->c[0] / w * 0.5 + 0.5) * W, sy = (v[k]->c[1] / w * 0.5 + 0.5) * H;
        if (!(std::fabs(sx) < 1e9 && std::fabs(sy) < 1e9)) ok = false;
        s.X[k] = static_cast<int64_t>(std::llround(sx * kSub));
        s.Y[k] = static_cast<int64_t>(std::llround(sy * kSub));
        s.z[k] = v[k]->c[2] / w * 0.5 + 0.5;
        s.invw[k] = 1.0 / w;
        for (int j = 0; j < 3; ++j) s.bary[k][j] = v[k]->bary[j];
      }
      if (!ok) continue;
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

namespace {

// floor(a / b) and ceil(a / b) for b > 0.
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

// The visible pixel (y, x) of s with edge values e (double): depth test LESS, then the
// perspective-correct barycentrics. The operations and their order are the reference's.
inline void shade_pixel(const ScreenTri &s, SceneVisibility *vis, size_t i, double l0, double l1, double l2) {
  const double z = l0 * s.z[0] + l1 * s.z[1] + l2 * s.z[2];
  if (!(z < vis->depth[i]) || z < 0.0) return;
  double B1, B2;
  scene_tri_bary(s, l0, l1, l2, &B1, &B2);
  vis->depth[i] = static_cast<float>(z);
  vis->draw[i] = s.draw;
  vis->tri[i] = s.tri;
  vis->b1[i] = static_cast<float>(B1);
  vis->b2[i] = static_cast<float>(B2);
}

// Rows ya..yb of a triangle with 64-bit edge values: per row, the covered span from the
// three edge inequalities (exact integer division), then the edge values stepped along x.
void raster_small(const ScreenTri &s, SceneVisibility *vis, int ya, int yb) {
  const int w = vis->w;
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
    const size_t row = static_cast<size_t>(y) * w;
    for (int64_t x = lo; x <= hi; ++x) {
      shade_pixel(s, vis, row + static_cast<size_t>(x), static_cast<double>(e0) * s.inv_area,
                  static_cast<double>(e1) * s.inv_area, static_cast<double>(e2) * s.inv_area);
      e0 += A[0];
      e1 += A[1];
      e2 += A[2];
    }
  }
}

// The general case (coordinates up to 1e9 * 256): 128-bit edge values per pixel.
void raster_wide(const ScreenTri &s, SceneVisibility *vis, int ya, int yb) {
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
      if (in) shade_pixel(s, vis, static_cast<size_t>(y) * vis->w + x, l[0], l[1], l[2]);
    }
  }
}

}  // namespace

void scene_rasterize_cpu(const PreparedScene &p, SceneVisibility *vis, int threads) {
  const size_t n = static_cast<size_t>(p.w) * p.h;
  vis->w = p.w;
  vis->h = p.h;
  // A buffer of this size is reset by the bands below; a new one is made on two threads (its
  // page faults are most of the cost), next to the vertex stage and triangle setup.
  const bool reuse = vis->draw.size() == n && vis->tri.size() == n && vis->b1.size() == n && vis->b2.size() == n &&
      vis->depth.size() == n;
  std::thread maker;
  if (!reuse) {
    maker = std::thread([vis, n] {
      fresh_buffer<int32_t>(&vis->draw, n, -1);
      fresh_buffer<int32_t>(&vis->tri, n, -1);
      fresh_buffer(&vis->b1, n, 0.f);
    });
    fresh_buffer(&vis->b2, n, 0.f);
    fresh_buffer(&vis->depth, n, 1.f);
  }
  // The draws' triangles are set up and rasterised in batches of about kBatch triangles, in draw
  // order (a band takes its triangles in that order, batch after batch, so that equal depths keep
  // the first draw, as GL_LESS does: the same visibility as one batch): the set-up triangles'
  // memory is bounded by the batch, not by the scene's draw count.
  const size_t kBatch = 16384;
  const int kBand = 8;
  const int bands = (p.h + kBand - 1) / kBand;
  std::vector<ScreenTri> tris;
  std::vector<float> clip;
  std::vector<std::vector<int>> band_tris(static_cast<size_t>(bands));
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
        std::fill(vis->depth.begin() + i0, vis->depth.begin() + i1, 1.f);
      }
      for (int ti : band_tris[static_cast<size_t>(band)]) {
        const ScreenTri &s = tris[static_cast<size_t>(ti)];
        const int ya = std::max(s.y0, ra), yb = std::min(s.y1, rb - 1);
        if (s.small)
          raster_small(s, vis, ya, yb);
        else
          raster_wide(s, vis, ya, yb);
      }
    });
    first = false;
  }
  if (getenv("TS_DRAW_MS")) fprintf(stderr, "C raster setup: %zu triangles\n", total);
}

namespace {

// The vertex outputs of the draws that own a pixel of vis (the others' stay empty: a hidden or
// off-screen draw costs neither the vertex stage nor its outputs' memory).
void visible_vertex_stage(const PreparedScene &p, const SceneVisibility &vis, std::vector<std::vector<float>> *vary) {
  std::vector<char> seen(p.draws.size(), 0);
  for (int32_t d : vis.draw)
    if (d >= 0 && static_cast<size_t>(d) < seen.size()) seen[static_cast<size_t>(d)] = 1;
  vary->assign(p.draws.size(), {});
  std::vector<float> clip;
  for (size_t di = 0; di < p.draws.size(); ++di)
    if (seen[di]) vertex_stage(p, p.draws[di], &clip, &(*vary)[di]);
}

}  // namespace

void scene_shade_cpu(const PreparedScene &p, const SceneVisibility &vis, ImageF *out, int threads,
                     const std::function<void(double)> &progress) {
  std::vector<DrawCtx> ctx;
  make_ctx(p, &ctx);
  std::vector<std::vector<float>> vary;
  visible_vertex_stage(p, vis, &vary);
  out->w = p.w;
  out->h = p.h;
  if (out->rgba.size() != static_cast<size_t>(p.w) * p.h * 4)  // every pixel is written below
    fresh_buffer(&out->rgba, static_cast<size_t>(p.w) * p.h * 4, 0.f);
  std::atomic<int> rows{0};
  // Per thread: the run's pixel slots and results (kept across rows).
  std::vector<std::vector<ts_vec4f>> pix_of(static_cast<size_t>(parallel_workers(p.h, threads)));
  parallel_rows_by_worker(p.h, threads, [&](int t, int y) {
    // Runs of pixels of one draw are shaded together by the batched twins (8 pixels per
    // instruction where the host has AVX2; the same bits as one pixel at a time).
    std::vector<ts_vec4f> &pix = pix_of[static_cast<size_t>(t)];
    pix.resize(static_cast<size_t>(kPixelSlots) * kChunk);
    const size_t row = static_cast<size_t>(y) * p.w;
    float *orow = &out->rgba[row * 4];
    int x = 0;
    while (x < p.w) {
      const int d = vis.draw[row + x];
      if (d < 0) {
        std::memset(orow + static_cast<size_t>(x) * 4, 0, 4 * sizeof(float));
        ++x;
        continue;
      }
      int x1 = x;
      while (x1 < p.w && vis.draw[row + x1] == d) ++x1;
      ts_vec4f *orow_px = reinterpret_cast<ts_vec4f *>(orow) + x;
      // In chunks of kChunk pixels, so that the slots stay in L1 between the two loops.
      const DrawCtx &c = ctx[d];
      int used[kPixelSlots];  // locals: the slot stores below cannot alias them
      const int nused = c.nused;
      std::copy(c.used, c.used + nused, used);
      const float *vd = vary[d].data();
      const uint32_t *indices = p.draws[d].geo->indices.data();
      const int32_t *tri = vis.tri.data() + row;
      const float *vb1 = vis.b1.data() + row, *vb2 = vis.b2.data() + row;
      ts_vec4f *pp = pix.data();
      for (int c0 = x; c0 < x1; c0 += kChunk) {
        const int n = std::min(kChunk, x1 - c0);
        for (int i = 0; i < n; ++i) {
          const int q = c0 + i;
          const uint32_t *idx = &indices[static_cast<size_t>(tri[q]) * 3];
          const float b1 = vb1[q], b2 = vb2[q], b0 = 1.f - b1 - b2;
          const float *v0 = &vd[idx[0] * kVary], *v1 = &vd[idx[1] * kVary], *v2 = &vd[idx[2] * kVary];
          // v0 b0 + v1 b1 + v2 b2 per component, four components per operation (float, unfused).
          const F4 B0 = splat4(b0), B1 = splat4(b1), B2 = splat4(b2);
          for (int u = 0; u < nused; ++u) {
            const int k = used[u];
            const F4 v = load4(v0 + k * 4) * B0 + load4(v1 + k * 4) * B1 + load4(v2 + k * 4) * B2;
            std::memcpy(&pp[static_cast<size_t>(k) * kChunk + i], &v, sizeof v);
          }
        }
        shade_run(c, pp, kChunk, n, orow_px + (c0 - x));
      }
      x = x1;
    }
    const int done = ++rows;
    if (progress && t == 0) progress(static_cast<double>(done) / p.h);
  });
  skybox_shade_background(p.sky, p.w, p.h, vis.draw.data(), out->rgba.data(), threads);  // skybox_pass.h
}

void scene_shade_records(const PreparedScene &p, const std::vector<int> &draw, const std::vector<float> &slots,
                         ImageF *out, int threads) {
  std::vector<DrawCtx> ctx;
  make_ctx(p, &ctx);
  out->w = p.w;
  out->h = p.h;
  out->rgba.assign(static_cast<size_t>(p.w) * p.h * 4, 0.f);
  parallel_rows(p.h, threads, [&](int y) {
    std::vector<ts_vec4f> pix(static_cast<size_t>(kPixelSlots) * p.w);
    std::vector<ts_vec4f> res(static_cast<size_t>(p.w));
    const size_t row = static_cast<size_t>(y) * p.w;
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
      shade_run(ctx[d], pix.data(), p.w, n, res.data());
      std::memcpy(&out->rgba[(row + x) * 4], res.data(), static_cast<size_t>(n) * sizeof(ts_vec4f));
      x = x1;
    }
  });
  skybox_shade_background(p.sky, p.w, p.h, draw.data(), out->rgba.data(), threads);  // skybox_pass.h
}

void scene_records_cpu(const PreparedScene &p, const SceneVisibility &vis, std::vector<int> *draw,
                       std::vector<float> *slots, int threads) {
  std::vector<std::vector<float>> vary;
  visible_vertex_stage(p, vis, &vary);
  const size_t n = static_cast<size_t>(p.w) * p.h;
  draw->assign(vis.draw.begin(), vis.draw.end());
  slots->assign(n * kVary, 0.f);
  parallel_rows(p.h, threads, [&](int y) {
    for (int x = 0; x < p.w; ++x) {
      const size_t q = static_cast<size_t>(y) * p.w + x;
      const int d = vis.draw[q];
      if (d < 0) continue;
      const uint32_t *idx = &p.draws[d].geo->indices[static_cast<size_t>(vis.tri[q]) * 3];
      const float b1 = vis.b1[q], b2 = vis.b2[q], b0 = 1.f - b1 - b2;
      const float *vd = vary[d].data();
      const float *v0 = &vd[idx[0] * kVary], *v1 = &vd[idx[1] * kVary], *v2 = &vd[idx[2] * kVary];
      const F4 B0 = splat4(b0), B1 = splat4(b1), B2 = splat4(b2);
      for (int k = 0; k < kPixelSlots; ++k) {
        const F4 v = load4(v0 + k * 4) * B0 + load4(v1 + k * 4) * B1 + load4(v2 + k * 4) * B2;
        std::memcpy(&(*slots)[q * kVary + k * 4], &v, sizeof v);
      }
    }
  });
}

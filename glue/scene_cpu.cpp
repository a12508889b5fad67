// tiershade glue: the C fallback's scene frames (glue/scene_cpu.h): rasteriser and shading.
#include "scene_cpu.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <thread>

#include "family.h"
#include "family_world_lighting.h"
#include "model_lighting.h"
#include "model_lighting_batch.h"
#include "world_lighting_batch.h"
#include "world_lighting.h"

namespace {

template <class Fn>
void parallel_rows(int h, int threads, Fn fn) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, std::max(1, h));
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([=] {
      ts_math_init();  // FTZ/DAZ is per thread
      for (int y = t; y < h; y += threads) fn(t, y);
    });
  for (auto &th : pool) th.join();
}

ml_variant ml_of(const Variant &v) {
  ml_variant m = {};
  m.tier = v.tier == Tier::PS20 ? TS_TIER_ID_PS20 : v.tier == Tier::PS2B ? TS_TIER_ID_PS2B : TS_TIER_ID_SM3;
  m.albedo_texture = v.value("ALBEDO_TEXTURE");
  m.half_lambert = v.value("HALF_LAMBERT");
  m.output_mode = v.value("OUTPUT_MODE");
  m.num_lights = v.value("NUM_LIGHTS");
  m.phong = v.value("PHONG");
  m.exponent_map = v.value("PHONG_EXPONENT_MAP");
  m.rim_light = v.value("RIM_LIGHT");
  m.envmap = v.value("ENVMAP");
  m.light_warp = v.value("LIGHT_WARP");
  return m;
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
      c.ml = ml_of(*d.variant);
      // u_albedo u_normal_map u_exponent_map u_light_warp u_envmap
      c.mt = {&c.t2[0], &c.t2[1], &c.t2[2], &c.t2[3], &c.cube};
    }
    c.rec = d.shared;
  }
}


// ---- vertex stage ----------------------------------------------------------------------

const int kVary = 24;  // 6 slots x 4
const int kPixelSlots = 6;  // ML_PIXEL_SLOTS == WL_PIXEL_SLOTS

// The production vertex shaders' outputs (model_lighting.vs, world_lighting.vs) in float.
void vertex_stage(const PreparedScene &p, const PreparedDraw &d, std::vector<float> *clip, std::vector<float> *vary) {
  const size_t n = d.position.size() / 3;
  clip->assign(n * 4, 0.f);
  vary->assign(n * kVary, 0.f);
  const float *m = p.view_proj;
  const bool ps20 = !d.world && d.variant->tier == Tier::PS20;
  const int nl = ps20 ? d.variant->value("NUM_LIGHTS") : 0;
  for (size_t i = 0; i < n; ++i) {
    const float *P = &d.position[i * 3], *N = &d.normal[i * 3], *T = &d.tangent[i * 4], *UV = &d.uv[i * 2];
    float *c = &(*clip)[i * 4];
    for (int r = 0; r < 4; ++r) c[r] = m[r] * P[0] + m[4 + r] * P[1] + m[8 + r] * P[2] + m[12 + r];
    float *v = &(*vary)[i * kVary];
    const float B[3] = {(N[1] * T[2] - N[2] * T[1]) * T[3], (N[2] * T[0] - N[0] * T[2]) * T[3],
                        (N[0] * T[1] - N[1] * T[0]) * T[3]};
    auto put = [&](int slot, float x, float y, float z, float w) {
      v[slot * 4 + 0] = x;
      v[slot * 4 + 1] = y;
      v[slot * 4 + 2] = z;
      v[slot * 4 + 3] = w;
    };
    if (d.world) {
      const float *L = &d.lightmap[i * 4];
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
        // ts_light_attenuation (common_lights.glsl) in double: the per-vertex value.
        const ts_vec4f *L = &d.shared[ML_SLOT_LIGHT0 + 5 * l];
        const double lv[3] = {L[2].x - P[0], L[2].y - P[1], L[2].z - P[2]};
        const double d2 = std::max(lv[0] * lv[0] + lv[1] * lv[1] + lv[2] * lv[2], 1e-30);
        const double dist = std::min(std::sqrt(d2), 1e18);
        const bool directional = L[0].w > 0.5f;
        double Ld[3];
        for (int k = 0; k < 3; ++k) Ld[k] = directional ? -(&L[1].x)[k] : lv[k] / std::sqrt(d2);
        double a = directional ? 1.0 : 1.0 / (L[4].x + L[4].y * dist + L[4].z * dist * dist);
        if (L[1].w > 0.5f) {
          const double cos_a = -(Ld[0] * L[1].x + Ld[1] * L[1].y + Ld[2] * L[1].z);
          a *= std::min(1.0, std::max(0.0, std::pow(std::max(1e-4, (cos_a - L[3].z) * L[3].w), L[3].x)));
        }
        att[l] = static_cast<float>(a);
      }
      put(ML_SLOT_VERTEX_ATTEN, att[0], att[1], att[2], att[3]);
    }
  }
}

// Shades n pixels of one draw with the batched twin: pixel slot k of pixel i at
// pix[k * pitch + i], the shared slots from the draw's record.
void shade_run(const DrawCtx &c, const ts_vec4f *pix, int pitch, int n, ts_vec4f *res) {
  if (c.world) {
    wl_batch_input in;
    for (int k = 0; k < WL_SLOTS; ++k) {
      const bool px = k < kPixelSlots;
      in.slot[k] = px ? &pix[static_cast<size_t>(k) * pitch] : &c.rec[k];
      in.stride[k] = px ? 1 : 0;
    }
    world_lighting_f_batch(&c.wl, &in, &c.wt, res, n);
  } else {
    ml_batch_input in;
    for (int k = 0; k < ML_SLOTS; ++k) {
      const bool px = k < kPixelSlots;
      in.slot[k] = px ? &pix[static_cast<size_t>(k) * pitch] : &c.rec[k];
      in.stride[k] = px ? 1 : 0;
    }
    model_lighting_f_batch(&c.ml, &in, &c.mt, res, n);
  }
}

// ---- rasteriser -----------------------------------------------------------------------

struct ClipVert {
  double c[4];
  double bary[3];
};

struct ScreenTri {
  int draw, tri;
  int64_t X[3], Y[3];  // 8-bit sub-pixel fixed point
  double z[3], invw[3];
  double bary[3][3];  // each screen vertex as barycentrics of the original triangle
  __int128 area;
  int x0, x1, y0, y1;
};

const int kSub = 256;  // llvmpipe rasterises with 8 sub-pixel bits

bool top_left(int64_t dx, int64_t dy) { return dy < 0 || (dy == 0 && dx > 0); }

void setup(const PreparedScene &p, int di, const std::vector<float> &clip, std::vector<ScreenTri> *out) {
  const PreparedDraw &d = p.draws[di];
  const double W = p.w, H = p.h;
  for (size_t t = 0; t + 2 < d.indices.size(); t += 3) {
    ClipVert in[3];
    for (int k = 0; k < 3; ++k) {
      const float *c = &clip[d.indices[t + k] * 4];
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
      out->push_back(s);
    }
  }
}

}  // namespace

void scene_rasterize_cpu(const PreparedScene &p, SceneVisibility *vis, int threads) {
  const size_t n = static_cast<size_t>(p.w) * p.h;
  vis->w = p.w;
  vis->h = p.h;
  vis->draw.assign(n, -1);
  vis->tri.assign(n, -1);
  vis->b1.assign(n, 0.f);
  vis->b2.assign(n, 0.f);
  vis->depth.assign(n, 1.f);
  std::vector<ScreenTri> tris;
  std::vector<float> clip, vary;
  for (size_t di = 0; di < p.draws.size(); ++di) {
    vertex_stage(p, p.draws[di], &clip, &vary);
    setup(p, static_cast<int>(di), clip, &tris);
  }
  if (getenv("TS_DRAW_MS")) fprintf(stderr, "C raster setup: %zu triangles\n", tris.size());
  // Bands of kBand rows, each with the triangles that reach it (in draw order, so that equal
  // depths keep the first draw, as GL_LESS does); workers take whole bands.
  const int kBand = 8;
  const int bands = (p.h + kBand - 1) / kBand;
  std::vector<std::vector<int>> band_tris(static_cast<size_t>(bands));
  for (size_t i = 0; i < tris.size(); ++i)
    for (int b = tris[i].y0 / kBand; b <= tris[i].y1 / kBand; ++b) band_tris[static_cast<size_t>(b)].push_back(static_cast<int>(i));
  parallel_rows(bands, threads, [&](int, int band) {
    for (int ti : band_tris[static_cast<size_t>(band)]) {
      const ScreenTri &s = tris[static_cast<size_t>(ti)];
      const double inv_area = 1.0 / static_cast<double>(s.area);
      const int ya = std::max(s.y0, band * kBand), yb = std::min(s.y1, band * kBand + kBand - 1);
      // Edge k (a -> b, opposite vertex k): e = dx (py - Ya) - dy (px - Xa), stepped along x.
      // 64-bit when the coordinates are small enough for exact products, else 128-bit.
      bool small = true;
      for (int k = 0; k < 3; ++k) small = small && std::llabs(s.X[k]) < (1LL << 27) && std::llabs(s.Y[k]) < (1LL << 27);
      for (int y = ya; y <= yb; ++y) {
        const int64_t py = static_cast<int64_t>(y) * kSub + kSub / 2;
        for (int x = s.x0; x <= s.x1; ++x) {
          const int64_t px = static_cast<int64_t>(x) * kSub + kSub / 2;
          double l[3];
          bool in = true;
          for (int k = 0; k < 3 && in; ++k) {
            const int a = (k + 1) % 3, b = (k + 2) % 3;
            const int64_t dx = s.X[b] - s.X[a], dy = s.Y[b] - s.Y[a];
            if (small) {
              const int64_t e = dx * (py - s.Y[a]) - dy * (px - s.X[a]);
              in = e > 0 || (e == 0 && top_left(dx, dy));
              l[k] = static_cast<double>(e) * inv_area;
            } else {
              const __int128 e = static_cast<__int128>(dx) * (py - s.Y[a]) - static_cast<__int128>(dy) * (px - s.X[a]);
              in = e > 0 || (e == 0 && top_left(dx, dy));
              l[k] = static_cast<double>(e) * inv_area;
            }
          }
          if (!in) continue;
          const double z = l[0] * s.z[0] + l[1] * s.z[1] + l[2] * s.z[2];
          const size_t i = static_cast<size_t>(y) * p.w + x;
          if (!(z < vis->depth[i]) || z < 0.0) continue;
          const double q[3] = {l[0] * s.invw[0], l[1] * s.invw[1], l[2] * s.invw[2]};
          const double qs = q[0] + q[1] + q[2];
          double B[3] = {0, 0, 0};
          for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) B[j] += q[k] / qs * s.bary[k][j];
          vis->depth[i] = static_cast<float>(z);
          vis->draw[i] = s.draw;
          vis->tri[i] = s.tri;
          vis->b1[i] = static_cast<float>(B[1]);
          vis->b2[i] = static_cast<float>(B[2]);
        }
      }
    }
  });
}

void scene_shade_cpu(const PreparedScene &p, const SceneVisibility &vis, ImageF *out, int threads,
                     const std::function<void(double)> &progress) {
  std::vector<DrawCtx> ctx;
  make_ctx(p, &ctx);
  std::vector<std::vector<float>> vary(p.draws.size());
  std::vector<float> clip;
  for (size_t di = 0; di < p.draws.size(); ++di) vertex_stage(p, p.draws[di], &clip, &vary[di]);
  out->w = p.w;
  out->h = p.h;
  out->rgba.assign(static_cast<size_t>(p.w) * p.h * 4, 0.f);
  std::atomic<int> rows{0};
  parallel_rows(p.h, threads, [&](int t, int y) {
    // Runs of pixels of one draw are shaded together by the batched twins (8 pixels per
    // instruction where the host has AVX2; the same bits as one pixel at a time).
    std::vector<ts_vec4f> pix(static_cast<size_t>(kPixelSlots) * p.w);
    std::vector<ts_vec4f> res(static_cast<size_t>(p.w));
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
      const int n = x1 - x;
      const std::vector<float> &vd = vary[d];
      const uint32_t *indices = p.draws[d].indices.data();
      for (int i = 0; i < n; ++i) {
        const size_t q = row + x + i;
        const uint32_t *idx = &indices[static_cast<size_t>(vis.tri[q]) * 3];
        const float b1 = vis.b1[q], b2 = vis.b2[q], b0 = 1.f - b1 - b2;
        const float *v0 = &vd[idx[0] * kVary], *v1 = &vd[idx[1] * kVary], *v2 = &vd[idx[2] * kVary];
        for (int k = 0; k < kPixelSlots; ++k) {
          float *o = &pix[static_cast<size_t>(k) * p.w + i].x;
          for (int c = 0; c < 4; ++c) o[c] = v0[k * 4 + c] * b0 + v1[k * 4 + c] * b1 + v2[k * 4 + c] * b2;
        }
      }
      shade_run(ctx[d], pix.data(), p.w, n, res.data());
      std::memcpy(&out->rgba[(row + x) * 4], res.data(), static_cast<size_t>(n) * sizeof(ts_vec4f));
      x = x1;
    }
    const int done = ++rows;
    if (progress && t == 0) progress(static_cast<double>(done) / p.h);
  });
}

void scene_shade_records(const PreparedScene &p, const std::vector<int> &draw, const std::vector<float> &slots,
                         ImageF *out, int threads) {
  std::vector<DrawCtx> ctx;
  make_ctx(p, &ctx);
  out->w = p.w;
  out->h = p.h;
  out->rgba.assign(static_cast<size_t>(p.w) * p.h * 4, 0.f);
  parallel_rows(p.h, threads, [&](int, int y) {
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
}

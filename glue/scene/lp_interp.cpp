// tiershade scene: llvmpipe's attribute interpolation in float (glue/scene/lp_interp.h). Our own
// code; each formula cites the Mesa 22.3 file and function whose arithmetic it reproduces.
#include "scene/lp_interp.h"

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace {

inline LpF4 ld4(const float *p) {
  LpF4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline LpF4 sp4(float s) { return LpF4{s, s, s, s}; }

}  // namespace

void lp_window_pos(const float c[4], float W, float H, float out[4]) {
  // draw_llvm.c generate_viewport: out3 = 1 / w (LLVMBuildFDiv), x = x * out3 (LLVMBuildFMul),
  // x = lp_build_fmuladd(x, scale, trans).
  const float oow = 1.0f / c[3];
  const float scale[3] = {W * 0.5f, H * 0.5f, 0.5f}, trans[3] = {W * 0.5f, H * 0.5f, 0.5f};
  for (int i = 0; i < 3; ++i) out[i] = ts_madf(c[i] * oow, scale[i], trans[i]);
  out[3] = oow;
}

int lp_clipmask(const float c[4]) {
  // draw_llvm.c generate_clipmask: x > w, -w > x, y > w, -w > y (clip_xy, no guard band);
  // -w > z (near, GL's -1..1 depth), z > w (far).
  const float x = c[0], y = c[1], z = c[2], w = c[3], nw = -w;
  return (x > w ? 1 : 0) | (nw > x ? 2 : 0) | (y > w ? 4 : 0) | (nw > y ? 8 : 0) | (nw > z ? 16 : 0) |
      (z > w ? 32 : 0);
}

bool lp_tri_order(const float *p0, const float *p1, const float *p2, int order[3]) {
  // lp_setup_tri.c calc_fixed_position (SSE path): (x - pixel_offset) * FIXED_ONE in float,
  // cvtps2dq (round to nearest even); area = dx01 * dy20 - dx20 * dy01 in 64 bits.
  const float off = 0.5f, one = 256.0f;
  auto snap = [&](float v) { return static_cast<int64_t>(std::nearbyint((v - off) * one)); };
  const int64_t x0 = snap(p0[0]), x1 = snap(p1[0]), x2 = snap(p2[0]);
  const int64_t y0 = snap(p0[1]), y1 = snap(p1[1]), y2 = snap(p2[1]);
  const int64_t area = (x0 - x1) * (y2 - y0) - (x2 - x0) * (y0 - y1);
  if (area == 0) return false;
  // triangle_both: area > 0 as given; area < 0 with flatshade_first off: (v1, v0, v2).
  if (area > 0) {
    order[0] = 0, order[1] = 1, order[2] = 2;
  } else {
    order[0] = 1, order[1] = 0, order[2] = 2;
  }
  return true;
}

void lp_tri_planes(const float *const p[3], const float *const v[3], const int *used, int nused, LpPlanes *out) {
  // lp_state_setup.c init_args: xy0_center = pos0 - 0.5 (pixel_center_half); dxy01 = pos0 - pos1;
  // dxy20 = pos2 - pos0; ef = dxy01 * dxy20.yx; ooa = 1 / (e - f); dxy20 *= ooa; dxy01 *= ooa.
  const LpF4 P0 = ld4(p[0]), P1 = ld4(p[1]), P2 = ld4(p[2]);
  const LpF4 xy0c = P0 - sp4(0.5f);
  LpF4 d01 = P0 - P1, d20 = P2 - P0;
  const float e = d01[0] * d20[1], f = d01[1] * d20[0];
  const float ooa = 1.0f / (e - f);
  d20 = d20 * sp4(ooa);
  d01 = d01 * sp4(ooa);
  const LpF4 dy20 = sp4(d20[1]), dy01 = sp4(d01[1]), dx20 = sp4(d20[0]), dx01 = sp4(d01[0]);
  const LpF4 x0c = sp4(xy0c[0]), y0c = sp4(xy0c[1]);
  // calc_coef4: da01 = a0 - a1; da20 = a2 - a0; dadx = da01 dy20_ooa - da20 dy01_ooa;
  // dady = da20 dx01_ooa - da01 dx20_ooa; a0' = a0 - (dadx x0_center + dady y0_center); every
  // operation a separate LLVMBuild FMul/FSub/FAdd (never fused).
  auto coef = [&](LpF4 a0, LpF4 a1, LpF4 a2, LpF4 *c0, LpF4 *cx, LpF4 *cy) {
    const LpF4 da01 = a0 - a1, da20 = a2 - a0;
    const LpF4 dadx = da01 * dy20 - da20 * dy01;
    const LpF4 dady = da20 * dx01 - da01 * dx20;
    *c0 = a0 - (dadx * x0c + dady * y0c);
    *cx = dadx;
    *cy = dady;
  };
  LpF4 c0, cx, cy;
  coef(P0, P1, P2, &c0, &cx, &cy);  // the position, slot 0: its w is 1/w
  out->w0 = c0[3];
  out->wdx = cx[3];
  out->wdy = cy[3];
  out->z0 = c0[2];
  out->zdx = cx[2];
  out->zdy = cy[2];
  // apply_perspective_corr: every vertex's attribute times its own 1/w (pos[3]) before calc_coef4.
  const LpF4 o0 = sp4(p[0][3]), o1 = sp4(p[1][3]), o2 = sp4(p[2][3]);
  for (int u = 0; u < nused; ++u) {
    const int k = used[u];
    coef(ld4(v[0] + 4 * k) * o0, ld4(v[1] + 4 * k) * o1, ld4(v[2] + 4 * k) * o2, &out->a0[k], &out->dx[k],
         &out->dy[k]);
  }
}

namespace {

// lp_bld_interp.c: pixoffx = quad offset + block x, an integer in float (exact); w =
// fmuladd(dwdy, y, fmuladd(dwdx, x, w0)) (interp_attrib_linear on the position's w); oow =
// lp_build_rcp(w), a true division (lp_bld_arit.c: RCPPS is not used); per channel a =
// fmuladd(dady, y, fmuladd(dadx, x, a0)), then a * oow (lp_build_mul).
#pragma GCC push_options
#pragma GCC target("fma")
void span_fused(const LpPlanes &pl, int x0, int y, int n, const int *used, int nused, ts_vec4f *out, int pitch,
                int i0) {
  const float yf = static_cast<float>(y);
  const __m128 Y = _mm_set1_ps(yf);
  int i = 0;
  // Two pixels per 8-lane vector (pixel i in lanes 0-3, i + 1 in 4-7): the same operations per
  // lane as the one-pixel loop below; slot k's two results are adjacent in out.
  const __m256 Y8 = _mm256_set1_ps(yf), wdx = _mm256_set1_ps(pl.wdx), wdy = _mm256_set1_ps(pl.wdy);
  const __m256 w0 = _mm256_set1_ps(pl.w0), one = _mm256_set1_ps(1.0f);
  for (; i + 1 < n; i += 2) {
    const float xa = static_cast<float>(x0 + i), xb = static_cast<float>(x0 + i + 1);
    const __m256 X = _mm256_setr_ps(xa, xa, xa, xa, xb, xb, xb, xb);
    const __m256 O = _mm256_div_ps(one, _mm256_fmadd_ps(wdy, Y8, _mm256_fmadd_ps(wdx, X, w0)));
    for (int u = 0; u < nused; ++u) {
      const int k = used[u];
      const __m256 dy = _mm256_broadcast_ps(reinterpret_cast<const __m128 *>(&pl.dy[k]));
      const __m256 dx = _mm256_broadcast_ps(reinterpret_cast<const __m128 *>(&pl.dx[k]));
      const __m256 a0 = _mm256_broadcast_ps(reinterpret_cast<const __m128 *>(&pl.a0[k]));
      const __m256 a = _mm256_fmadd_ps(dy, Y8, _mm256_fmadd_ps(dx, X, a0));
      _mm256_storeu_ps(&out[static_cast<size_t>(k) * pitch + i0 + i].x, _mm256_mul_ps(a, O));
    }
  }
  for (; i < n; ++i) {
    const float xf = static_cast<float>(x0 + i);
    const float w = std::fma(pl.wdy, yf, std::fma(pl.wdx, xf, pl.w0));
    const __m128 X = _mm_set1_ps(xf), O = _mm_set1_ps(1.0f / w);
    for (int u = 0; u < nused; ++u) {
      const int k = used[u];
      const __m128 a = _mm_fmadd_ps((__m128)pl.dy[k], Y, _mm_fmadd_ps((__m128)pl.dx[k], X, (__m128)pl.a0[k]));
      _mm_storeu_ps(&out[static_cast<size_t>(k) * pitch + i0 + i].x, _mm_mul_ps(a, O));
    }
  }
}
void depth_fused(const LpPlanes &pl, int x0, int y, int n, float *out) {
  const float yf = static_cast<float>(y);
  int i = 0;
  // Eight pixels a vector: maxps(0, z) and minps(1, m) return their second operand for a NaN, as
  // std::max(z, 0) and std::min(m, 1) do; the rounding is the current mode's, as nearbyint's.
  const __m256 Y = _mm256_set1_ps(yf), zdx = _mm256_set1_ps(pl.zdx), zdy = _mm256_set1_ps(pl.zdy);
  const __m256 z0 = _mm256_set1_ps(pl.z0), zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
  const __m256 scale = _mm256_set1_ps(16777215.0f), step = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
  for (; i + 8 <= n; i += 8) {
    const __m256 X = _mm256_add_ps(_mm256_set1_ps(static_cast<float>(x0 + i)), step);  // exact below 2^24
    __m256 z = _mm256_fmadd_ps(zdy, Y, _mm256_fmadd_ps(zdx, X, z0));
    z = _mm256_min_ps(one, _mm256_max_ps(zero, z));
    _mm256_storeu_ps(out + i, _mm256_round_ps(_mm256_mul_ps(z, scale), _MM_FROUND_CUR_DIRECTION));
  }
  for (; i < n; ++i) {
    float z = std::fma(pl.zdy, yf, std::fma(pl.zdx, static_cast<float>(x0 + i), pl.z0));
    z = std::min(std::max(z, 0.0f), 1.0f);
    out[i] = std::nearbyint(z * 16777215.0f);
  }
}
// Two quads' top-left, top-right, bottom-left (and bottom-left again) pixels in 8 lanes: their
// .x (s) and .y (t) of slot k, as span_fused computes them.
void quad_grad_fused(const LpPlanes &pl, int k, int x0, int y, int n, ts_vec4f *out) {
  const int qa = x0 & ~1, qb = (x0 + n - 1) & ~1, qy = y & ~1;
  const float fy = static_cast<float>(qy), fy1 = static_cast<float>(qy + 1);
  const __m256 Y = _mm256_setr_ps(fy, fy, fy1, fy1, fy, fy, fy1, fy1);
  const __m256 wdx = _mm256_set1_ps(pl.wdx), wdy = _mm256_set1_ps(pl.wdy), w0 = _mm256_set1_ps(pl.w0);
  const __m256 sdx = _mm256_set1_ps(pl.dx[k][0]), sdy = _mm256_set1_ps(pl.dy[k][0]), s0 = _mm256_set1_ps(pl.a0[k][0]);
  const __m256 tdx = _mm256_set1_ps(pl.dx[k][1]), tdy = _mm256_set1_ps(pl.dy[k][1]), t0 = _mm256_set1_ps(pl.a0[k][1]);
  const __m256 one = _mm256_set1_ps(1.0f);
  for (int qx = qa; qx <= qb; qx += 4) {
    const float a = static_cast<float>(qx), b = static_cast<float>(qx + 2);
    const __m256 X = _mm256_setr_ps(a, a + 1.0f, a, a, b, b + 1.0f, b, b);  // exact: integers below 2^24
    const __m256 O = _mm256_div_ps(one, _mm256_fmadd_ps(wdy, Y, _mm256_fmadd_ps(wdx, X, w0)));
    alignas(32) float S[8], T[8];
    _mm256_store_ps(S, _mm256_mul_ps(_mm256_fmadd_ps(sdy, Y, _mm256_fmadd_ps(sdx, X, s0)), O));
    _mm256_store_ps(T, _mm256_mul_ps(_mm256_fmadd_ps(tdy, Y, _mm256_fmadd_ps(tdx, X, t0)), O));
    for (int h = 0; h < 2; ++h) {
      const float *s = S + 4 * h, *t = T + 4 * h;
      const ts_vec4f g = {s[1] - s[0], s[2] - s[0], t[1] - t[0], t[2] - t[0]};
      const int p0 = std::max(x0, qx + 2 * h), p1 = std::min(x0 + n, qx + 2 * h + 2);
      for (int p = p0; p < p1; ++p) out[p - x0] = g;
    }
  }
}
#pragma GCC pop_options

typedef float LpF8 __attribute__((vector_size(32)));  // eight IEEE float ops at once, never fused

void quad_grad_plain(const LpPlanes &pl, int k, int x0, int y, int n, ts_vec4f *out) {
  const int qa = x0 & ~1, qb = (x0 + n - 1) & ~1, qy = y & ~1;
  const float fy = static_cast<float>(qy), fy1 = static_cast<float>(qy + 1);
  const LpF8 Y = {fy, fy, fy1, fy1, fy, fy, fy1, fy1};
  for (int qx = qa; qx <= qb; qx += 4) {
    const float a = static_cast<float>(qx), b = static_cast<float>(qx + 2);
    const LpF8 X = {a, a + 1.0f, a, a, b, b + 1.0f, b, b};
    const LpF8 O = 1.0f / (pl.wdy * Y + (pl.wdx * X + pl.w0));
    const LpF8 S = (pl.dy[k][0] * Y + (pl.dx[k][0] * X + pl.a0[k][0])) * O;
    const LpF8 T = (pl.dy[k][1] * Y + (pl.dx[k][1] * X + pl.a0[k][1])) * O;
    for (int h = 0; h < 2; ++h) {
      const int o = 4 * h;
      const ts_vec4f g = {S[o + 1] - S[o], S[o + 2] - S[o], T[o + 1] - T[o], T[o + 2] - T[o]};
      const int p0 = std::max(x0, qx + 2 * h), p1 = std::min(x0 + n, qx + 2 * h + 2);
      for (int p = p0; p < p1; ++p) out[p - x0] = g;
    }
  }
}

void depth_plain(const LpPlanes &pl, int x0, int y, int n, float *out) {
  const float yf = static_cast<float>(y);
  for (int i = 0; i < n; ++i) {
    float z = pl.zdy * yf + (pl.zdx * static_cast<float>(x0 + i) + pl.z0);
    z = std::min(std::max(z, 0.0f), 1.0f);
    out[i] = std::nearbyint(z * 16777215.0f);
  }
}

void span_plain(const LpPlanes &pl, int x0, int y, int n, const int *used, int nused, ts_vec4f *out, int pitch,
                int i0) {
  const float yf = static_cast<float>(y);
  const LpF4 Y = sp4(yf);
  for (int i = 0; i < n; ++i) {
    const float xf = static_cast<float>(x0 + i);
    const float w = pl.wdy * yf + (pl.wdx * xf + pl.w0);
    const LpF4 X = sp4(xf), O = sp4(1.0f / w);
    for (int u = 0; u < nused; ++u) {
      const int k = used[u];
      const LpF4 a = (pl.dy[k] * Y + (pl.dx[k] * X + pl.a0[k])) * O;
      std::memcpy(&out[static_cast<size_t>(k) * pitch + i0 + i], &a, sizeof a);
    }
  }
}

}  // namespace

void lp_depth24_span(const LpPlanes &pl, int x0, int y, int n, float *out) {
  if (ts_math_fused())
    depth_fused(pl, x0, y, n, out);
  else
    depth_plain(pl, x0, y, n, out);
}

void lp_interp_span(const LpPlanes &pl, int x0, int y, int n, const int *used, int nused, ts_vec4f *out, int pitch,
                    int i0) {
  if (ts_math_fused())
    span_fused(pl, x0, y, n, used, nused, out, pitch, i0);
  else
    span_plain(pl, x0, y, n, used, nused, out, pitch, i0);
}

void lp_quad_grad_span(const LpPlanes &pl, int k, int x0, int y, int n, ts_vec4f *out) {
  if (n <= 0) return;
  if (ts_math_fused())
    quad_grad_fused(pl, k, x0, y, n, out);
  else
    quad_grad_plain(pl, k, x0, y, n, out);
}

namespace {

// draw_pipe_clip.c getclipdist for the 6 view-volume planes: dot4(clip_pos, plane), the planes of
// draw_context.c draw_init: (-1,0,0,1) (1,0,0,1) (0,-1,0,1) (0,1,0,1) (0,0,1,1) (0,0,-1,1).
float clip_dist(const float *c, int plane) {
  static const float P[6][4] = {{-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {0, 0, -1, 1}};
  const float *p = P[plane];
  return c[0] * p[0] + c[1] * p[1] + c[2] * p[2] + c[3] * p[3];
}

// draw_pipe_clip.c interp: dst = out + t (in - out) for the clip position and every perspective
// attribute (LINTERP, unfused: Mesa is built for baseline x86-64); the window position from the
// new clip position: oow = 1 / w, x = x * oow * scale + trans (unfused, left to right).
void clip_interp(LpVert *dst, float t, const LpVert &out, const LpVert &in, float W, float H) {
  for (int i = 0; i < 4; ++i) dst->clip[i] = out.clip[i] + t * (in.clip[i] - out.clip[i]);
  const float oow = 1.0f / dst->clip[3];
  const float scale[3] = {W * 0.5f, H * 0.5f, 0.5f}, trans[3] = {W * 0.5f, H * 0.5f, 0.5f};
  for (int i = 0; i < 3; ++i) dst->win[i] = dst->clip[i] * oow * scale[i] + trans[i];
  dst->win[3] = oow;
  for (int i = 0; i < 24; ++i) dst->attr[i] = out.attr[i] + t * (in.attr[i] - out.attr[i]);
}

}  // namespace

int lp_clip_tri(const LpVert in[3], const int m[3], float W, float H, LpVert poly[kLpMaxPoly]) {
  // clip_tri: all three outside one plane: culled.
  if ((m[0] & m[1] & m[2]) != 0) return 0;
  int clipmask = m[0] | m[1] | m[2];
  LpVert tmp[2 * kLpMaxPoly + 2];
  const LpVert *lists[2][kLpMaxPoly + 1];
  int cur = 0, n = 3, ntmp = 0;
  for (int k = 0; k < 3; ++k) lists[0][k] = &in[k];
  while (clipmask && n >= 3) {
    const int plane = __builtin_ctz(static_cast<unsigned>(clipmask));  // ffs(clipmask) - 1
    clipmask &= ~(1 << plane);
    const LpVert **inl = lists[cur];
    const LpVert **outl = lists[cur ^ 1];
    const LpVert *prev = inl[0];
    float dp_prev = clip_dist(prev->clip, plane);
    if (!std::isfinite(dp_prev)) return 0;  // discard nan (and inf: util_is_inf_or_nan)
    inl[n] = inl[0];  // prevent rotation of vertices
    int outcount = 0;
    for (int i = 1; i <= n; ++i) {
      const LpVert *v = inl[i];
      const float dp = clip_dist(v->clip, plane);
      if (!std::isfinite(dp)) return 0;
      bool different;
      if (dp_prev >= 0.0f) {
        if (outcount >= kLpMaxPoly) return 0;
        outl[outcount++] = prev;
        different = dp < 0.0f;
      } else {
        different = !(dp < 0.0f);
      }
      if (different) {
        if (outcount >= kLpMaxPoly || ntmp >= 2 * kLpMaxPoly + 2) return 0;
        LpVert *nv = &tmp[ntmp++];
        const float denom = dp - dp_prev;
        if (dp < 0.0f) {  // going out
          if (-dp < dp_prev)
            clip_interp(nv, dp / denom, *v, *prev, W, H);
          else
            clip_interp(nv, -dp_prev / denom, *prev, *v, W, H);
        } else {  // coming back in
          if (-dp_prev < dp)
            clip_interp(nv, -dp_prev / denom, *prev, *v, W, H);
          else
            clip_interp(nv, dp / denom, *v, *prev, W, H);
        }
        outl[outcount++] = nv;
      }
      prev = v;
      dp_prev = dp;
    }
    cur ^= 1;
    n = outcount;
  }
  if (n < 3) return 0;
  for (int k = 0; k < n; ++k) poly[k] = *lists[cur][k];
  return n;
}

namespace {

// lp_setup_tri.c calc_fixed_position: (v - 0.5) * 256 in float, rounded to nearest even.
int64_t lp_snap(float v) { return static_cast<int64_t>(std::nearbyint((v - 0.5f) * 256.0f)); }

}  // namespace

void lp_setup_tri(const LpVert in[3], const int m[3], float W, float H, const int *used, int nused, LpTriSet *out) {
  out->n = 0;
  out->clipped = (m[0] | m[1] | m[2]) != 0;
  auto add = [&](const LpVert *t0, const LpVert *t1, const LpVert *t2) {
    const LpVert *t[3] = {t0, t1, t2};
    int order[3];
    const int s = out->n++;
    out->valid[s] = lp_tri_order(t0->win, t1->win, t2->win, order);
    if (!out->valid[s]) return;
    const float *const po[3] = {t[order[0]]->win, t[order[1]]->win, t[order[2]]->win};
    const float *const ao[3] = {t[order[0]]->attr, t[order[1]]->attr, t[order[2]]->attr};
    lp_tri_planes(po, ao, used, nused, &out->pl[s]);
    for (int k = 0; k < 3; ++k) out->X[s][k] = lp_snap(po[k][0]), out->Y[s][k] = lp_snap(po[k][1]);
  };
  if (!out->clipped) {
    add(&in[0], &in[1], &in[2]);
    return;
  }
  LpVert poly[kLpMaxPoly];
  const int n = lp_clip_tri(in, m, W, H, poly);
  for (int i = 2; i < n; ++i) add(&poly[i - 1], &poly[i], &poly[0]);  // emit_poly, provoking vertex last
}

int lp_covering(const LpTriSet &c, int x, int y) {
  for (int s = 0; s < c.n; ++s) {
    if (!c.valid[s]) continue;
    int64_t X[3] = {c.X[s][0], c.X[s][1], c.X[s][2]}, Y[3] = {c.Y[s][0], c.Y[s][1], c.Y[s][2]};
    const int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
    if (area == 0) continue;
    if (area < 0) std::swap(X[1], X[2]), std::swap(Y[1], Y[2]);
    const int64_t px = static_cast<int64_t>(x) * 256, py = static_cast<int64_t>(y) * 256;
    bool in = true;
    for (int k = 0; k < 3 && in; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const int64_t dx = X[b] - X[a], dy = Y[b] - Y[a];
      const int64_t e = dx * (py - Y[a]) - dy * (px - X[a]);
      in = e > 0 || (e == 0 && (dy < 0 || (dy == 0 && dx > 0)));
    }
    if (in) return s;
  }
  return -1;
}

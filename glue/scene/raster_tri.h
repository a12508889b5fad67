// tiershade scene: the C fallback's triangle set-up, shared by its one-sample rasteriser
// (glue/scene/cpu_renderer.cpp) and its multisample one (glue/scene/msaa.cpp): clip-space
// vertices, the triangles llvmpipe draws for each (its window positions and clipper against the
// six planes, glue/scene/lp_interp.h), its 8-bit sub-pixel snapping (FIXED_ORDER 8), the
// top-left rule and the perspective-correct barycentrics at a point given by its edge values.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/prepare.h"

struct ScreenTri {
  int draw, tri;
  int sub;  // which of the triangles llvmpipe draws for tri (LpTriSet's index; 0 unclipped)
  int64_t X[3], Y[3];  // 8-bit sub-pixel fixed point
  double z[3], invw[3];
  double bary[3][3];  // each screen vertex as barycentrics of the original triangle
  __int128 area;
  int x0, x1, y0, y1;
  // Derived once in setup: 1 / area; edge k (a -> b, opposite vertex k) as dx, dy and its
  // top-left bias (an edge value of 0 covers the pixel iff the edge is top or left); small:
  // every coordinate below 2^27, so the edge values are exact in 64 bits; unit: not clipped,
  // each screen vertex is one original vertex (bary rows are unit vectors; ui[j]: the screen
  // vertex that is original vertex j).
  double inv_area;
  // llvmpipe's plane of the window z (lp_tri_planes with the set-up's vertex order), for its
  // 24-bit depth values (lp_depth24_span).
  float z0, zdx, zdy;
  int64_t dx[3], dy[3];
  int bias[3];
  bool small, unit;
  int ui[3];
};

const int kSub = 256;  // llvmpipe rasterises with 8 sub-pixel bits

// u_model * vec4(X, 1) (a point) or vec4(X, 0) (a direction) in float, summed left to right as
// llvmpipe's vertex shader sums a mat4 * vec4 (model_lighting.vs); the constant w's term is
// folded by the compiler (x * 1 = x; x * 0 and + 0 dropped, no signed zeros kept by GLSL).
inline void model_point(const float *m, const float *X, float *out) {
  for (int r = 0; r < 3; ++r) out[r] = m[r] * X[0] + m[4 + r] * X[1] + m[8 + r] * X[2] + m[12 + r];
}
inline void model_direction(const float *m, const float *X, float *out) {
  for (int r = 0; r < 3; ++r) out[r] = m[r] * X[0] + m[4 + r] * X[1] + m[8 + r] * X[2];
}

// A new buffer of n copies of v in *out (made aside, then swapped in: the old one is freed).
template <class T>
void fresh_buffer(std::vector<T> *out, size_t n, T v) {
  std::vector<T> b(n, v);
  out->swap(b);
}

// Rows [y0, y0 + rows) of a visibility buffer w pixels wide (pixel (x, y) at (y - y0) * w + x):
// the whole frame's (scene_rasterize_cpu) or a band's (scene_render_cpu's tiles).
struct VisRows {
  int w = 0, y0 = 0;
  int32_t *draw = nullptr, *tri = nullptr;
  uint8_t *sub = nullptr;
  float *b1 = nullptr, *b2 = nullptr, *depth = nullptr;
  bool bary = true;  // false: b1, b2 are not written (a pass that interpolates with llvmpipe's planes)
};
// Rasterises rows ya..yb (inside v's rows) of s into v: depth test LESS against v.depth, then
// the pixel's draw, triangle, sub-triangle and (v.bary) barycentrics.
void scene_raster_rows(const ScreenTri &s, const VisRows &v, int ya, int yb);

// The clip coordinates of a draw's vertices (u_view_proj * vec4(P, 1), summed as llvmpipe's
// vertex shader sums them).
void scene_clip_stage(const PreparedScene &p, const PreparedDraw &d, std::vector<float> *clip);
// The screen triangles of draw di (clipped and snapped as llvmpipe does, counter-clockwise,
// bounding box in pixels).
void scene_tri_setup(const PreparedScene &p, int di, const std::vector<float> &clip, std::vector<ScreenTri> *out);
// The same for the triangles tris[0 .. count - 1] of draw di (triangle numbers: indices 3 t ..
// 3 t + 2), in that order.
void scene_tri_setup_list(const PreparedScene &p, int di, const std::vector<float> &clip, const uint32_t *tris,
                          size_t count, std::vector<ScreenTri> *out);

// Edge k's value at the sub-pixel point (px, py) (exact: 128-bit products).
inline __int128 scene_tri_edge(const ScreenTri &s, int k, int64_t px, int64_t py) {
  const int a = (k + 1) % 3;
  return static_cast<__int128>(s.dx[k]) * (py - s.Y[a]) - static_cast<__int128>(s.dy[k]) * (px - s.X[a]);
}

// The perspective-correct barycentrics of original vertices 1 and 2 at the point whose
// normalised edge values are l0, l1, l2 (the operations and their order are the reference's).
inline void scene_tri_bary(const ScreenTri &s, double l0, double l1, double l2, double *b1, double *b2) {
  typedef double D2 __attribute__((vector_size(16)));  // GCC vector extension: one SSE2 register
  const double q[3] = {l0 * s.invw[0], l1 * s.invw[1], l2 * s.invw[2]};
  const double qs = q[0] + q[1] + q[2];
  if (s.unit) {
    // Rows of unit vectors: the sum over k of q[k] / qs * bary[k][j] is +0 + ... with one
    // non-zero term (q >= 0 and finite inside the triangle), which is that term exactly.
    const D2 r = D2{q[s.ui[1]], q[s.ui[2]]} / D2{qs, qs};  // two IEEE divisions in one instruction
    *b1 = r[0];
    *b2 = r[1];
  } else {
    // B[j] = sum over k of q[k] / qs * bary[k][j], from 0 in k order (B[0] is not kept).
    const D2 r01 = D2{q[0], q[1]} / D2{qs, qs};
    const double r0 = r01[0], r1 = r01[1], r2 = q[2] / qs;
    *b1 = ((0.0 + r0 * s.bary[0][1]) + r1 * s.bary[1][1]) + r2 * s.bary[2][1];
    *b2 = ((0.0 + r0 * s.bary[0][2]) + r1 * s.bary[1][2]) + r2 * s.bary[2][2];
  }
}

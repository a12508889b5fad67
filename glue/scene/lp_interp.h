// tiershade scene: llvmpipe's attribute interpolation, mirrored in float so that the C fallback's
// varyings are GL's bit for bit (Mesa 22.3 llvmpipe; facts read from Mesa's source, cited next to
// each formula; checked by tests/unit/test_raster_exact.cpp). Three stages:
//  - the window position of a vertex (draw module: the viewport transform after the divide),
//  - the triangle set-up (lp_setup_tri.c: winding; lp_state_setup.c: the plane coefficients a0,
//    dadx, dady of every attribute, perspective attributes pre-multiplied by 1/w),
//  - the fragment side (gallivm lp_bld_interp.c: a = a0 + dadx x + dady y at the integer pixel
//    position with two llvm.fmuladd, fused on an FMA host; perspective: a * (1 / w(x, y))).
#pragma once
#include <cstdint>

#include "math/ts_math.h"

typedef float LpF4 __attribute__((vector_size(16)));  // four IEEE float ops at once, never fused

// Window position (x, y, z, 1/w) of clip position c for a viewport (0, 0, W, H) and the depth
// range [0, 1]. Mesa draw_llvm.c generate_viewport (vertices the clipper keeps): oow = 1 / w (one
// division), then per axis (c * oow) * scale + trans, the last as lp_build_fmuladd (fused on an
// FMA host); scale = trans = (W/2, H/2, 1/2) (st_atom_viewport.c for a framebuffer object, no
// y flip).
void lp_window_pos(const float c[4], float W, float H, float out[4]);

// draw_llvm.c generate_clipmask with the guard band off (llvmpipe clips x and y too): the
// planes a vertex is outside of (x > w, x < -w, y > w, y < -w, z < -w, z > w); 0 = inside.
int lp_clipmask(const float c[4]);

// The per-triangle plane coefficients of up to 6 vec4 slots plus the position's 1/w.
struct LpPlanes {
  float w0, wdx, wdy;  // 1/w = w0 + wdx x + wdy y
  float z0, zdx, zdy;  // window z (no polygon offset)
  LpF4 a0[6], dx[6], dy[6];
};

// lp_setup_tri.c calc_fixed_position + triangle_both (no culling, provoking vertex last): the
// order (0, 1, 2) or (1, 0, 2) in which the set-up sees the vertices; false for a zero area.
bool lp_tri_order(const float *p0, const float *p1, const float *p2, int order[3]);

// lp_state_setup.c init_args + calc_coef4 + apply_perspective_corr for vertices given in the
// set-up's order: window positions p[k] (x, y, z, 1/w), slot vec4s at v[k] + 4 slot, for the
// slots listed in used.
void lp_tri_planes(const float *const p[3], const float *const v[3], const int *used, int nused, LpPlanes *out);

// llvmpipe's depth values of pixels x0 .. x0 + n - 1 of row y against a 24-bit depth buffer:
// z = fmuladd(zdy, y, fmuladd(zdx, x, z0)) (lp_bld_interp.c, the position's z), clamped to
// [0, 1] and converted as lp_bld_conv.c lp_build_clamped_float_to_unsigned_norm does for 24 bits
// (mantissa + 1): iround(z * 16777215) (nearest even); the values as floats (exact below 2^24).
void lp_depth24_span(const LpPlanes &pl, int x0, int y, int n, float *out);
const float kLpDepth24Clear = 16777215.f;  // a depth buffer cleared to 1

// The fragment side for n pixels of row y from column x0 (lp_bld_interp.c attribs_update_simple
// + interp_attrib_linear): slot used[u] of pixel i into out[used[u] * pitch + i0 + i].
void lp_interp_span(const LpPlanes &pl, int x0, int y, int n, const int *used, int nused, ts_vec4f *out, int pitch,
                    int i0);

// The quad derivatives of slot k's .xy for pixels x0 .. x0 + n - 1 of row y, every pixel
// interpolated with pl (lp_bld_quad.c lp_build_packed_ddx_ddy_twocoord: per 2x2 quad at even
// (x, y), top-right minus top-left and bottom-left minus top-left, the quad's pixels interpolated
// as lp_interp_span does, covered or not): out[i] = (ds/dx, ds/dy, dt/dx, dt/dy). Two quads
// per 8-lane vector; the same bits as lp_interp_span at each of the quad's pixels.
void lp_quad_grad_span(const LpPlanes &pl, int k, int x0, int y, int n, ts_vec4f *out);

// A vertex as the draw module holds it: clip position, window position (x, y, z, 1/w), the
// 24 slot floats.
struct LpVert {
  float clip[4], win[4], attr[24];
};
const int kLpMaxPoly = 9;  // a triangle clipped by 6 planes has at most 9 vertices

// draw_pipe_clip.c do_clip_tri (planes of draw_context.c draw_init, in clip-mask bit order;
// interp for each new vertex; the guard band off): the clipped polygon of triangle in[0..2]
// (clip masks m[0..2], their union non-zero) into poly; returns its vertex count (0: culled).
// emit_poly (provoking vertex last) draws its fan as triangles (poly[i - 1], poly[i], poly[0]),
// i = 2 .. n - 1.
int lp_clip_tri(const LpVert in[3], const int m[3], float W, float H, LpVert poly[kLpMaxPoly]);

// A triangle as llvmpipe rasterises it: itself, or the fan of its clipped polygon; per triangle
// the planes and the vertices in llvmpipe's 8-bit fixed point (to find the one covering a pixel).
struct LpTriSet {
  int n = 0;  // triangles drawn: the fan's i - 2 for (poly[i - 1], poly[i], poly[0]); 1 unclipped
  bool clipped = false;
  bool valid[kLpMaxPoly - 2];  // false: zero area in llvmpipe's fixed point (not drawn)
  LpPlanes pl[kLpMaxPoly - 2];
  int64_t X[kLpMaxPoly - 2][3], Y[kLpMaxPoly - 2][3];
};

// The whole set-up of one triangle (vertex masks m from lp_clipmask): lp_clip_tri when a mask is
// set, then lp_tri_order and lp_tri_planes for each triangle drawn (zero areas dropped).
void lp_setup_tri(const LpVert in[3], const int m[3], float W, float H, const int *used, int nused, LpTriSet *out);

// The triangle of s that covers pixel (x, y) (its centre), with the coverage rule of the C
// rasteriser (glue/scene/cpu_raster.cpp: counter-clockwise, top-left), or -1.
int lp_covering(const LpTriSet &s, int x, int y);

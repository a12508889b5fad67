/* tiershade math: texture sampling mirror of Mesa 22.3.6 llvmpipe for RGBA32F textures:
 * texelFetch, 2D NEAREST/LINEAR with REPEAT or CLAMP_TO_EDGE, cube maps (CLAMP_TO_EDGE,
 * seamless OFF), and 2D mip chains with llvmpipe's level of detail from a quad's derivatives
 * (ts_texture2D_gradf).  "f" = bit-exact float32 mirror, "d" = double reference with the same
 * addressing rules (single level).
 * Uses ts_math (call ts_math_init() first).  Details: docs/c_math_layer.md.
 */
#ifndef TS_SAMPLER_H
#define TS_SAMPLER_H

#include "math/ts_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/* CLAMP = GL_CLAMP_TO_EDGE. REPEAT_NPOT: GL_REPEAT addressed as llvmpipe addresses a texture whose
 * level 0 side is not a power of two, whatever the level's own size (lp_bld_sample.c
 * lp_sampler_static_texture_state: pot_width/pot_height come from width0/height0); only
 * ts_mip_level makes it, for the levels of such a texture. */
enum { TS_WRAP_REPEAT = 0, TS_WRAP_CLAMP = 1, TS_WRAP_REPEAT_NPOT = 2 };
enum { TS_FILTER_NEAREST = 0, TS_FILTER_LINEAR = 1 }; /* min = mag filter         */

enum { TS_MIP_NONE = 0, TS_MIP_NEAREST = 1, TS_MIP_LINEAR = 2 }; /* GL_*_MIPMAP_NEAREST / _LINEAR */
#define TS_MAX_MIP_LEVELS 16 /* a 32768-texel side */

/* RGBA32F, 4 floats per texel, row-major; row 0 = GL's t=0 row (glTexImage2D order). Level 0 is
 * (w, h, texels); levels 1 .. mip_levels - 1 (mip_levels <= 1: a single level) are
 * mip_w[k] x mip_h[k] at mip_texels[k], each max(1, size >> k) as GL requires of a complete chain;
 * filter is both the magnification filter and the minification filter's image part, mip_filter
 * its mipmap part (read only by ts_texture2D_gradf, and only when it is given derivatives). */
typedef struct {
  int w, h;
  const float *texels;
  int wrap_s, wrap_t, filter;
  int mip_levels, mip_filter;
  int mip_w[TS_MAX_MIP_LEVELS], mip_h[TS_MAX_MIP_LEVELS];
  const float *mip_texels[TS_MAX_MIP_LEVELS];
} ts_tex2d;

/* A single-level texture (no mip chain). */
static inline ts_tex2d ts_tex2d_single(int w, int h, const float *texels, int wrap_s, int wrap_t, int filter) {
  ts_tex2d t;
  __builtin_memset(&t, 0, sizeof t);
  t.w = w;
  t.h = h;
  t.texels = texels;
  t.wrap_s = wrap_s;
  t.wrap_t = wrap_t;
  t.filter = filter;
  t.mip_levels = 1;
  return t;
}

/* Texel (x,y) exactly; outside [0,w)x[0,h) returns (0,0,0,0) (llvmpipe's
 * out-of-bounds texelFetch result; GL itself leaves it undefined). */
ts_vec4f ts_texelFetchf(const ts_tex2d *t, int x, int y);
ts_vec4f ts_texture2Df(const ts_tex2d *t, ts_vec2f uv); /* llvmpipe-exact */
ts_vec4d ts_texture2Dd(const ts_tex2d *t, ts_vec2d uv); /* double reference */

/* texture2D with implicit derivatives as llvmpipe computes them for a fragment shader: grad =
 * (ds/dx, ds/dy, dt/dx, dt/dy) of the coordinate over the pixel's 2x2 quad (lp_bld_quad.c
 * lp_build_packed_ddx_ddy_twocoord: top-right minus top-left, bottom-left minus top-left, one
 * value for the whole quad). grad NULL or a single level: ts_texture2Df. */
ts_vec4f ts_texture2D_gradf(const ts_tex2d *t, ts_vec2f uv, const ts_vec4f *grad);
/* The level selection of ts_texture2D_gradf (lp_bld_sample.c lp_build_rho, lp_build_lod_selector,
 * lp_build_linear_mip_levels / lp_build_nearest_mip_level; Mesa's defaults: no rho
 * approximation, no brilinear, LOD per quad): levels l0, l1 and the weight of l1. *lod gets the
 * level of detail before clamping (a NEAREST mip filter: its integer level). */
ts_vec4d ts_texture2D_gradd(const ts_tex2d *t, ts_vec2d uv, const ts_vec4f *grad); /* double reference */
void ts_mip_select(const ts_tex2d *t, ts_vec4f grad, int *l0, int *l1, float *weight, float *lod);
/* Its second half, lp_build_lod_selector from rho^2 (level 0's texel units) on. */
void ts_mip_select_rho2(const ts_tex2d *t, float rho2, int *l0, int *l1, float *weight, float *lod);
/* textureGrad / texture2DGradEXT (explicit derivatives) as llvmpipe samples them in a fragment
 * shader: dpdx_dpdy = (dPdx.s, dPdx.t, dPdy.s, dPdy.t), the level of detail per pixel from them
 * (not per quad). ts_sampler_grad.c (the Mesa functions; the spec's bound: ts_texture2DGradiv). */
ts_vec4f ts_texture2DGradf(const ts_tex2d *t, ts_vec2f uv, ts_vec4f dpdx_dpdy);
ts_vec4d ts_texture2DGradd(const ts_tex2d *t, ts_vec2d uv, ts_vec4f dpdx_dpdy); /* double reference */
/* The double references' last step: levels l0 and l1 filtered in double, blended with weight w
 * of l1 (w <= 0 or NaN: l0 alone). */
ts_vec4d ts_mip_blendd(const ts_tex2d *t, ts_vec2d uv, int l0, int l1, float w);
/* One level of t as a single-level texture (level 0: t itself without its chain). */
ts_tex2d ts_mip_level(const ts_tex2d *t, int level);
/* lp_build_fast_log2: (exponent - 1) + mantissa in [1, 2) (piecewise linear, exact at powers of 2). */
float ts_fast_log2f(float x);

/* Faces in GL order +X,-X,+Y,-Y,+Z,-Z, each size*size RGBA32F, row 0 = t=0. */
typedef struct {
  int size;
  const float *faces[6];
  int filter;
} ts_texcube;

ts_vec4f ts_textureCubef(const ts_texcube *c, ts_vec3f dir);
ts_vec4d ts_textureCubed(const ts_texcube *c, ts_vec3d dir);

#ifdef __cplusplus
}
#endif
#endif /* TS_SAMPLER_H */

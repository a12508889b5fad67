/* tiershade math: 3D (volume) texture sampling mirror of Mesa 22.3.6 llvmpipe for RGBA32F
 * textures, single level (no mipmaps, no LOD): texelFetch, NEAREST and LINEAR
 * (trilinear) with REPEAT or CLAMP_TO_EDGE on each axis.  "f" = bit-exact
 * float32 mirror, "d" = double reference with the same addressing rules.
 * The per-axis addressing is the 2D rule of ts_sampler.c applied to a third
 * axis; the lerp order (x, then y, then z) and the fused lerp were measured
 * with tests/unit/test_sampler3d.cpp (docs/c_math_layer.md, "3D sampler").
 * Uses ts_math (call ts_math_init() first).
 */
#ifndef TS_SAMPLER3D_H
#define TS_SAMPLER3D_H

#include "math/ts_math.h"
#include "math/ts_sampler.h" /* TS_WRAP_*, TS_FILTER_* */

#ifdef __cplusplus
extern "C" {
#endif

/* RGBA32F, 4 floats per texel; x fastest, then y (rows), then z (slices):
 * the glTexImage3D order. Texel (x,y,z) at texels[4*((z*h + y)*w + x)]. */
typedef struct {
  int w, h, d;
  const float *texels;
  int wrap_s, wrap_t, wrap_r, filter;
} ts_tex3d;

/* Texel (x,y,z) exactly; outside the volume returns (0,0,0,0) (llvmpipe's
 * out-of-bounds texelFetch result; GL itself leaves it undefined). */
ts_vec4f ts_texelFetch3Df(const ts_tex3d *t, int x, int y, int z);
ts_vec4f ts_texture3Df(const ts_tex3d *t, ts_vec3f uvw); /* llvmpipe-exact */
ts_vec4d ts_texture3Dd(const ts_tex3d *t, ts_vec3d uvw); /* double reference */

#ifdef __cplusplus
}
#endif
#endif /* TS_SAMPLER3D_H */

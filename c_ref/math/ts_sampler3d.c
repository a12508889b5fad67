/* tiershade math: RGBA32F 3D texture sampling, mirror of llvmpipe (Mesa 22.3.6) SoA float path.
 * Addressing: gallivm lp_bld_sample_soa.c (lp_build_sample_wrap_nearest,
 * lp_build_sample_wrap_linear), applied per axis exactly as for 2D textures
 * (/work/shared/docs/llvmpipe_bitexact.md "Texture sampling"; c_ref/math/ts_sampler.c).
 * Trilinear = lerp(wz, bilinear(slice z0), bilinear(slice z1)), bilinear =
 * lerp(wy, lerp(wx, t000, t100), lerp(wx, t010, t110)), lerp = mad(w, b - a, a)
 * fused iff the host has FMA (gallivm lp_build_lerp_3d; measured bit for bit by
 * tests/unit/test_sampler3d.cpp on OSMesa GL 3.3 and EGL GLES 3.0).
 * The per-axis rules are ts_sampler.c's (c_ref/math/ts_sampler_wrap.h).
 */
#include "math/ts_sampler3d.h"
#include "math/ts_sampler_wrap.h"

#include <math.h>
#include <stddef.h>

/* ts_texture3Df / ts_texture3Dd: the same steps in precision S (R its real type, V4 the texel
 * type): NEAREST, or LINEAR as lerp(wz, bilinear(slice z0), bilinear(slice z1)). */
#define TS_TEXTURE3D(S, R, V4)                                                                                  \
  V4 ts_texture3D##S(const ts_tex3d *t, ts_vec3##S p) {                                                         \
    int x0, x1, y0, y1, z0, z1;                                                                                 \
    R wx, wy, wz;                                                                                               \
    V4 s0, s1;                                                                                                  \
    if (t->filter == TS_FILTER_NEAREST)                                                                         \
      return fetch_##S(t, ts_wrap_nearest_##S(p.x, t->w, t->wrap_s), ts_wrap_nearest_##S(p.y, t->h, t->wrap_t), \
                       ts_wrap_nearest_##S(p.z, t->d, t->wrap_r));                                              \
    ts_wrap_linear_##S(p.x, t->w, t->wrap_s, &x0, &x1, &wx);                                                    \
    ts_wrap_linear_##S(p.y, t->h, t->wrap_t, &y0, &y1, &wy);                                                    \
    ts_wrap_linear_##S(p.z, t->d, t->wrap_r, &z0, &z1, &wz);                                                    \
    s0 = ts_lerp4_##S(wy, ts_lerp4_##S(wx, fetch_##S(t, x0, y0, z0), fetch_##S(t, x1, y0, z0)),                 \
                      ts_lerp4_##S(wx, fetch_##S(t, x0, y1, z0), fetch_##S(t, x1, y1, z0)));                    \
    s1 = ts_lerp4_##S(wy, ts_lerp4_##S(wx, fetch_##S(t, x0, y0, z1), fetch_##S(t, x1, y0, z1)),                 \
                      ts_lerp4_##S(wx, fetch_##S(t, x0, y1, z1), fetch_##S(t, x1, y1, z1)));                    \
    return ts_lerp4_##S(wz, s0, s1);                                                                            \
  }

static ts_vec4f texel(const ts_tex3d *t, int x, int y, int z) {
  const float *p = t->texels + (((size_t)z * (size_t)t->h + (size_t)y) * (size_t)t->w + (size_t)x) * 4u;
  return ts_v4f(p[0], p[1], p[2], p[3]);
}

/* Never reads outside the volume: llvmpipe produces in-range indices for
 * finite coordinates; NaN/inf coordinates are clamped here. */
static ts_vec4f fetch_f(const ts_tex3d *t, int x, int y, int z) {
  return texel(t, ts_clampi(x, 0, t->w - 1), ts_clampi(y, 0, t->h - 1), ts_clampi(z, 0, t->d - 1));
}

ts_vec4f ts_texelFetch3Df(const ts_tex3d *t, int x, int y, int z) {
  if (x < 0 || y < 0 || z < 0 || x >= t->w || y >= t->h || z >= t->d) return ts_v4f(0.0f, 0.0f, 0.0f, 0.0f);
  return texel(t, x, y, z);
}

/* ---------------------------------------------------------------------------- */
/* float32, llvmpipe-exact                                                       */
/* ---------------------------------------------------------------------------- */

TS_TEXTURE3D(f, float, ts_vec4f)

/* ---------------------------------------------------------------------------- */
/* double reference: same addressing, computed in double                         */
/* ---------------------------------------------------------------------------- */

static ts_vec4d fetch_d(const ts_tex3d *t, int x, int y, int z) {
  ts_vec4f p = fetch_f(t, x, y, z);
  return ts_v4d(p.x, p.y, p.z, p.w);
}

TS_TEXTURE3D(d, double, ts_vec4d)

/* tiershade math: texture sampling mirror of Mesa 22.3.6 llvmpipe for RGBA32F textures, single
 * level (no mipmaps, no LOD): texelFetch, 2D NEAREST/LINEAR with REPEAT or
 * CLAMP_TO_EDGE, cube maps (CLAMP_TO_EDGE, seamless OFF).  "f" = bit-exact
 * float32 mirror, "d" = double reference with the same addressing rules.
 * Uses ts_math (call ts_math_init() first).  Details: docs/c_math_layer.md.
 */
#ifndef TS_SAMPLER_H
#define TS_SAMPLER_H

#include "math/ts_math.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { TS_WRAP_REPEAT = 0, TS_WRAP_CLAMP = 1 }; /* CLAMP = GL_CLAMP_TO_EDGE */
enum { TS_FILTER_NEAREST = 0, TS_FILTER_LINEAR = 1 }; /* min = mag filter         */

/* RGBA32F, 4 floats per texel, row-major; row 0 = GL's t=0 row (glTexImage2D order). */
typedef struct {
  int w, h;
  const float *texels;
  int wrap_s, wrap_t, filter;
} ts_tex2d;

/* Texel (x,y) exactly; outside [0,w)x[0,h) returns (0,0,0,0) (llvmpipe's
 * out-of-bounds texelFetch result; GL itself leaves it undefined). */
ts_vec4f ts_texelFetchf(const ts_tex2d *t, int x, int y);
ts_vec4f ts_texture2Df(const ts_tex2d *t, ts_vec2f uv); /* llvmpipe-exact */
ts_vec4d ts_texture2Dd(const ts_tex2d *t, ts_vec2d uv); /* double reference */

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

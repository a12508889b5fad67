/* tiershade offline: a small direct-light baker for radiosity-normal-mapped
 * lightmaps (fact sheet section 1, "How vrad bakes the per-basis values"):
 * the world-space bump basis of a surface (GetBumpNormals) and the four values of
 * one lightmap texel, flat and along the three basis vectors, from a set of lights.
 * The per-texel arithmetic of glue/bake/world_bake.cpp, which passes each sample
 * the lights its shadow rays reach (no bounce or sky yet). Double precision (an
 * offline tool, not a shader twin). */
#ifndef TS_RNM_BAKE_H
#define TS_RNM_BAKE_H
#include <stddef.h>

#include "math/ts_math.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  int directional; /* 1: a sun shining along dir; 0: a point light at pos */
  ts_vec3d pos; /* point light position */
  ts_vec3d dir; /* directional light: the direction the light travels (unit) */
  ts_vec3d color; /* linear intensity */
  double atten[3]; /* point light: falloff 1 / (a0 + a1 d + a2 d^2) */
  int spot; /* 1: the point light is a spot shining along spot_dir */
  ts_vec3d spot_dir; /* spot: the direction the light travels (non-zero) */
  double cos_inner, cos_outer, exponent; /* spot cone, cos_inner > cos_outer; exponent >= 0 */
} rnm_light;

/* The tangent-space basis b0, b1, b2 (fact sheet section 1), k = 0..2. */
ts_vec3d rnm_basis(int k);

/* GetBumpNormals: axis1 = normalize(N x S), axis0 = normalize(axis1 x N) with N the
 * smooth (phong) normal; axis1 negated when dot(face normal, S x T) < 0 (left-handed);
 * bump_k = b_k.x axis0 + b_k.y axis1 + b_k.z N. Returns 0, or -1 with a message in err
 * when a vector is zero, not finite, or S is parallel to N. */
int rnm_bump_basis(ts_vec3d s_vec, ts_vec3d t_vec, ts_vec3d face_normal, ts_vec3d phong_normal, ts_vec3d bump[3],
                   char *err, size_t errlen);

/* The four lightmap values of a texel at pos: out[0] flat (face normal), out[1..3]
 * along bump[0..2]. Per light: contribution = color * falloff * max(0, n . L) for each
 * normal (cosine-weighted, negatives clamped), and a light behind the face
 * (face normal . L <= 0) feeds none of the three bumped values (GatherSampleLightSSE).
 * A spot multiplies its falloff as vrad does (fact sheet, "vrad old-style attenuation":
 * GatherSampleStandardLightSSE): by dot2 = cos(angle between the spot axis and the
 * light-to-texel direction), by 0 outside the outer cone (dot2 <= cos_outer), and between
 * the cones by ((dot2 - cos_outer) / (cos_inner - cos_outer))^exponent.
 * Returns 0, or -1 with a message when an input is not finite, a falloff is <= 0 or a
 * spot's axis or cone is degenerate. */
int rnm_bake_texel(ts_vec3d pos, ts_vec3d face_normal, const ts_vec3d bump[3], const rnm_light *lights, int num_lights,
                   ts_vec3d out[4], char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

/* tiershade offline: the radiosity-normal-mapping baker (see rnm_bake.h; fact sheet
 * section 1: GetBumpNormals in bumpvects.cpp, GatherSampleStandardLightSSE and
 * GatherSampleLightSSE in lightmap.cpp). */
#include "offline/rnm_bake.h"

#include <math.h>
#include <stdio.h>

static ts_vec3d cross3(ts_vec3d a, ts_vec3d b) {
  return ts_v3d(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double dot3(ts_vec3d a, ts_vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static int finite3(ts_vec3d v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }
static ts_vec3d scale3(ts_vec3d v, double s) { return ts_v3d(v.x * s, v.y * s, v.z * s); }
static ts_vec3d add3(ts_vec3d a, ts_vec3d b) { return ts_v3d(a.x + b.x, a.y + b.y, a.z + b.z); }

/* Unit vector, or 0 when v is zero or not finite. */
static int unit3(ts_vec3d v, ts_vec3d *out) {
  const double l = sqrt(dot3(v, v));
  if (!finite3(v) || !(l > 0) || !isfinite(l)) return 0;
  *out = scale3(v, 1.0 / l);
  return 1;
}

ts_vec3d rnm_basis(int k) {
  const double s23 = sqrt(2.0 / 3.0), oo6 = 1.0 / sqrt(6.0), oo2 = 1.0 / sqrt(2.0), oo3 = 1.0 / sqrt(3.0);
  if (k == 0) return ts_v3d(s23, 0.0, oo3);
  if (k == 1) return ts_v3d(-oo6, oo2, oo3);
  return ts_v3d(-oo6, -oo2, oo3);
}

int rnm_bump_basis(ts_vec3d s_vec, ts_vec3d t_vec, ts_vec3d face_normal, ts_vec3d phong_normal, ts_vec3d bump[3],
                   char *err, size_t errlen) {
  ts_vec3d n, axis0, axis1, fn;
  if (!finite3(s_vec) || !finite3(t_vec) || !unit3(face_normal, &fn) || !unit3(phong_normal, &n)) {
    snprintf(err, errlen, "rnm_bump_basis: the S and T vectors and both normals must be finite, the normals non-zero");
    return -1;
  }
  if (!unit3(cross3(n, s_vec), &axis1)) {
    snprintf(err, errlen, "rnm_bump_basis: the S texture vector is zero or parallel to the normal");
    return -1;
  }
  if (!unit3(cross3(axis1, n), &axis0)) {
    snprintf(err, errlen, "rnm_bump_basis: degenerate tangent frame");
    return -1;
  }
  if (dot3(fn, cross3(s_vec, t_vec)) < 0.0) axis1 = scale3(axis1, -1.0);
  for (int k = 0; k < 3; ++k) {
    const ts_vec3d b = rnm_basis(k);
    bump[k] = add3(add3(scale3(axis0, b.x), scale3(axis1, b.y)), scale3(n, b.z));
  }
  return 0;
}

int rnm_bake_texel(ts_vec3d pos, ts_vec3d face_normal, const ts_vec3d bump[3], const rnm_light *lights, int num_lights,
                   ts_vec3d out[4], char *err, size_t errlen) {
  ts_vec3d n;
  for (int k = 0; k < 4; ++k) out[k] = ts_v3d(0, 0, 0);
  if (num_lights < 0 || (num_lights > 0 && !lights)) {
    snprintf(err, errlen, "rnm_bake_texel: %d lights", num_lights);
    return -1;
  }
  if (!finite3(pos) || !unit3(face_normal, &n) || !finite3(bump[0]) || !finite3(bump[1]) || !finite3(bump[2])) {
    snprintf(err, errlen, "rnm_bake_texel: position, face normal and bump vectors must be finite, the normal non-zero");
    return -1;
  }
  for (int i = 0; i < num_lights; ++i) {
    const rnm_light *l = &lights[i];
    ts_vec3d L;
    double falloff = 1.0;
    if (!finite3(l->color) || (l->directional ? !finite3(l->dir) : !finite3(l->pos))) {
      snprintf(err, errlen, "rnm_bake_texel: light %d has a non-finite colour, position or direction", i);
      return -1;
    }
    if (l->directional) {
      if (!unit3(scale3(l->dir, -1.0), &L)) {
        snprintf(err, errlen, "rnm_bake_texel: light %d (directional) has a zero direction", i);
        return -1;
      }
    } else {
      const ts_vec3d d = ts_v3d(l->pos.x - pos.x, l->pos.y - pos.y, l->pos.z - pos.z);
      const double dist = sqrt(dot3(d, d));
      const double denom = l->atten[0] + l->atten[1] * dist + l->atten[2] * dist * dist;
      if (!(denom > 0) || !isfinite(denom)) {
        snprintf(err, errlen, "rnm_bake_texel: light %d: falloff denominator %g at distance %g is not positive", i,
                 denom, dist);
        return -1;
      }
      if (!unit3(d, &L)) continue; /* the light sits on the texel: no direction, no light */
      falloff = 1.0 / denom;
      if (l->spot) { /* vrad's spot cone (rnm_bake.h) */
        ts_vec3d axis;
        if (!unit3(l->spot_dir, &axis) || !(l->cos_inner > l->cos_outer) || !(l->cos_inner <= 1.0) ||
            !(l->cos_outer >= -1.0) || !(l->exponent >= 0.0) || !isfinite(l->exponent)) {
          snprintf(err, errlen,
                   "rnm_bake_texel: light %d (spot) needs a non-zero axis, cos_inner > cos_outer "
                   "within [-1, 1] and a finite exponent >= 0",
                   i);
          return -1;
        }
        const double dot2 = -dot3(L, axis);
        if (dot2 <= l->cos_outer) continue; /* outside the cone */
        const double mult =
            dot2 >= l->cos_inner ? 1.0 : pow((dot2 - l->cos_outer) / (l->cos_inner - l->cos_outer), l->exponent);
        falloff *= dot2 * mult;
      }
    }
    const double dot0 = fmax(0.0, dot3(n, L));
    if (dot0 == 0.0) continue; /* behind the face: feeds neither the flat nor the bumped maps */
    out[0] = add3(out[0], scale3(l->color, falloff * dot0));
    for (int k = 0; k < 3; ++k) out[k + 1] = add3(out[k + 1], scale3(l->color, falloff * fmax(0.0, dot3(bump[k], L))));
  }
  return 0;
}

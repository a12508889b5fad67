/* tiershade offline: light packing, incident light at a point, and folding of the lights beyond a
 * tier's limit into the ambient cube (see light_folding.h; rule and derivation:
 * docs/light_folding.md). CPU set-up code in double, not a bit-exact twin.
 */
#include "offline/light_folding.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#include "math/ts_math.h"

/* The attenuation formula once: common_lights.h's light_attenuation, instantiated
 * here in double (light_attenuation_d). */
#include "math/ts_generic.h"
#include "math/ts_generic_double.h"
#include "common/common_math.h"
#include "common/common_lights.h"

/* Fold constants (docs/light_folding.md, "Derivation"): the ambient cube
 * integrates to (2 pi / 3) * sum(faces) over the sphere of normals; a Lambert
 * light to pi * I, a half-Lambert light to (4 pi / 3) * I. */
#define TS_FOLD_K_LAMBERT 1.5
#define TS_FOLD_K_HALF_LAMBERT 2.0

/* Rec. 709 / sRGB luminance weights (ITU-R BT.709-6, item 3.2). */
#define TS_LUMA_R 0.2126
#define TS_LUMA_G 0.7152
#define TS_LUMA_B 0.0722

static void set_err(char *err, size_t errlen, const char *fmt, ...) {
  va_list ap;
  if (!err || errlen == 0) return;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
}

static const char *type_name(ts_light_type t) {
  switch (t) {
    case TS_LIGHT_POINT:
      return "point";
    case TS_LIGHT_SPOT:
      return "spot";
    case TS_LIGHT_DIRECTIONAL:
      return "directional";
  }
  return "unknown";
}

static int check_finite3(const float v[3], const char *field, const char *tn, char *err, size_t errlen) {
  for (int i = 0; i < 3; ++i) {
    if (!isfinite(v[i])) {
      set_err(err, errlen, "ts_light_pack: %s light: %s[%d] = %g is not finite", tn, field, i, (double)v[i]);
      return 0;
    }
  }
  return 1;
}

/* Returns 1 if valid, else 0 with a message. */
static int validate(const ts_light *l, char *err, size_t errlen) {
  if (!l) {
    set_err(err, errlen, "ts_light_pack: light is NULL");
    return 0;
  }
  if (l->type != TS_LIGHT_POINT && l->type != TS_LIGHT_SPOT && l->type != TS_LIGHT_DIRECTIONAL) {
    set_err(err, errlen, "ts_light_pack: unknown light type %d", (int)l->type);
    return 0;
  }
  const char *tn = type_name(l->type);
  if (!check_finite3(l->color, "color", tn, err, errlen) || !check_finite3(l->dir, "dir", tn, err, errlen) ||
      !check_finite3(l->pos, "pos", tn, err, errlen) || !check_finite3(l->atten, "atten", tn, err, errlen))
    return 0;
  const float spot[3] = {l->spot_exponent, l->cos_inner, l->cos_outer};
  static const char *const spot_names[3] = {"spot_exponent", "cos_inner", "cos_outer"};
  for (int i = 0; i < 3; ++i) {
    if (!isfinite(spot[i])) {
      set_err(err, errlen, "ts_light_pack: %s light: %s = %g is not finite", tn, spot_names[i], (double)spot[i]);
      return 0;
    }
  }
  if (l->type != TS_LIGHT_DIRECTIONAL) {
    /* Fact sheet section 4: distance attenuation 1/(c + l d + q d^2). */
    for (int i = 0; i < 3; ++i) {
      if (l->atten[i] < 0.0f) {
        set_err(err, errlen, "ts_light_pack: %s light: atten[%d] = %g is negative", tn, i, (double)l->atten[i]);
        return 0;
      }
    }
    if ((double)l->atten[0] + (double)l->atten[1] + (double)l->atten[2] == 0.0) {
      set_err(err, errlen, "ts_light_pack: %s light: atten = (0, 0, 0): c + l + q must be > 0", tn);
      return 0;
    }
  }
  if (l->type != TS_LIGHT_POINT) {
    double d2 = (double)l->dir[0] * l->dir[0] + (double)l->dir[1] * l->dir[1] + (double)l->dir[2] * l->dir[2];
    if (!(d2 > 0.0)) {
      set_err(err, errlen, "ts_light_pack: %s light: dir has zero length", tn);
      return 0;
    }
  }
  if (l->type == TS_LIGHT_SPOT) {
    if (!(l->cos_inner > l->cos_outer)) {
      set_err(err, errlen, "ts_light_pack: spot light: cos_inner = %g must be > cos_outer = %g", (double)l->cos_inner,
              (double)l->cos_outer);
      return 0;
    }
    double w = 1.0 / ((double)l->cos_inner - (double)l->cos_outer);
    if (!(w <= (double)FLT_MAX)) {
      set_err(err, errlen, "ts_light_pack: spot light: cone too narrow, 1/(cos_inner - cos_outer) = %g overflows float",
              w);
      return 0;
    }
    if (l->spot_exponent < 0.0f) {
      set_err(err, errlen, "ts_light_pack: spot light: spot_exponent = %g is negative", (double)l->spot_exponent);
      return 0;
    }
  }
  return 1;
}

/* Packing of a validated light; layout of shaders/common_lights.glsl (fact sheet
 * section 4, VertexAttenInternal: color.w = 1 directional, dir.w = 1 spot,
 * spot = (exponent, -, cos outer, 1/(cos inner - cos outer))). */
static void pack_valid(const ts_light *l, float out[5][4]) {
  const int directional = l->type == TS_LIGHT_DIRECTIONAL;
  const int spot = l->type == TS_LIGHT_SPOT;
  for (int s = 0; s < 5; ++s)
    for (int c = 0; c < 4; ++c) out[s][c] = 0.0f;

  for (int c = 0; c < 3; ++c) out[0][c] = l->color[c];
  out[0][3] = directional ? 1.0f : 0.0f;

  if (l->type != TS_LIGHT_POINT) {
    double d[3] = {l->dir[0], l->dir[1], l->dir[2]};
    double len = ts_sqrtd(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int c = 0; c < 3; ++c) out[1][c] = (float)(d[c] / len);
  }
  out[1][3] = spot ? 1.0f : 0.0f;

  if (!directional)
    for (int c = 0; c < 3; ++c) out[2][c] = l->pos[c];

  if (spot) {
    out[3][0] = l->spot_exponent;
    out[3][2] = l->cos_outer;
    out[3][3] = (float)(1.0 / ((double)l->cos_inner - (double)l->cos_outer));
  }

  if (directional) {
    out[4][0] = 1.0f; /* attenuation unused by the shader; (1, 0, 0) keeps it 1 */
  } else {
    for (int c = 0; c < 3; ++c) out[4][c] = l->atten[c];
  }
}

int ts_light_pack(const ts_light *l, float out[5][4], char *err, size_t errlen) {
  if (!out) {
    set_err(err, errlen, "ts_light_pack: out is NULL");
    return 0;
  }
  if (!validate(l, err, errlen)) return 0;
  pack_valid(l, out);
  set_err(err, errlen, "%s", "");
  return 1;
}

double ts_packed_light_attenuation(const float packed[5][4], const double p[3], double to_light[3]) {
  ts_vec4d l[5];
  for (int k = 0; k < 5; ++k) l[k] = ts_v4d(packed[k][0], packed[k][1], packed[k][2], packed[k][3]);
  ts_vec3d L;
  const double att = light_attenuation_d(l, ts_v3d(p[0], p[1], p[2]), &L);
  if (to_light) {
    to_light[0] = L.x;
    to_light[1] = L.y;
    to_light[2] = L.z;
  }
  return att;
}

void ts_light_incident(const ts_light *l, const float p[3], double rgb[3], double to_light[3]) {
  float pk[5][4];
  for (int c = 0; c < 3; ++c) rgb[c] = to_light[c] = 0.0;
  if (!p || !validate(l, NULL, 0)) return;
  pack_valid(l, pk);
  const double pd[3] = {p[0], p[1], p[2]};
  const double att = ts_packed_light_attenuation(pk, pd, to_light);
  for (int c = 0; c < 3; ++c) rgb[c] = (double)pk[0][c] * att;
}

static double luminance(const double rgb[3]) { return TS_LUMA_R * rgb[0] + TS_LUMA_G * rgb[1] + TS_LUMA_B * rgb[2]; }

static void add_face(float cube[6][3], int face, const double add[3]) {
  for (int c = 0; c < 3; ++c) {
    double v = (double)cube[face][c] + add[c];
    v = v > (double)FLT_MAX ? (double)FLT_MAX : (v < -(double)FLT_MAX ? -(double)FLT_MAX : v);
    cube[face][c] = (float)v;
  }
}

/* Adds one light (incident rgb I, direction L) to the cube: docs/light_folding.md,
 * "Rule". */
static void fold_one(const double I[3], const double L[3], int half_lambert, float cube[6][3]) {
  double a2 = L[0] * L[0] + L[1] * L[1] + L[2] * L[2];
  double add[3];
  if (a2 >= 1.0 - 1.0e-6) {
    /* The normal case: unit L (renormalised in double); weights L_j^2 sum to 1. */
    double k = half_lambert ? TS_FOLD_K_HALF_LAMBERT : TS_FOLD_K_LAMBERT;
    double inv = 1.0 / a2;
    for (int j = 0; j < 3; ++j) {
      double w = k * L[j] * L[j] * inv;
      for (int c = 0; c < 3; ++c) add[c] = w * I[c];
      add_face(cube, 2 * j + (L[j] >= 0.0 ? 0 : 1), add);
    }
    return;
  }
  /* Degenerate: the light sits on the centre and the shader's L has length
   * a < 1. Lambert integrates to pi a I -> faces get (3/2) I a Lhat_j^2;
   * half-Lambert ((a t + 1)/2)^2 integrates to pi (1 + a^2/3) I -> faces get
   * 2 I L_j^2 plus (1 - a^2) I / 4 on all six. */
  double a = ts_sqrtd(a2);
  for (int j = 0; j < 3; ++j) {
    double w =
        half_lambert ? TS_FOLD_K_HALF_LAMBERT * L[j] * L[j] : (a > 0.0 ? TS_FOLD_K_LAMBERT * L[j] * L[j] / a : 0.0);
    for (int c = 0; c < 3; ++c) add[c] = w * I[c];
    add_face(cube, 2 * j + (L[j] >= 0.0 ? 0 : 1), add);
  }
  if (half_lambert) {
    for (int c = 0; c < 3; ++c) add[c] = 0.25 * (1.0 - a2) * I[c];
    for (int f = 0; f < 6; ++f) add_face(cube, f, add);
  }
}

/* Up to this many lights, each light's luminance is evaluated once into a stack table
 * (ts_light_incident n times, then n^2 comparisons); more lights re-evaluate them per
 * comparison as the ranking runs (n^2 evaluations: still no allocation). The same bits
 * either way: the ranking compares the same doubles. */
#define TS_FOLD_TABLE 256

int ts_fold_lights(const ts_light *lights, int n, int max_local, const float center[3], int half_lambert,
                   float cube[6][3], int *kept) {
  if (!lights || n <= 0 || !center) return 0;
  if (max_local < 0) max_local = 0;
  double table[TS_FOLD_TABLE]; /* luminance at center */
  unsigned char valid[TS_FOLD_TABLE];
  const int tabled = n <= TS_FOLD_TABLE;
  for (int i = 0; tabled && i < n; ++i) {
    double I[3], L[3];
    table[i] = 0.0;
    valid[i] = (unsigned char)(validate(&lights[i], NULL, 0) != 0);
    if (!valid[i]) continue;
    ts_light_incident(&lights[i], center, I, L);
    table[i] = luminance(I);
  }
  int nkept = 0;
  for (int i = 0; i < n; ++i) {
    if (tabled ? !valid[i] : !validate(&lights[i], NULL, 0)) continue; /* invalid: neither kept nor folded */
    double Ii[3], Li[3];
    ts_light_incident(&lights[i], center, Ii, Li);
    double lum_i = luminance(Ii);
    /* rank = number of valid lights ahead of i (brighter, or as bright with a lower index) */
    int rank = 0;
    for (int j = 0; j < n && rank < max_local; ++j) {
      if (j == i) continue;
      double lum_j;
      if (tabled) {
        if (!valid[j]) continue;
        lum_j = table[j];
      } else {
        if (!validate(&lights[j], NULL, 0)) continue;
        double Ij[3], Lj[3];
        ts_light_incident(&lights[j], center, Ij, Lj);
        lum_j = luminance(Ij);
      }
      if (lum_j > lum_i || (lum_j == lum_i && j < i)) ++rank;
    }
    if (rank < max_local) {
      if (kept) kept[nkept] = i;
      ++nkept;
    } else if (cube) {
      fold_one(Ii, Li, half_lambert, cube);
    }
  }
  return nkept;
}

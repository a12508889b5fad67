/* tiershade math: interval arithmetic of the GLSL ES 3.00 highp precision rules (ts_interval.h).
 * Exact results are computed in double (a float32 product is exact in double, a sum is exact
 * with its TwoSum error term), then rounded outward to float32. ULP allowances follow the CTS
 * (VK-GL-CTS glsBuiltinPrecisionTests.cpp, ../shared/docs/anchors.md): n ULP of the exact
 * result, ULP = 2^(exponent - 23), at least 2^-149. libm's double exp2/log2/sqrt are within one
 * double ULP, covered by adding 1e-6 to every ULP count (a double ULP is 2^-29 float ULP). */
#include "math/ts_interval.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

#include "math/ts_bits.h"

#define TS_IV_SLACK 1e-6 /* ULPs added for the double evaluation (see banner) */

/* ---- the precision whose rules apply (ts_iv_set_mediump) ---- */

/* highp: float32 (23 fraction bits, normals from 2^-126). mediump: the CTS's format for it,
 * FloatFormat(-13, 13, 9 bits) (VK-GL-CTS glsBuiltinPrecisionTests.cpp; ../shared/docs/anchors.md):
 * 9 fraction bits, normals from 2^-13, the largest finite value (2 - 2^-9) 2^13; past it a result
 * admits everything up to Inf. Every result is rounded outward to the format's grid, which holds
 * float32 and fp16 results alike (an implementation may compute mediump at any higher precision). */
static int g_mediump = 0;
static int fmt_bits(void) { return g_mediump ? 9 : 23; }
static double fmt_min(void) { return g_mediump ? 0x1p-13 : (double)FLT_MIN; }
static double fmt_max(void) { return g_mediump ? (2.0 - 0x1p-9) * 0x1p13 : (double)FLT_MAX; }
void ts_iv_set_mediump(int on) { g_mediump = on != 0; }
int ts_iv_mediump(void) { return g_mediump; }

/* v rounded down to the mediump grid (9 fraction bits), v finite and normal in the format */
static double grid_dn(double v) {
  int e;
  frexp(v, &e); /* |v| = m 2^e, m in [0.5, 1): grid step 2^(e - 1 - bits) */
  const double q = ldexp(1.0, e - 1 - fmt_bits());
  return floor(v / q) * q;
}

/* ---- outward rounding to float32 with the FTZ rule ---- */

/* the largest float32 <= v (v exact); a result in the denormal range may also be flushed to 0 */
static float dn(double v) {
  if (g_mediump) {
    if (v >= 0 && v < fmt_min()) return 0.0f;
    if (v < 0 && v > -fmt_min()) return (float)-fmt_min();
    if (v > fmt_max()) return (float)fmt_max(); /* overflow: the largest value, or anything above */
    if (v < -fmt_max()) return -INFINITY;
    return (float)grid_dn(v); /* exact in float32 */
  }
  if (v >= 0 && v < FLT_MIN) return 0.0f;
  if (v < 0 && v > -FLT_MIN) return -FLT_MIN;
  float f = (float)v;
  if ((double)f > v) f = nextafterf(f, -INFINITY);
  return f;
}
/* the smallest float32 >= v (v exact) */
static float up(double v) {
  if (g_mediump) return -dn(-v);
  if (v <= 0 && v > -FLT_MIN) return 0.0f;
  if (v > 0 && v < FLT_MIN) return FLT_MIN;
  float f = (float)v;
  if ((double)f < v) f = nextafterf(f, INFINITY);
  return f;
}
/* the same for the exact value s + e (|e| at most half a double ULP of s, TwoSum) */
static float dn2(double s, double e) {
  if (g_mediump) return dn(e < 0 ? nextafter(s, -INFINITY) : s); /* the grid is far coarser than double */
  if (e < 0 && (double)(float)s == s) return dn(nextafter(s, -INFINITY));
  return dn(s);
}
static float up2(double s, double e) {
  if (g_mediump) return up(e > 0 ? nextafter(s, INFINITY) : s);
  if (e > 0 && (double)(float)s == s) return up(nextafter(s, INFINITY));
  return up(s);
}
static double two_sum_err(double a, double b, double s) {
  const double bb = s - a;
  return (a - (s - bb)) + (b - bb);
}

/* ULP of an exact value in the format's precision (float32: 2^(e - 23); mediump: 2^(e - 9)) */
static double ulpd(double y) {
  y = fabs(y);
  if (isinf(y)) return INFINITY;
  if (y < fmt_min()) return g_mediump ? ldexp(fmt_min(), -fmt_bits()) : 0x1p-149;
  int e;
  frexp(y, &e); /* y = m 2^e, m in [0.5, 1) */
  return ldexp(1.0, e - 1 - fmt_bits());
}
/* least value admitted, n ULP allowed, for any exact result in [y, next power of two above y]:
 * an exact result just past a power of two has twice the ULP */
static double allow_lo(double y, double n) {
  if (isinf(y)) return y; /* an exact Inf (an overflow of the exact result) stays */
  double a = y - n * ulpd(y);
  if (y > 0 && isfinite(y)) {
    int e;
    frexp(y, &e);
    const double p = ldexp(1.0, e), b = p - n * ulpd(p);
    if (b < a) a = b;
  }
  return a;
}
static double allow_hi(double y, double n) { return -allow_lo(-y, n); }

static int has_num(ts_iv a) { return a.lo <= a.hi; }
static int is_denorm(float f) { return (ts_fbits(f) & 0x7f800000u) == 0 && (ts_fbits(f) & 0x7fffffu) != 0; }

ts_iv ts_ivany(void) {
  ts_iv r = {-INFINITY, INFINITY, 1};
  return r;
}
static ts_iv nan_only(void) {
  ts_iv r = {INFINITY, -INFINITY, 1};
  return r;
}
static ts_iv mk(double lo, double hi) {
  ts_iv r = {dn(lo), up(hi), 0};
  return r;
}

ts_iv ts_ivrange(float lo, float hi) {
  if (isnan(lo) || isnan(hi)) return ts_ivany();
  ts_iv r = {lo, hi, 0};
  /* mediump: a float32 input (a uniform, an attribute, a texel stored to a mediump variable) is
   * converted to the format: either neighbour on its grid, 0 below its normals, any value from the
   * largest finite one up past it */
  if (g_mediump) {
    r.lo = dn(lo);
    r.hi = up(hi);
  }
  /* DAZ: a denormal bound may be read as 0; widen it to the nearest normal outward */
  if (is_denorm(lo)) r.lo = lo < 0 ? -FLT_MIN : 0.0f;
  if (is_denorm(hi)) r.hi = hi > 0 ? FLT_MIN : 0.0f;
  if (r.lo == 0.0f) r.lo = 0.0f; /* -0 -> +0: the bounds compare as numbers */
  if (r.hi == 0.0f) r.hi = 0.0f;
  return r;
}
ts_iv ts_ivpoint(float x) { return isnan(x) ? nan_only() : ts_ivrange(x, x); }

ts_iv ts_ivjoin(ts_iv a, ts_iv b) {
  ts_iv r;
  r.lo = a.lo < b.lo ? a.lo : b.lo;
  r.hi = a.hi > b.hi ? a.hi : b.hi;
  r.nan = a.nan || b.nan;
  return r;
}

int ts_ivcontains(ts_iv a, float x) {
  if (isnan(x)) return a.nan;
  return (double)a.lo <= (double)x && (double)x <= (double)a.hi;
}

/* float32 order as integers: -0 and +0 both map to 0 */
static int64_t ford(float f) {
  const uint32_t u = ts_fbits(f);
  return (u & 0x80000000u) ? -(int64_t)(u & 0x7fffffffu) : (int64_t)u;
}
double ts_ivwidth_ulp(ts_iv a) {
  if (a.nan || !has_num(a) || isinf(a.lo) || isinf(a.hi)) return INFINITY;
  return (double)(ford(a.hi) - ford(a.lo));
}
double ts_ivexcess_ulp(ts_iv a, float x) {
  if (ts_ivcontains(a, x)) return 0;
  if (isnan(x) || !has_num(a)) return INFINITY;
  return (double)x < (double)a.lo ? (double)(ford(a.lo) - ford(x)) : (double)(ford(x) - ford(a.hi));
}
ts_iv ts_ivwiden(ts_iv a, int n) {
  if (!has_num(a)) return a;
  for (int i = 0; i < n; ++i) {
    a.lo = nextafterf(a.lo, -INFINITY);
    a.hi = nextafterf(a.hi, INFINITY);
  }
  ts_iv r = ts_ivrange(a.lo, a.hi);
  r.nan = a.nan;
  return r;
}

/* ---- + - * / : an operand that may be NaN gives any result (ESSL 3.00 4.5.1: NaN support is
 * not required, so nothing is promised of an operation on one) ---- */

ts_iv ts_addiv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan) return ts_ivany();
  const double sl = (double)a.lo + b.lo, sh = (double)a.hi + b.hi;
  if (isnan(sl) || isnan(sh)) return ts_ivany(); /* Inf - Inf */
  ts_iv r = {dn2(sl, two_sum_err(a.lo, b.lo, sl)), up2(sh, two_sum_err(a.hi, b.hi, sh)), 0};
  return r;
}
ts_iv ts_negiv(ts_iv a) {
  ts_iv r = {-a.hi, -a.lo, a.nan};
  if (r.lo == 0.0f) r.lo = 0.0f;
  if (r.hi == 0.0f) r.hi = 0.0f;
  return r;
}
ts_iv ts_subiv(ts_iv a, ts_iv b) { return ts_addiv(a, ts_negiv(b)); }

ts_iv ts_muliv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan) return ts_ivany();
  const double p[4] = {(double)a.lo * b.lo, (double)a.lo * b.hi, (double)a.hi * b.lo, (double)a.hi * b.hi};
  double lo = p[0], hi = p[0];
  for (int i = 0; i < 4; ++i) {
    if (isnan(p[i])) return ts_ivany(); /* 0 * Inf */
    if (p[i] < lo) lo = p[i];
    if (p[i] > hi) hi = p[i];
  }
  return mk(lo, hi); /* float32 products are exact in double */
}

/* 2.5 ULP when every |b| is in [2^-126, 2^127] (the CTS's range); otherwise any result */
ts_iv ts_diviv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan || !(isfinite(a.lo) && isfinite(a.hi))) return ts_ivany();
  /* |b| in [2^minExp, 2^(maxExp - 1)]: float32 [2^-126, 2^127], mediump [2^-13, 2^12] */
  const float bmin = (float)fmt_min(), bmax = g_mediump ? 0x1p12f : 0x1p127f;
  const int pos = b.lo >= bmin && b.hi <= bmax, neg = b.hi <= -bmin && b.lo >= -bmax;
  if (!pos && !neg) return ts_ivany();
  const double q[4] = {(double)a.lo / b.lo, (double)a.lo / b.hi, (double)a.hi / b.lo, (double)a.hi / b.hi};
  double lo = q[0], hi = q[0];
  for (int i = 1; i < 4; ++i) {
    if (q[i] < lo) lo = q[i];
    if (q[i] > hi) hi = q[i];
  }
  return mk(allow_lo(lo, 2.5 + TS_IV_SLACK), allow_hi(hi, 2.5 + TS_IV_SLACK));
}

/* ---- comparisons ---- */
int ts_leiv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan || !has_num(a) || !has_num(b)) return TS_IV_EITHER;
  if (a.hi <= b.lo) return TS_IV_TRUE;
  if (a.lo > b.hi) return TS_IV_FALSE;
  return TS_IV_EITHER;
}
int ts_ltiv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan || !has_num(a) || !has_num(b)) return TS_IV_EITHER;
  if (a.hi < b.lo) return TS_IV_TRUE;
  if (a.lo >= b.hi) return TS_IV_FALSE;
  return TS_IV_EITHER;
}
int ts_geiv(ts_iv a, ts_iv b) { return ts_leiv(b, a); }
int ts_gtiv(ts_iv a, ts_iv b) { return ts_ltiv(b, a); }
ts_iv ts_seliv(int c, ts_iv a, ts_iv b) { return c == TS_IV_TRUE ? a : c == TS_IV_FALSE ? b : ts_ivjoin(a, b); }

/* ---- builtins ---- */

/* exp2: (3 + 2|x|) ULP, with the largest |x| of the interval at both ends */
ts_iv ts_exp2iv(ts_iv x) {
  if (x.nan || !has_num(x)) return ts_ivany();
  /* highp (3 + 2|x|) ULP, mediump (2 + 2|x|) ULP of its own format (anchors.md's table) */
  const double n = (g_mediump ? 2 : 3) + 2 * fmax(fabs((double)x.lo), fabs((double)x.hi)) + TS_IV_SLACK;
  ts_iv r = mk(isinf(n) ? 0.0 : allow_lo(exp2(x.lo), n), isinf(n) ? INFINITY : allow_hi(exp2(x.hi), n));
  if (x.hi == -INFINITY) r.hi = 0.0f; /* exp2(-Inf) = 0 */
  if (r.lo < 0) r.lo = 0.0f; /* n ULP below a tiny result (or the Inf case): never below 0 */
  return r;
}

/* log2: absolute 2^-21 where x may be in [0.5, 2], else 3 ULP; x <= 0 undefined (any) */
ts_iv ts_log2iv(ts_iv x) {
  if (x.nan || !has_num(x) || x.lo <= 0.0f) return ts_ivany();
  const double yl = log2(x.lo), yh = log2(x.hi);
  /* highp 3 ULP, absolute 2^-21 in [0.5, 2]; mediump 2 ULP, absolute 2^-7 there */
  const double nl = (g_mediump ? 2 : 3) + TS_IV_SLACK;
  double el = ulpd(yl) * nl, eh = ulpd(yh) * nl;
  if (x.lo <= 2.0f && x.hi >= 0.5f) {
    const double abs_err = (g_mediump ? 0x1p-7 : 0x1p-21) * (1 + 1e-9);
    if (el < abs_err) el = abs_err;
    if (eh < abs_err) eh = abs_err;
  }
  /* |log2| is largest at an end, so ulpd at the ends bounds it inside; a power-of-two crossing
   * is covered by allow_lo/hi's rule when the error is relative */
  if (isinf(yl)) return ts_ivpoint(INFINITY); /* log2(Inf) = Inf */
  const double lo = fmin(yl - el, allow_lo(yl, nl));
  const double hi = isinf(yh) ? INFINITY : fmax(yh + eh, allow_hi(yh, nl));
  return mk(lo, hi);
}


/* inversesqrt: 2 ULP; x <= 0 undefined */
ts_iv ts_inversesqrtiv(ts_iv x) {
  if (x.nan || !has_num(x) || x.lo <= 0.0f) return ts_ivany();
  const double lo = x.hi == INFINITY ? 0.0 : allow_lo(1.0 / sqrt((double)x.hi), 2 + TS_IV_SLACK);
  return mk(lo, allow_hi(1.0 / sqrt((double)x.lo), 2 + TS_IV_SLACK));
}

/* sqrt: 1 / inversesqrt(x) (ESSL 3.00 8.2, the CTS derives it so); sqrt(0) = 0 by the limit,
 * x < 0 undefined */
ts_iv ts_sqrtiv(ts_iv x) {
  if (x.nan || !has_num(x) || x.lo < 0.0f) return ts_ivany();
  if (x.hi == 0.0f) return ts_ivpoint(0.0f);
  ts_iv pos = x;
  if (pos.lo < (float)fmt_min()) pos.lo = (float)fmt_min(); /* below the format's normals: may be 0 */
  ts_iv r = ts_diviv(ts_ivpoint(1.0f), ts_inversesqrtiv(pos));
  if (!r.nan && x.lo < (float)fmt_min()) r.lo = 0.0f;
  return r;
}

/* min, max: exact; a NaN operand gives any result (ESSL 3.00 does not define it) */
ts_iv ts_miniv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan) return ts_ivany();
  ts_iv r = {fminf(a.lo, b.lo), fminf(a.hi, b.hi), 0};
  return r;
}
ts_iv ts_maxiv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan) return ts_ivany();
  ts_iv r = {fmaxf(a.lo, b.lo), fmaxf(a.hi, b.hi), 0};
  return r;
}


/* dot in any order, each product and sum correctly rounded or fused: the exact sum of the exact
 * products' ranges, widened by 5 ULP of 2 M (M = sum of the largest |product|s): 3 products and 2
 * sums each err by under one ULP of a value below 2 M */
ts_iv ts_dot3iv(ts_vec3iv a, ts_vec3iv b) {
  const ts_iv p[3] = {ts_muliv(a.x, b.x), ts_muliv(a.y, b.y), ts_muliv(a.z, b.z)};
  double lo = 0, hi = 0, m = 0;
  for (int i = 0; i < 3; ++i) {
    if (p[i].nan || !isfinite(p[i].lo) || !isfinite(p[i].hi)) return ts_ivany();
    /* the exact products lie in p[i] (outward rounded); their sums in double are exact to
     * 2^-53 relative, covered by the slack below */
    lo += p[i].lo;
    hi += p[i].hi;
    m += fmax(fabs((double)p[i].lo), fabs((double)p[i].hi));
  }
  const double w = (5 + TS_IV_SLACK) * ulpd(2 * m);
  return mk(lo - w, hi + w);
}

/* ---- texture lookups (see ts_interval.h) ----
 * The precision the CTS allows a 2D lookup (dEQP tcuTexLookupVerifier, LookupPrecision, with the
 * values the GLES 3 2D filtering tests set, es3fTextureFilteringTests.cpp: coordBits 20, uvwBits
 * 7): the unnormalised coordinate u * size to 20 bits relative, the sub-texel weight to within
 * 2^-7; LINEAR = bilinear of the 2x2 texels with weights anywhere in that range, NEAREST = the
 * texels floor(u * size) can reach. A coordinate range over more than two texel cells on an axis
 * falls back to the hull of the texels it can touch. */

#define TS_TEX_COORD_BITS 20
#define TS_TEX_UVW_BITS 7

typedef struct {
  int n;          /* 1 or 2 cells (LINEAR) / texels (NEAREST); 0: every texel (hull) */
  int i[2];       /* first texel of each cell (unwrapped) */
  double w[2][2]; /* weight range of the cell's second texel */
} axis_cells;

static axis_cells axis_of(ts_iv c, int len, int linear) {
  axis_cells a = {0, {0, 0}, {{0, 0}, {0, 0}}};
  if (c.nan || !has_num(c) || !(fabsf(c.lo) <= 0x1p20f && fabsf(c.hi) <= 0x1p20f)) return a;
  const double err_lo = fabs((double)c.lo * len) * ldexp(1.0, -TS_TEX_COORD_BITS);
  const double err_hi = fabs((double)c.hi * len) * ldexp(1.0, -TS_TEX_COORD_BITS);
  const double lo = (double)c.lo * len - err_lo - (linear ? 0.5 : 0), hi = (double)c.hi * len + err_hi - (linear ? 0.5 : 0);
  const double f0 = floor(lo), f1 = floor(hi);
  if (f1 - f0 > 1) return a;
  const double q = ldexp(1.0, -TS_TEX_UVW_BITS);
  a.n = (int)(f1 - f0) + 1;
  a.i[0] = (int)f0;
  a.i[1] = (int)f1;
  if (a.n == 1) {
    a.w[0][0] = fmax(0.0, lo - f0 - q);
    a.w[0][1] = fmin(1.0, hi - f0 + q);
  } else {
    a.w[0][0] = fmax(0.0, lo - f0 - q);
    a.w[0][1] = 1.0;
    a.w[1][0] = 0.0;
    a.w[1][1] = fmin(1.0, hi - f1 + q);
  }
  return a;
}
static int wrap_index(int i, int len, int wrap) {
  if (wrap != TS_WRAP_CLAMP) return ((i % len) + len) % len;
  return i < 0 ? 0 : (i >= len ? len - 1 : i);
}
static const float *texel_at(const ts_tex2d *t, int x, int y) {
  return t->texels + ((size_t)wrap_index(y, t->h, t->wrap_t) * (size_t)t->w + (size_t)wrap_index(x, t->w, t->wrap_s)) * 4u;
}

typedef struct {
  double lo[4], hi[4], mag[4]; /* exact value range and the largest |texel| per channel */
  int bad[4];                  /* a NaN or Inf texel */
} tex_acc;

static void acc_value(tex_acc *a, int c, double v, double mag) {
  if (v < a->lo[c]) a->lo[c] = v;
  if (v > a->hi[c]) a->hi[c] = v;
  if (mag > a->mag[c]) a->mag[c] = mag;
}

ts_vec4iv ts_texture2Div(const ts_tex2d *t, ts_vec2iv uv) {
  const int linear = t->filter == TS_FILTER_LINEAR;
  const axis_cells ax = axis_of(uv.x, t->w, linear), ay = axis_of(uv.y, t->h, linear);
  tex_acc acc;
  for (int c = 0; c < 4; ++c) acc.lo[c] = INFINITY, acc.hi[c] = -INFINITY, acc.mag[c] = 0, acc.bad[c] = 0;
  if (ax.n == 0 || ay.n == 0) { /* the hull of every texel the coordinate can reach */
    for (int y = 0; y < t->h; ++y)
      for (int x = 0; x < t->w; ++x) {
        const float *p = t->texels + ((size_t)y * (size_t)t->w + (size_t)x) * 4u;
        for (int c = 0; c < 4; ++c) {
          if (!isfinite(p[c])) acc.bad[c] = 1;
          else acc_value(&acc, c, p[c], fabs((double)p[c]));
        }
      }
  } else {
    for (int cy = 0; cy < ay.n; ++cy)
      for (int cx = 0; cx < ax.n; ++cx) {
        const int x0 = ax.i[cx], y0 = ay.i[cy];
        const float *p00 = texel_at(t, x0, y0), *p10 = texel_at(t, x0 + linear, y0);
        const float *p01 = texel_at(t, x0, y0 + linear), *p11 = texel_at(t, x0 + linear, y0 + linear);
        for (int c = 0; c < 4; ++c) {
          const double v00 = p00[c], v10 = p10[c], v01 = p01[c], v11 = p11[c];
          if (!isfinite(v00) || !isfinite(v10) || !isfinite(v01) || !isfinite(v11)) {
            acc.bad[c] = 1;
            continue;
          }
          const double mag = fmax(fmax(fabs(v00), fabs(v10)), fmax(fabs(v01), fabs(v11)));
          /* bilinear is linear in each weight: its extremes are at the weight box's corners */
          for (int k = 0; k < 4; ++k) {
            const double wx = linear ? ax.w[cx][k & 1] : 0, wy = linear ? ay.w[cy][k >> 1] : 0;
            const double v = (1 - wy) * ((1 - wx) * v00 + wx * v10) + wy * ((1 - wx) * v01 + wx * v11);
            acc_value(&acc, c, v, mag);
          }
        }
      }
  }
  ts_iv ch[4];
  for (int c = 0; c < 4; ++c) {
    if (acc.bad[c]) { /* NaN or Inf texels: Inf - Inf in a lerp, NaN weights: any result */
      ch[c] = ts_ivany();
      continue;
    }
    /* three lerps in float32 (mad or not): each rounds by under one ULP of the largest texel, x2
     * for the difference b - a; 8 ULP of the largest |texel| in all */
    const double e = 8 * ulpd(acc.mag[c]);
    ch[c] = mk(acc.lo[c] - e, acc.hi[c] + e);
  }
  return ts_v4iv(ch[0], ch[1], ch[2], ch[3]);
}

/* ---- cube and 3D lookups (issue 14) ---- */

static ts_vec4iv join4(ts_vec4iv a, ts_vec4iv b) {
  return ts_v4iv(ts_ivjoin(a.x, b.x), ts_ivjoin(a.y, b.y), ts_ivjoin(a.z, b.z), ts_ivjoin(a.w, b.w));
}
static ts_vec4iv empty4(void) {
  const ts_iv e = {INFINITY, -INFINITY, 0};
  return ts_v4iv(e, e, e, e);
}

/* The hull of the texels on the border rows and columns of all six faces, rounded outward: what a
 * seamless LINEAR lookup (ES 3.00 section 3.8.9.1, always on in ES 3) may blend in from the
 * neighbouring faces when its footprint crosses a face edge. Conservative: any face's border. */
static ts_vec4iv cube_border_hull(const ts_texcube *c) {
  double lo[4], hi[4], mag[4];
  int bad[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) lo[k] = INFINITY, hi[k] = -INFINITY, mag[k] = 0;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < c->size; ++y)
      for (int x = 0; x < c->size; ++x) {
        if (x != 0 && y != 0 && x != c->size - 1 && y != c->size - 1) continue;
        const float *p = c->faces[f] + ((size_t)y * (size_t)c->size + (size_t)x) * 4u;
        for (int k = 0; k < 4; ++k) {
          if (!isfinite(p[k])) bad[k] = 1;
          if (p[k] < lo[k]) lo[k] = p[k];
          if (p[k] > hi[k]) hi[k] = p[k];
          if (fabs((double)p[k]) > mag[k]) mag[k] = fabs((double)p[k]);
        }
      }
  ts_iv ch[4];
  for (int k = 0; k < 4; ++k) {
    const double e = 8 * ulpd(mag[k]); /* the lerps' rounding, as ts_texture2Div */
    ch[k] = bad[k] ? ts_ivany() : mk(lo[k] - e, hi[k] + e);
  }
  return ts_v4iv(ch[0], ch[1], ch[2], ch[3]);
}

/* range of q / m for q in [ql, qh], m in [ml, mh] (0 < ml <= mh), clamped to [-1, 1] */
static void quot_range(double ql, double qh, double ml, double mh, double *lo, double *hi) {
  const double r[4] = {ql / ml, ql / mh, qh / ml, qh / mh};
  *lo = r[0], *hi = r[0];
  for (int i = 1; i < 4; ++i) *lo = fmin(*lo, r[i]), *hi = fmax(*hi, r[i]);
  *lo = fmax(*lo, -1.0), *hi = fmin(*hi, 1.0);
}

/* textureCube (ES 3.00 section 3.8.10, table 3.21; the face choice as dEQP's
 * tcuTexLookupVerifier does it, getPossibleCubeFaces: every face whose major axis can be the
 * largest somewhere in the direction's box, each sampled over the face coordinates the box
 * projects to). Face coordinates s = (sc / |ma| + 1) / 2 are widened by 2^-20 (the division's
 * 2.5 ULP and the scale-and-bias, under 2^-21 each near 1), then bounded as a 2D CLAMP_TO_EDGE
 * lookup (ts_texture2Div: coordBits 20, uvwBits 7). A LINEAR footprint that reaches a face
 * edge also admits the border texels of the faces (seamless filtering, on in ES 3, off in ES 2
 * and on llvmpipe's desktop contexts: both are covered). A direction box that contains the zero
 * vector, or a NaN or Inf component: any result. */
ts_vec4iv ts_textureCubeiv(const ts_texcube *c, ts_vec3iv d) {
  const ts_iv comp[3] = {d.x, d.y, d.z};
  double amin[3];
  int zero_in_box = 1;
  for (int a = 0; a < 3; ++a) {
    const ts_iv v = comp[a];
    if (v.nan || !has_num(v) || !isfinite(v.lo) || !isfinite(v.hi)) return ts_v4ivany();
    amin[a] = (v.lo <= 0 && v.hi >= 0) ? 0.0 : fmin(fabs((double)v.lo), fabs((double)v.hi));
    if (amin[a] > 0) zero_in_box = 0;
  }
  if (zero_in_box) return ts_v4ivany();
  /* face f: major axis f / 2, negative if f odd; (sc, tc) = (sign * axis) per table 3.21 */
  static const int sc_axis[6] = {2, 2, 0, 0, 0, 0}, tc_axis[6] = {1, 1, 2, 2, 1, 1};
  static const int sc_sign[6] = {-1, 1, 1, 1, 1, -1}, tc_sign[6] = {-1, -1, 1, -1, -1, -1};
  ts_vec4iv r = empty4();
  int any_face = 0, edge = 0;
  for (int f = 0; f < 6; ++f) {
    const int a = f / 2, neg = f & 1;
    const ts_iv v = comp[a];
    if (neg ? !(v.lo < 0) : !(v.hi > 0)) continue;
    const double ml0 = neg ? fmax(-(double)v.hi, 0.0) : fmax((double)v.lo, 0.0), mh = neg ? -(double)v.lo : v.hi;
    const int b = sc_axis[f], e = tc_axis[f];
    const double ml = fmax(ml0, fmax(amin[b], amin[e]));
    if (!(ml <= mh) || !(ml > 0)) continue;
    const ts_iv sb = comp[b], te = comp[e];
    double sl = sc_sign[f] > 0 ? sb.lo : -(double)sb.hi, sh = sc_sign[f] > 0 ? sb.hi : -(double)sb.lo;
    double tl = tc_sign[f] > 0 ? te.lo : -(double)te.hi, th = tc_sign[f] > 0 ? te.hi : -(double)te.lo;
    sl = fmax(sl, -mh), sh = fmin(sh, mh), tl = fmax(tl, -mh), th = fmin(th, mh);
    double qsl, qsh, qtl, qth;
    quot_range(sl, sh, ml, mh, &qsl, &qsh);
    quot_range(tl, th, ml, mh, &qtl, &qth);
    const double w = 0x1p-20;
    const double s0 = 0.5 * qsl + 0.5 - w, s1 = 0.5 * qsh + 0.5 + w, t0 = 0.5 * qtl + 0.5 - w, t1 = 0.5 * qth + 0.5 + w;
    const ts_tex2d face = {.w = c->size, .h = c->size, .texels = c->faces[f], .wrap_s = TS_WRAP_CLAMP, .wrap_t = TS_WRAP_CLAMP, .filter = c->filter};
    r = join4(r, ts_texture2Div(&face, ts_v2iv(mk(s0, s1), mk(t0, t1))));
    any_face = 1;
    if (c->filter == TS_FILTER_LINEAR) {
      const double n = c->size, m = 1e-6 + n * 0x1p-19; /* texel-space margin: coordBits, w */
      if (s0 * n < 0.5 + m || s1 * n > n - 0.5 - m || t0 * n < 0.5 + m || t1 * n > n - 0.5 - m) edge = 1;
    }
  }
  if (!any_face) return ts_v4ivany();
  if (edge) r = join4(r, cube_border_hull(c));
  return r;
}

/* texture3D: the 2D rule (ts_texture2Div) on three axes; LINEAR is trilinear, whose value is
 * multilinear in the three weights, so its extremes over the weight box lie at the box's
 * corners. Seven lerps in float32: 12 ULP of the largest |texel| (as ts_texture2Div's 8 for
 * three). */
ts_vec4iv ts_texture3Div(const ts_tex3d *t, ts_vec3iv uvw) {
  const int linear = t->filter == TS_FILTER_LINEAR;
  const axis_cells ax = axis_of(uvw.x, t->w, linear), ay = axis_of(uvw.y, t->h, linear), az = axis_of(uvw.z, t->d, linear);
  tex_acc acc;
  for (int c = 0; c < 4; ++c) acc.lo[c] = INFINITY, acc.hi[c] = -INFINITY, acc.mag[c] = 0, acc.bad[c] = 0;
  if (ax.n == 0 || ay.n == 0 || az.n == 0) {
    const size_t n = (size_t)t->w * (size_t)t->h * (size_t)t->d;
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 4; ++c) {
        const float p = t->texels[i * 4u + (size_t)c];
        if (!isfinite(p)) acc.bad[c] = 1;
        else acc_value(&acc, c, p, fabs((double)p));
      }
  } else {
    for (int cz = 0; cz < az.n; ++cz)
      for (int cy = 0; cy < ay.n; ++cy)
        for (int cx = 0; cx < ax.n; ++cx) {
          const float *p[8];
          for (int k = 0; k < 8; ++k) {
            const int x = wrap_index(ax.i[cx] + (linear & k), t->w, t->wrap_s);
            const int y = wrap_index(ay.i[cy] + (linear & (k >> 1)), t->h, t->wrap_t);
            const int z = wrap_index(az.i[cz] + (linear & (k >> 2)), t->d, t->wrap_r);
            p[k] = t->texels + (((size_t)z * (size_t)t->h + (size_t)y) * (size_t)t->w + (size_t)x) * 4u;
          }
          for (int c = 0; c < 4; ++c) {
            double v[8], mag = 0;
            int bad = 0;
            for (int k = 0; k < 8; ++k) {
              v[k] = p[k][c];
              if (!isfinite(v[k])) bad = 1;
              mag = fmax(mag, fabs(v[k]));
            }
            if (bad) {
              acc.bad[c] = 1;
              continue;
            }
            for (int q = 0; q < 8; ++q) {
              const double wx = linear ? ax.w[cx][q & 1] : 0, wy = linear ? ay.w[cy][(q >> 1) & 1] : 0;
              const double wz = linear ? az.w[cz][q >> 2] : 0;
              const double x0 = (1 - wx) * v[0] + wx * v[1], x1 = (1 - wx) * v[2] + wx * v[3];
              const double x2 = (1 - wx) * v[4] + wx * v[5], x3 = (1 - wx) * v[6] + wx * v[7];
              const double y0 = (1 - wy) * x0 + wy * x1, y1 = (1 - wy) * x2 + wy * x3;
              acc_value(&acc, c, (1 - wz) * y0 + wz * y1, mag);
            }
          }
        }
  }
  ts_iv ch[4];
  for (int c = 0; c < 4; ++c) {
    if (acc.bad[c]) {
      ch[c] = ts_ivany();
      continue;
    }
    const double e = 12 * ulpd(acc.mag[c]);
    ch[c] = mk(acc.lo[c] - e, acc.hi[c] + e);
  }
  return ts_v4iv(ch[0], ch[1], ch[2], ch[3]);
}

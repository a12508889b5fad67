/* tiershade math: interval arithmetic (ts_interval.h), continued: the comparisons, logic and
 * conversions the other twin families need (==, !=, ||, &&, int(), floor, vec3/vec4 helpers), on
 * the same true / false / either outcomes as ts_interval.c's comparisons (ESSL 3.00 section 4.5.1:
 * a NaN operand or an interval that straddles the test gives either). An interval with lo > hi
 * holds no number (only NaN). */
#include <float.h>
#include <math.h>

#include "math/ts_interval.h"

/* ---- more comparisons, logic and conversions (the other twin families, issue 14) ---- */

int ts_eqiv(ts_iv a, ts_iv b) {
  if (a.nan || b.nan || !(a.lo <= a.hi) || !(b.lo <= b.hi)) return TS_IV_EITHER;
  if (a.lo == a.hi && b.lo == b.hi && a.lo == b.lo) return TS_IV_TRUE;
  if (a.hi < b.lo || b.hi < a.lo) return TS_IV_FALSE;
  return TS_IV_EITHER;
}
int ts_neiv(ts_iv a, ts_iv b) { return ts_notiv(ts_eqiv(a, b)); }
int ts_notiv(int c) { return c == TS_IV_EITHER ? c : !c; }
int ts_oriv(int a, int b) {
  if (a == TS_IV_TRUE || b == TS_IV_TRUE) return TS_IV_TRUE;
  return a == TS_IV_FALSE && b == TS_IV_FALSE ? TS_IV_FALSE : TS_IV_EITHER;
}
int ts_andiv(int a, int b) {
  if (a == TS_IV_FALSE || b == TS_IV_FALSE) return TS_IV_FALSE;
  return a == TS_IV_TRUE && b == TS_IV_TRUE ? TS_IV_TRUE : TS_IV_EITHER;
}
ts_vec4iv ts_sel4iv(int c, ts_vec4iv a, ts_vec4iv b) {
  return ts_v4iv(ts_seliv(c, a.x, b.x), ts_seliv(c, a.y, b.y), ts_seliv(c, a.z, b.z), ts_seliv(c, a.w, b.w));
}
int ts_ivtoint(ts_iv x) {
  if (x.nan || !(x.lo <= x.hi) || !(fabsf(x.lo) < 0x1p30f && fabsf(x.hi) < 0x1p30f)) return TS_IV_UNSURE_INT;
  const int lo = (int)x.lo, hi = (int)x.hi; /* GLSL int(): truncation */
  return lo == hi ? lo : TS_IV_UNSURE_INT;
}
ts_vec4iv ts_v4ivany(void) { return ts_v4iv(ts_ivany(), ts_ivany(), ts_ivany(), ts_ivany()); }

/* floor: exact, monotonic */
ts_iv ts_flooriv(ts_iv x) {
  if (x.nan || !(x.lo <= x.hi)) return ts_ivany();
  return ts_ivrange(floorf(x.lo), floorf(x.hi));
}

ts_vec3iv ts_neg3iv(ts_vec3iv v) { return ts_v3iv(ts_negiv(v.x), ts_negiv(v.y), ts_negiv(v.z)); }
ts_vec3iv ts_max3iv(ts_vec3iv a, ts_vec3iv b) { return ts_v3iv(ts_maxiv(a.x, b.x), ts_maxiv(a.y, b.y), ts_maxiv(a.z, b.z)); }
ts_vec3iv ts_min3iv(ts_vec3iv a, ts_vec3iv b) { return ts_v3iv(ts_miniv(a.x, b.x), ts_miniv(a.y, b.y), ts_miniv(a.z, b.z)); }

/* ---- mix() in another implementation's form (ts_generic.h ALT_LERP) ----
 * GLSL ES 3.00 defines mix(x, y, t) as x (1 - t) + y t and lets its precision be inherited from
 * that expression, so an implementation may compute it as x (1 - t) + y t, x + (y - x) t or
 * (1 - t) + y t with x = 1 (llvmpipe lowers NIR's flrp to the second, or the third; SwiftShader was
 * measured computing the second where llvmpipe computes the first: docs/conformance.md "In a
 * browser"). Each form rounds at most 3 times, each time by less than one ULP of its result (< 2^-23
 * of it), and each intermediate is bounded by |x| (1 + |t|) + |y| |t|: every form lies within
 * 2^-21 (|x| (1 + |t|) + |y| |t|) of the exact value, plus FLT_MIN per operation for a flushed
 * denormal. `a` (one form, outward-rounded like every interval here) contains the exact value, so
 * widening it by that much contains every form: the join of the forms without taking the operands
 * apart again (the x + (y - x) t form evaluated on intervals counts x twice, and on wide operands
 * came out 18 times wider). */
static double mag(ts_iv v) {
  const double l = fabs((double)v.lo), h = fabs((double)v.hi);
  return l > h ? l : h;
}

ts_iv ts_ivlerp_forms(ts_iv a, ts_iv x, ts_iv y, ts_iv t) {
  if (a.nan || x.nan || y.nan || t.nan || a.lo > a.hi || x.lo > x.hi || y.lo > y.hi || t.lo > t.hi) return ts_ivany();
  const double mt = mag(t);
  /* mediump: 4 ULP of its 9-bit format (2^-7) and its smallest normal 2^-13 (ts_iv_set_mediump) */
  const int md = ts_iv_mediump();
  const double e = ldexp(mag(x) * (1.0 + mt) + mag(y) * mt, md ? -7 : -21) + 4.0 * (md ? 0x1p-13 : FLT_MIN);
  if (!isfinite(e)) return ts_ivany();
  const double lo = (double)a.lo - e, hi = (double)a.hi + e;
  /* outward to float: the next float at or beyond each end */
  float flo = (float)lo, fhi = (float)hi;
  if ((double)flo > lo) flo = nextafterf(flo, -INFINITY);
  if ((double)fhi < hi) fhi = nextafterf(fhi, INFINITY);
  ts_iv r = ts_ivrange(flo, fhi);
  r.nan = 0;
  return r;
}

/* ---- vectors and the helpers built on the operations alone (moved from ts_interval.c) ---- */
ts_vec3iv ts_sel3iv(int c, ts_vec3iv a, ts_vec3iv b) {
  return ts_v3iv(ts_seliv(c, a.x, b.x), ts_seliv(c, a.y, b.y), ts_seliv(c, a.z, b.z));
}

/* clamp(x, lo, hi) = min(max(x, lo), hi) (ESSL 3.00 8.3) */
ts_iv ts_clampiv(ts_iv x, ts_iv lo, ts_iv hi) { return ts_miniv(ts_maxiv(x, lo), hi); }
ts_iv ts_saturateiv(ts_iv x) { return ts_clampiv(x, ts_ivpoint(0.0f), ts_ivpoint(1.0f)); }
/* step(edge, x) = x < edge ? 0 : 1; straddling: both */
ts_iv ts_stepiv(ts_iv edge, ts_iv x) { return ts_seliv(ts_ltiv(x, edge), ts_ivpoint(0.0f), ts_ivpoint(1.0f)); }

/* ---- vectors ---- */
ts_vec2iv ts_v2iv(ts_iv x, ts_iv y) {
  ts_vec2iv v = {x, y};
  return v;
}
ts_vec3iv ts_v3iv(ts_iv x, ts_iv y, ts_iv z) {
  ts_vec3iv v = {x, y, z};
  return v;
}
ts_vec4iv ts_v4iv(ts_iv x, ts_iv y, ts_iv z, ts_iv w) {
  ts_vec4iv v = {x, y, z, w};
  return v;
}

ts_vec3iv ts_add3iv(ts_vec3iv a, ts_vec3iv b) { return ts_v3iv(ts_addiv(a.x, b.x), ts_addiv(a.y, b.y), ts_addiv(a.z, b.z)); }
ts_vec3iv ts_sub3iv(ts_vec3iv a, ts_vec3iv b) { return ts_v3iv(ts_subiv(a.x, b.x), ts_subiv(a.y, b.y), ts_subiv(a.z, b.z)); }
ts_vec3iv ts_mul3iv(ts_vec3iv a, ts_vec3iv b) { return ts_v3iv(ts_muliv(a.x, b.x), ts_muliv(a.y, b.y), ts_muliv(a.z, b.z)); }
ts_vec3iv ts_scale3iv(ts_vec3iv v, ts_iv s) { return ts_v3iv(ts_muliv(v.x, s), ts_muliv(v.y, s), ts_muliv(v.z, s)); }
ts_vec3iv ts_saturate3iv(ts_vec3iv v) { return ts_v3iv(ts_saturateiv(v.x), ts_saturateiv(v.y), ts_saturateiv(v.z)); }
/* normalize(v) = v * inversesqrt(dot(v, v)) (ESSL 3.00 8.4, derived) */
ts_vec3iv ts_normalize3iv(ts_vec3iv v) { return ts_scale3iv(v, ts_inversesqrtiv(ts_dot3iv(v, v))); }
ts_iv ts_absiv(ts_iv x) {
  if (!(x.lo <= x.hi)) return x;
  if (x.lo >= 0) return x;
  if (x.hi <= 0) return ts_negiv(x);
  ts_iv r = {0.0f, fmaxf(-x.lo, x.hi), x.nan};
  return r;
}
/* pow(x, y) = exp2(y * log2(x)) (ESSL 3.00 8.2: derived precision; undefined for x < 0 and for
 * x = 0 with y <= 0, and log2(0) is undefined, so any x interval reaching 0 gives any result) */
ts_iv ts_powiv(ts_iv x, ts_iv y) { return ts_exp2iv(ts_muliv(y, ts_log2iv(x))); }

/* ts_interval.h: a mip chain sampled with derivatives, the hull of every level (the level of
 * detail is the implementation's, within wide limits). */
ts_vec4iv ts_texture2D_gradiv(const ts_tex2d *t, ts_vec2iv uv, const ts_vec4f *grad) {
  ts_vec4iv r = ts_texture2Div(t, uv);
  if (!grad || t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return r;
  for (int l = 1; l < t->mip_levels; ++l) {
    const ts_tex2d lv = ts_mip_level(t, l);
    const ts_vec4iv s = ts_texture2Div(&lv, uv);
    r = ts_v4iv(ts_ivjoin(r.x, s.x), ts_ivjoin(r.y, s.y), ts_ivjoin(r.z, s.z), ts_ivjoin(r.w, s.w));
  }
  return r;
}

/* tiershade math: GLSL-like math layer: float32 llvmpipe-exact ("f") and double libm reference ("d").
 * The f family mirrors Mesa 22.3.6 llvmpipe: algorithms read in gallivm
 * lp_bld_arit.c (exp2, log2_safe, pow, polynomial, min/max, fract, rsqrt), NIR
 * lowering of GLSL builtins (nir_lower_alu_to_scalar for dot), and every result
 * checked bit for bit against the real driver (docs/c_math_layer.md has the table).
 * Shared facts: /work/shared/docs/llvmpipe_bitexact.md, platform_notes.md sec. 4.
 * Must be compiled with -ffp-contract=off (no implicit FMA) and run with FTZ|DAZ.
 */
#include "math/ts_math.h"

#include "math/ts_bits.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define TS_HAVE_SSE 1
#endif

/* ------------------------------------------------------------------------ */
/* state                                                                    */
/* ------------------------------------------------------------------------ */

static int ts_fused; /* 0 until ts_math_init()/ts_math_set_fused() */

void ts_math_set_ftz(void) {
#ifdef TS_HAVE_SSE
  _mm_setcsr(_mm_getcsr() | 0x8040u); /* FTZ (bit 15) | DAZ (bit 6) */
#endif
}

/* llvmpipe fuses gallivm mads iff util_cpu_caps.has_fma; GALLIUM_OVERRIDE_CPU_CAPS
 * set to a pre-AVX level clears it (llvmpipe_bitexact.md: sse4.1 -> unfused,
 * avx -> still fused). */
static int ts_detect_fma(void) {
  int fma = 0;
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __builtin_cpu_init();
  fma = __builtin_cpu_supports("fma") ? 1 : 0;
#endif
  {
    const char *o = getenv("GALLIUM_OVERRIDE_CPU_CAPS");
    if (o &&
        (!strcmp(o, "nosse") || !strcmp(o, "sse") || !strcmp(o, "sse2") || !strcmp(o, "sse3") || !strcmp(o, "ssse3") ||
         !strcmp(o, "sse4.1")))
      fma = 0;
  }
  return fma;
}

void ts_math_init(void) {
  ts_math_set_ftz();
  ts_fused = ts_detect_fma();
}

void ts_math_set_fused(int on) { ts_fused = on ? 1 : 0; }
int ts_math_fused(void) { return ts_fused; }

/* ------------------------------------------------------------------------ */
/* float32 bit helpers and raw gallivm/x86 primitives                        */
/* ------------------------------------------------------------------------ */

static int is_nanf(float x) { return x != x; }

float ts_madf(float a, float b, float c) { return ts_fused ? fmaf(a, b, c) : a * b + c; }

float ts_lp_minf(float a, float b) {
  a = ts_daz(a);
  b = ts_daz(b);
  return a < b ? a : b;
}

float ts_lp_maxf(float a, float b) {
  a = ts_daz(a);
  b = ts_daz(b);
  return a > b ? a : b;
}

int ts_lp_itruncf(float x) {
  if (!(x > -2147483904.0f && x < 2147483648.0f)) /* NaN or out of range */
    return INT32_MIN;
  return (int)x;
}

/* SSE4.1 roundps(floor), as used by gallivm lp_build_floor: DAZ, NaN quieted. */
static float lp_floor(float x) {
  float t;
  x = ts_daz(x);
  if (is_nanf(x)) return ts_bitsf(ts_fbits(x) | 0x00400000u);
  if (!(fabsf(x) < 8388608.0f)) return x; /* inf, or already an integer */
  t = (float)(int)x; /* exact: |x| < 2^23 */
  if (t > x) t -= 1.0f;
  return t == 0.0f ? copysignf(0.0f, x) : t;
}

/* gallivm lp_build_polynomial: even/odd split, Horner in x^2, mads. */
static float lp_poly(float x, const float *c, int n) {
  float x2 = x * x, even = 0.0f, odd = 0.0f;
  int i, have_even = 0, have_odd = 0;
  for (i = n - 1; i >= 0; i--) {
    if (i % 2 == 0) {
      even = have_even ? ts_madf(x2, even, c[i]) : c[i];
      have_even = 1;
    } else {
      odd = have_odd ? ts_madf(x2, odd, c[i]) : c[i];
      have_odd = 1;
    }
  }
  return have_odd ? ts_madf(odd, x, even) : even;
}

/* Coefficients (double in gallivm, rounded to float): llvmpipe_bitexact.md tables. Their bits:
 * exp2 0x3f800000 0x3f31727b 0x3e75ead4 0x3d64aa23 0x3c134806 0x3af61905,
 * log2 0x4038aa3b 0x3f7637f9 0x3f13d321 0x3ece8316 0x3ed03d59. */
const float ts_lp_exp2_coeffs[6] = {0x1p+0f,        0x1.62e4f6p-1f, 0x1.ebd5a8p-3f,
                                    0x1.c95446p-5f, 0x1.26900cp-7f, 0x1.ec320ap-10f};
const float ts_lp_log2_coeffs[5] = {0x1.715476p+1f, 0x1.ec6ff2p-1f, 0x1.27a642p-1f, 0x1.9d062cp-2f, 0x1.a07ab2p-2f};

/* ------------------------------------------------------------------------ */
/* scalar float32, llvmpipe-exact                                            */
/* ------------------------------------------------------------------------ */

/* gallivm lp_build_exp2: x = minps(128,x); x = maxps(-126.99999,x) (a NaN x is
 * the second operand, so it passes); ipart = floor, fpart = x - ipart;
 * 2^ipart built in the exponent field; result = 2^ipart * P(fpart). */
static int g_nan_model = TS_NAN_LLVMPIPE;
void ts_set_nan_model(int model) { g_nan_model = model; }

float ts_exp2f(float x) {
  float fl, fr, scale;
  int i;
  if (g_nan_model == TS_NAN_PROPAGATE && is_nanf(x)) return x;
  x = ts_lp_minf(128.0f, x);
  x = ts_lp_maxf(-126.99999f, x);
  fl = lp_floor(x);
  fr = x - fl;
  i = ts_lp_itruncf(fl);
  scale = ts_bitsf(((uint32_t)i + 127u) << 23);
  return scale * lp_poly(fr, ts_lp_exp2_coeffs, 6);
}

/* gallivm lp_build_log2_approx(handle_edge_cases=1) ("log2_safe"). The edge
 * masks use lp_build_cmp, whose float predicates are UNORDERED, so a NaN input
 * sets all three; the selects run inf, zero, negative (last wins). */
float ts_log2f(float x) {
  uint32_t b = ts_fbits(x);
  float e = (float)((int)((b & 0x7f800000u) >> 23) - 127);
  float m = ts_bitsf((b & 0x007fffffu) | 0x3f800000u);
  float y = (m - 1.0f) / (m + 1.0f);
  float r = ts_madf(y, lp_poly(y * y, ts_lp_log2_coeffs, 5), e);
  float xd = ts_daz(x);
  if (!(xd < INFINITY)) r = INFINITY; /* UGE +inf  */
  if (!(xd != 0.0f)) r = -INFINITY; /* UEQ 0     */
  if (!(xd >= 0.0f)) r = NAN; /* ULT 0     */
  if (g_nan_model == TS_NAN_PROPAGATE && xd == 0.0f) r = -127.0f;
  return r;
}

/* gallivm lp_build_pow: select(x UEQ 0, 0, exp2(log2_safe(x) * y)). */
float ts_powf(float x, float y) {
  float r = ts_exp2f(ts_log2f(x) * y);
  float xd = ts_daz(x);
  if (g_nan_model == TS_NAN_PROPAGATE) return r;
  return (xd == 0.0f || is_nanf(xd)) ? 0.0f : r;
}

/* GLSL exp/log -> NIR fexp2(x*log2(e)) / flog2(x)*ln(2) (llvmpipe_bitexact.md). */
float ts_expf(float x) { return ts_exp2f(x * 0x1.715476p+0f); } /* 0x3fb8aa3b */
float ts_logf(float x) { return ts_log2f(x) * 0x1.62e430p-1f; } /* 0x3f317218 */

float ts_sqrtf(float x) { return sqrtf(x); }
/* lp_build_rsqrt without the fast path: a real sqrt then an IEEE division. */
float ts_inversesqrtf(float x) { return 1.0f / sqrtf(x); }

/* GLSL min/max = gallivm min/max with GALLIVM_NAN_RETURN_OTHER on SSE
 * (lp_build_min/max_simple): r = minps(a,b); if b is NaN, r = a.  Measured:
 * both argument orders, +-0 ties, denormals, NaN. NB: NIR moves a constant
 * operand second, so GLSL max(0.0, x) == ts_maxf(x, 0.0f). */
float ts_minf(float a, float b) {
  if (g_nan_model == TS_NAN_PROPAGATE && (is_nanf(a) || is_nanf(b))) return NAN;
  return is_nanf(b) ? a : ts_lp_minf(a, b);
}
float ts_maxf(float a, float b) {
  if (g_nan_model == TS_NAN_PROPAGATE && (is_nanf(a) || is_nanf(b))) return NAN;
  return is_nanf(b) ? a : ts_lp_maxf(a, b);
}
/* GLSL clamp -> fmin(fmax(x, lo), hi). */
float ts_clampf(float x, float lo, float hi) { return ts_minf(ts_maxf(x, lo), hi); }
/* NIR fsat -> lp_build_clamp_zero_one_nanzero: minps(maxps(x, 0), 1). */
float ts_saturatef(float x) {
  if (g_nan_model == TS_NAN_PROPAGATE && is_nanf(x)) return x;
  return ts_lp_minf(ts_lp_maxf(x, 0.0f), 1.0f);
}
float ts_floorf(float x) { return lp_floor(x); }
float ts_fractf(float x) { return x - lp_floor(x); } /* not clamped: fract(-tiny) = 1 */
float ts_absf(float x) { return ts_bitsf(ts_fbits(x) & 0x7fffffffu); }
/* step(edge,x) = x >= edge ? 1 : 0 (ordered compare: NaN -> 0; measured). */
float ts_stepf(float edge, float x) { return x >= edge ? 1.0f : 0.0f; }
/* sign: +1/-1 by comparison; +0 for +-0, denormals and NaN (measured). */
float ts_signf(float x) {
  float xd = ts_daz(x);
  if (xd > 0.0f) return 1.0f;
  if (xd < 0.0f) return -1.0f;
  return 0.0f;
}

/* ------------------------------------------------------------------------ */
/* scalar double reference (libm)                                            */
/* ------------------------------------------------------------------------ */

double ts_exp2d(double x) { return exp2(x); }
double ts_log2d(double x) { return log2(x); }
double ts_powd(double x, double y) { return pow(x, y); } /* libm: pow(0,0)=1, pow(0,-1)=inf */
double ts_expd(double x) { return exp(x); }
double ts_logd(double x) { return log(x); }
double ts_sqrtd(double x) { return sqrt(x); }
double ts_inversesqrtd(double x) { return 1.0 / sqrt(x); }
double ts_mind(double a, double b) { return b != b ? a : (a != a ? b : (a < b ? a : b)); }
double ts_maxd(double a, double b) { return b != b ? a : (a != a ? b : (a > b ? a : b)); }
double ts_clampd(double x, double lo, double hi) { return ts_mind(ts_maxd(x, lo), hi); }
double ts_saturated(double x) { return ts_clampd(x, 0.0, 1.0); }
double ts_floord(double x) { return floor(x); }
double ts_fractd(double x) { return x - floor(x); }
double ts_absd(double x) { return fabs(x); }
double ts_stepd(double edge, double x) { return x >= edge ? 1.0 : 0.0; }
double ts_signd(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

/* ------------------------------------------------------------------------ */
/* vectors, float32                                                          */
/* ------------------------------------------------------------------------ */

#include "math/ts_generic.h"
#include "math/ts_generic_float.h"
#include "math/ts_math_vec.h"

/* GLSL dot: NIR scalarises fdotN as a reduction from the LAST component,
 * a0*b0 + (a1*b1 + (a2*b2 + a3*b3)), unfused (measured on llvmpipe; the
 * left-to-right order mismatches in ~7% of random cases). */
float ts_dot3f(ts_vec3f a, ts_vec3f b) { return a.x * b.x + (a.y * b.y + a.z * b.z); }
float ts_dot4f(ts_vec4f a, ts_vec4f b) { return a.x * b.x + (a.y * b.y + (a.z * b.z + a.w * b.w)); }
/* GLSL normalize(v) = v * inversesqrt(dot(v,v)). */
ts_vec3f ts_normalize3f(ts_vec3f v) { return ts_scale3f(v, ts_inversesqrtf(ts_dot3f(v, v))); }

/* ------------------------------------------------------------------------ */
/* vectors, double                                                           */
/* ------------------------------------------------------------------------ */

#include "math/ts_generic_double.h"
#include "math/ts_math_vec.h"

double ts_dot3d(ts_vec3d a, ts_vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double ts_dot4d(ts_vec4d a, ts_vec4d b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
ts_vec3d ts_normalize3d(ts_vec3d v) {
  double l = sqrt(ts_dot3d(v, v));
  return ts_v3d(v.x / l, v.y / l, v.z / l);
}

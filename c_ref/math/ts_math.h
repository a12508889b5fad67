/* tiershade math: GLSL-like scalar/vector math in two precisions (the suffix is the LAST letter):
 *   ...f  float32, bit-exact mirror of Mesa 22.3.6 llvmpipe (gallivm + NIR lowering)
 *   ...d  double, plain libm accuracy reference
 * Build with -std=c99 -ffp-contract=off -fno-fast-math and call ts_math_init() once
 * per computing thread (FTZ/DAZ + fused-mad choice).  Facts and sources:
 * docs/c_math_layer.md.
 */
#ifndef TS_MATH_H
#define TS_MATH_H

#ifdef __cplusplus
extern "C" {
#endif

/* One precision's vector types and functions: S is the suffix (f, d), R the real type. The
 * two instances (below) hold the same names; what each computes is in ts_math.c. */
#define TS_MATH_API(S, R)                            \
  typedef struct {                                   \
    R x, y;                                          \
  } ts_vec2##S;                                      \
  typedef struct {                                   \
    R x, y, z;                                       \
  } ts_vec3##S;                                      \
  typedef struct {                                   \
    R x, y, z, w;                                    \
  } ts_vec4##S;                                      \
  /* scalar */                                       \
  R ts_exp2##S(R x);                                 \
  R ts_log2##S(R x);                                 \
  R ts_pow##S(R x, R y);                             \
  R ts_exp##S(R x);                                  \
  R ts_log##S(R x);                                  \
  R ts_sqrt##S(R x);                                 \
  R ts_inversesqrt##S(R x);                          \
  R ts_min##S(R a, R b);                             \
  R ts_max##S(R a, R b);                             \
  R ts_clamp##S(R x, R lo, R hi);                    \
  R ts_saturate##S(R x);                             \
  R ts_floor##S(R x);                                \
  R ts_fract##S(R x);                                \
  R ts_abs##S(R x);                                  \
  R ts_step##S(R edge, R x);                         \
  R ts_sign##S(R x);                                 \
  /* vectors (the constructors inline: they sit in  \
     the C fallback's per-pixel loops) */            \
  static inline ts_vec2##S ts_v2##S(R x, R y) {      \
    ts_vec2##S v;                                    \
    v.x = x;                                         \
    v.y = y;                                         \
    return v;                                        \
  }                                                  \
  static inline ts_vec3##S ts_v3##S(R x, R y, R z) { \
    ts_vec3##S v;                                    \
    v.x = x;                                         \
    v.y = y;                                         \
    v.z = z;                                         \
    return v;                                        \
  }                                                  \
  static inline ts_vec4##S ts_v4##S(R x, R y, R z, R w) { \
    ts_vec4##S v;                                    \
    v.x = x;                                         \
    v.y = y;                                         \
    v.z = z;                                         \
    v.w = w;                                         \
    return v;                                        \
  }                                                  \
  R ts_dot2##S(ts_vec2##S a, ts_vec2##S b);          \
  ts_vec3##S ts_add3##S(ts_vec3##S a, ts_vec3##S b); \
  ts_vec3##S ts_sub3##S(ts_vec3##S a, ts_vec3##S b); \
  ts_vec3##S ts_mul3##S(ts_vec3##S a, ts_vec3##S b); \
  ts_vec3##S ts_scale3##S(ts_vec3##S v, R s);        \
  R ts_dot3##S(ts_vec3##S a, ts_vec3##S b);          \
  R ts_length3##S(ts_vec3##S v);                     \
  ts_vec3##S ts_normalize3##S(ts_vec3##S v);         \
  ts_vec3##S ts_max3##S(ts_vec3##S a, ts_vec3##S b); \
  ts_vec3##S ts_min3##S(ts_vec3##S a, ts_vec3##S b); \
  ts_vec3##S ts_saturate3##S(ts_vec3##S v);          \
  ts_vec3##S ts_pow3##S(ts_vec3##S a, ts_vec3##S b); \
  ts_vec3##S ts_neg3##S(ts_vec3##S v);               \
  ts_vec4##S ts_add4##S(ts_vec4##S a, ts_vec4##S b); \
  ts_vec4##S ts_sub4##S(ts_vec4##S a, ts_vec4##S b); \
  ts_vec4##S ts_mul4##S(ts_vec4##S a, ts_vec4##S b); \
  ts_vec4##S ts_scale4##S(ts_vec4##S v, R s);        \
  R ts_dot4##S(ts_vec4##S a, ts_vec4##S b);          \
  ts_vec4##S ts_saturate4##S(ts_vec4##S v);

/* float32, llvmpipe-exact (ts_exp2f, ts_vec3f, ts_dot3f, ...) */
TS_MATH_API(f, float)
/* double, plain libm accuracy reference (ts_exp2d, ts_vec3d, ts_dot3d, ...) */
TS_MATH_API(d, double)
#undef TS_MATH_API

/* ---- state ---------------------------------------------------------------- */
void ts_math_init(void); /* FTZ|DAZ on this thread + fused-mad autodetect */
void ts_math_set_fused(int on); /* process-wide override of the fused-mad choice  */
int ts_math_fused(void);
void ts_math_set_ftz(void); /* MXCSR |= 0x8040 on the calling thread only     */

/* gallivm lp_build_mad: a*b+c, one rounding iff fused mode (llvm.fmuladd).
 * NOT what GLSL a*b+c or fma() give (those are always unfused): use a*b+c. */
float ts_madf(float a, float b, float c);

/* NaN model of the scalar float32 builtins below (min, max, clamp, saturate, exp2, log2, pow).
 * TS_NAN_LLVMPIPE (the default) is llvmpipe's, bit for bit. TS_NAN_PROPAGATE is a test model of
 * another conformant implementation: a NaN operand of min/max/clamp/saturate/exp2/pow gives NaN
 * (SwiftShader returns one operand or the other, by position), log2(0) = -127 and pow(0, y) =
 * exp2(-127 y) (SwiftShader, measured in issue 14). tests/unit/test_nan_independence.cpp renders
 * the finite hard cases in both models: the shaders must not depend on which one runs. Only the
 * scalar twins (eval_f) see it; the SIMD and batch twins are llvmpipe's always. */
enum { TS_NAN_LLVMPIPE = 0, TS_NAN_PROPAGATE = 1 };
void ts_set_nan_model(int model);

/* Raw x86/gallivm primitives (also used by ts_sampler.c):
 *   ts_lp_minf(a,b) = SSE minps(a,b): a<b ? a : b (b if either is NaN), DAZ applied
 *   ts_lp_maxf(a,b) = SSE maxps(a,b): a>b ? a : b (b if either is NaN), DAZ applied
 *   ts_lp_itruncf(x) = cvttps2dq: round toward 0; NaN/out of range -> INT32_MIN  */
float ts_lp_minf(float a, float b);
float ts_lp_maxf(float a, float b);
int ts_lp_itruncf(float x);
/* gallivm lp_build_exp2 / lp_build_log2_approx polynomial coefficients (ts_exp2f, ts_log2f and
 * their lanes in ts_simd.h), lowest degree first. */
extern const float ts_lp_exp2_coeffs[6];
extern const float ts_lp_log2_coeffs[5];

#ifdef __cplusplus
}
#endif
#endif /* TS_MATH_H */

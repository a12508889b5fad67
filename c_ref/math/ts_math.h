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

typedef struct {
  float x, y;
} ts_vec2f;
typedef struct {
  double x, y;
} ts_vec2d;
typedef struct {
  float x, y, z;
} ts_vec3f;
typedef struct {
  double x, y, z;
} ts_vec3d;
typedef struct {
  float x, y, z, w;
} ts_vec4f;
typedef struct {
  double x, y, z, w;
} ts_vec4d;

/* ---- state ---------------------------------------------------------------- */
void ts_math_init(void); /* FTZ|DAZ on this thread + fused-mad autodetect */
void ts_math_set_fused(int on); /* process-wide override of the fused-mad choice  */
int ts_math_fused(void);
void ts_math_set_ftz(void); /* MXCSR |= 0x8040 on the calling thread only     */

/* gallivm lp_build_mad: a*b+c, one rounding iff fused mode (llvm.fmuladd).
 * NOT what GLSL a*b+c or fma() give (those are always unfused): use a*b+c. */
float ts_madf(float a, float b, float c);

/* Raw x86/gallivm primitives (also used by ts_sampler.c):
 *   ts_lp_minf(a,b) = SSE minps(a,b): a<b ? a : b (b if either is NaN), DAZ applied
 *   ts_lp_maxf(a,b) = SSE maxps(a,b): a>b ? a : b (b if either is NaN), DAZ applied
 *   ts_lp_itruncf(x) = cvttps2dq: round toward 0; NaN/out of range -> INT32_MIN  */
float ts_lp_minf(float a, float b);
float ts_lp_maxf(float a, float b);
int ts_lp_itruncf(float x);

/* ---- scalar, float32 llvmpipe-exact ---------------------------------------- */
float ts_exp2f(float x);
float ts_log2f(float x);
float ts_powf(float x, float y);
float ts_expf(float x);
float ts_logf(float x);
float ts_sqrtf(float x);
float ts_inversesqrtf(float x);
float ts_minf(float a, float b);
float ts_maxf(float a, float b);
float ts_clampf(float x, float lo, float hi);
float ts_saturatef(float x);
float ts_floorf(float x);
float ts_fractf(float x);
float ts_absf(float x);
float ts_stepf(float edge, float x);
float ts_signf(float x);

/* ---- scalar, double reference ----------------------------------------------- */
double ts_exp2d(double x);
double ts_log2d(double x);
double ts_powd(double x, double y);
double ts_expd(double x);
double ts_logd(double x);
double ts_sqrtd(double x);
double ts_inversesqrtd(double x);
double ts_mind(double a, double b);
double ts_maxd(double a, double b);
double ts_clampd(double x, double lo, double hi);
double ts_saturated(double x);
double ts_floord(double x);
double ts_fractd(double x);
double ts_absd(double x);
double ts_stepd(double edge, double x);
double ts_signd(double x);

/* ---- vectors, float32 --------------------------------------------------------- */
ts_vec2f ts_v2f(float x, float y);
ts_vec3f ts_v3f(float x, float y, float z);
ts_vec4f ts_v4f(float x, float y, float z, float w);
float ts_dot2f(ts_vec2f a, ts_vec2f b);
ts_vec3f ts_add3f(ts_vec3f a, ts_vec3f b);
ts_vec3f ts_sub3f(ts_vec3f a, ts_vec3f b);
ts_vec3f ts_mul3f(ts_vec3f a, ts_vec3f b);
ts_vec3f ts_scale3f(ts_vec3f v, float s);
float ts_dot3f(ts_vec3f a, ts_vec3f b);
float ts_length3f(ts_vec3f v);
ts_vec3f ts_normalize3f(ts_vec3f v);
ts_vec3f ts_max3f(ts_vec3f a, ts_vec3f b);
ts_vec3f ts_min3f(ts_vec3f a, ts_vec3f b);
ts_vec3f ts_saturate3f(ts_vec3f v);
ts_vec3f ts_pow3f(ts_vec3f a, ts_vec3f b);
ts_vec3f ts_neg3f(ts_vec3f v);
ts_vec4f ts_add4f(ts_vec4f a, ts_vec4f b);
ts_vec4f ts_sub4f(ts_vec4f a, ts_vec4f b);
ts_vec4f ts_mul4f(ts_vec4f a, ts_vec4f b);
ts_vec4f ts_scale4f(ts_vec4f v, float s);
float ts_dot4f(ts_vec4f a, ts_vec4f b);
ts_vec4f ts_saturate4f(ts_vec4f v);

/* ---- vectors, double ------------------------------------------------------------ */
ts_vec2d ts_v2d(double x, double y);
ts_vec3d ts_v3d(double x, double y, double z);
ts_vec4d ts_v4d(double x, double y, double z, double w);
double ts_dot2d(ts_vec2d a, ts_vec2d b);
ts_vec3d ts_add3d(ts_vec3d a, ts_vec3d b);
ts_vec3d ts_sub3d(ts_vec3d a, ts_vec3d b);
ts_vec3d ts_mul3d(ts_vec3d a, ts_vec3d b);
ts_vec3d ts_scale3d(ts_vec3d v, double s);
double ts_dot3d(ts_vec3d a, ts_vec3d b);
double ts_length3d(ts_vec3d v);
ts_vec3d ts_normalize3d(ts_vec3d v);
ts_vec3d ts_max3d(ts_vec3d a, ts_vec3d b);
ts_vec3d ts_min3d(ts_vec3d a, ts_vec3d b);
ts_vec3d ts_saturate3d(ts_vec3d v);
ts_vec3d ts_pow3d(ts_vec3d a, ts_vec3d b);
ts_vec3d ts_neg3d(ts_vec3d v);
ts_vec4d ts_add4d(ts_vec4d a, ts_vec4d b);
ts_vec4d ts_sub4d(ts_vec4d a, ts_vec4d b);
ts_vec4d ts_mul4d(ts_vec4d a, ts_vec4d b);
ts_vec4d ts_scale4d(ts_vec4d v, double s);
double ts_dot4d(ts_vec4d a, ts_vec4d b);
ts_vec4d ts_saturate4d(ts_vec4d v);

#ifdef __cplusplus
}
#endif
#endif /* TS_MATH_H */

/* tiershade tests: pure-C unit checks of c_ref/math/ts_math.[ch] and c_ref/math/ts_sampler.[ch] (no GL needed).
 * The expected values are llvmpipe facts measured on Mesa 22.3.6 (see
 * docs/c_math_layer.md), or exact identities. Prints "PASS name" or
 * "FAIL name: details" per check; exit status 1 if any check failed.
 * Build: gcc -std=c99 -O2 -Wall -Wextra -Werror -ffp-contract=off -fno-fast-math
 *        -Ic_ref tests/unit/test_ts_math.c c_ref/math/ts_math.c c_ref/math/ts_sampler.c -lm
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "math/ts_bits.h"
#include "math/ts_math.h"
#include "math/ts_sampler.h"

static int g_failed, g_passed;

static int same_bits(float a, float b) { return ts_fbits(a) == ts_fbits(b); }

static void report(int ok, const char *name, const char *detail) {
  if (ok) {
    g_passed++;
    printf("PASS %s\n", name);
  } else {
    g_failed++;
    printf("FAIL %s: %s\n", name, detail);
  }
}

/* bit-exact float comparison (NaN must be NaN, the sign of zero matters) */
static void check_f(const char *name, float got, float want) {
  char d[160];
  int ok = (got != got && want != want) || same_bits(got, want);
  snprintf(d, sizeof d, "got %.9g (0x%08x), want %.9g (0x%08x)", got, ts_fbits(got), want, ts_fbits(want));
  report(ok, name, d);
}

static void check_d(const char *name, double got, double want, double tol) {
  char d[160];
  int ok = (got != got && want != want) || got == want || fabs(got - want) <= tol;
  snprintf(d, sizeof d, "got %.17g, want %.17g (tol %g)", got, want, tol);
  report(ok, name, d);
}

static void check_true(const char *name, int cond, const char *detail) { report(cond, name, detail); }

/* ------------------------------------------------------------------------ */

static void test_state(void) {
  volatile float den = ts_bitsf(0x00000005u), one = 1.0f;
  float r;
  int saved = ts_math_fused();
  float a = 1.0f + 0x1p-12f, c = -1.0f;

  r = den * one;
  check_f("ftz_daz denormal*1 == 0", r, 0.0f);
  r = den + 0.0f * one;
  check_f("ftz_daz denormal+0 == 0", r, 0.0f);

  ts_math_set_fused(1);
  check_true("set_fused(1) reported", ts_math_fused() == 1, "ts_math_fused() != 1");
  check_f("madf fused = one rounding", ts_madf(a, a, c), 0x1p-11f + 0x1p-24f);
  ts_math_set_fused(0);
  check_true("set_fused(0) reported", ts_math_fused() == 0, "ts_math_fused() != 0");
  check_f("madf unfused = two roundings", ts_madf(a, a, c), 0x1p-11f);
  ts_math_set_fused(saved);
}

static void test_exp_log(int fused) {
  char name[96];
  int k, bad;
  const char *m = fused ? "fused" : "unfused";
  ts_math_set_fused(fused);

  for (bad = 0, k = -126; k <= 127; k++)
    if (!same_bits(ts_exp2f((float)k), ldexpf(1.0f, k))) bad++;
  snprintf(name, sizeof name, "exp2 of integers -126..127 exact (%s)", m);
  check_true(name, bad == 0, "some 2^k inexact");

  for (bad = 0, k = -126; k <= 127; k++)
    if (!same_bits(ts_log2f(ldexpf(1.0f, k)), (float)k)) bad++;
  snprintf(name, sizeof name, "log2 of powers of two exact (%s)", m);
  check_true(name, bad == 0, "some log2(2^k) != k");

  snprintf(name, sizeof name, "exp2(0.5) within 2 ulp of sqrt2 (%s)", m);
  check_true(name, fabsf(ts_exp2f(0.5f) - 1.41421356f) <= 2.5e-7f, "exp2(0.5) off");
  snprintf(name, sizeof name, "log2(3) within 1e-6 (%s)", m);
  check_true(name, fabs(ts_log2f(3.0f) - 1.5849625007) < 1e-6, "log2(3) off");
  snprintf(name, sizeof name, "pow(2.5,3.5) within 1e-5 rel (%s)", m);
  check_true(name, fabs(ts_powf(2.5f, 3.5f) / 24.705294220065465 - 1.0) < 1e-5, "pow off");
}

static void test_specials(void) {
  const float inf = INFINITY, qnan = NAN;
  const float den = ts_bitsf(0x00000001u), nden = ts_bitsf(0x80000001u);

  check_f("exp2(128) = +inf", ts_exp2f(128.0f), inf);
  check_f("exp2(200) = +inf", ts_exp2f(200.0f), inf);
  check_f("exp2(-127) = 0", ts_exp2f(-127.0f), 0.0f);
  check_f("exp2(-200) = 0", ts_exp2f(-200.0f), 0.0f);
  check_f("exp2(-inf) = 0", ts_exp2f(-inf), 0.0f);
  check_f("exp2(NaN) = NaN", ts_exp2f(qnan), qnan);
  check_f("exp2(-denormal) = 1 (DAZ)", ts_exp2f(nden), 1.0f);
  check_f("exp(0) = 1", ts_expf(0.0f), 1.0f);

  check_f("log2(1) = 0", ts_log2f(1.0f), 0.0f);
  check_f("log2(0) = -inf", ts_log2f(0.0f), -inf);
  check_f("log2(-0) = -inf", ts_log2f(-0.0f), -inf);
  check_f("log2(denormal) = -inf (DAZ)", ts_log2f(den), -inf);
  check_f("log2(-1) = NaN", ts_log2f(-1.0f), qnan);
  check_f("log2(-inf) = NaN", ts_log2f(-inf), qnan);
  check_f("log2(+inf) = +inf", ts_log2f(inf), inf);
  check_f("log2(NaN) = NaN", ts_log2f(qnan), qnan);
  check_f("log(1) = 0", ts_logf(1.0f), 0.0f);

  check_f("pow(0,0) = 0 (runtime llvmpipe)", ts_powf(0.0f, 0.0f), 0.0f);
  check_f("pow(0,-1) = 0", ts_powf(0.0f, -1.0f), 0.0f);
  check_f("pow(0,2) = 0", ts_powf(0.0f, 2.0f), 0.0f);
  check_f("pow(-0,3) = 0", ts_powf(-0.0f, 3.0f), 0.0f);
  check_f("pow(-1,2) = NaN", ts_powf(-1.0f, 2.0f), qnan);
  check_f("pow(1,inf) = NaN", ts_powf(1.0f, inf), qnan);
  check_f("pow(NaN,1) = 0 (x==0 test is unordered)", ts_powf(qnan, 1.0f), 0.0f);
  check_f("pow(2,10) = 1024", ts_powf(2.0f, 10.0f), 1024.0f);
  check_f("pow(1,y) = 1", ts_powf(1.0f, 7.25f), 1.0f);

  check_f("sqrt(-1) = NaN", ts_sqrtf(-1.0f), qnan);
  check_f("sqrt(4) = 2", ts_sqrtf(4.0f), 2.0f);
  check_f("inversesqrt(0) = +inf", ts_inversesqrtf(0.0f), inf);
  check_f("inversesqrt(4) = 0.5", ts_inversesqrtf(4.0f), 0.5f);
  check_f("inversesqrt(3) = 1/sqrtf(3)", ts_inversesqrtf(3.0f), 1.0f / sqrtf(3.0f));

  check_f("max(NaN,1) = 1", ts_maxf(qnan, 1.0f), 1.0f);
  check_f("max(1,NaN) = 1", ts_maxf(1.0f, qnan), 1.0f);
  check_f("min(NaN,1) = 1", ts_minf(qnan, 1.0f), 1.0f);
  check_f("min(1,NaN) = 1", ts_minf(1.0f, qnan), 1.0f);
  check_f("max(-0,+0) = +0 (second on tie)", ts_maxf(-0.0f, 0.0f), 0.0f);
  check_f("max(+0,-0) = -0 (second on tie)", ts_maxf(0.0f, -0.0f), -0.0f);
  check_f("min(+0,-0) = -0 (second on tie)", ts_minf(0.0f, -0.0f), -0.0f);
  check_f("max(denormal,-1) = 0 (DAZ)", ts_maxf(den, -1.0f), 0.0f);
  check_f("clamp(NaN,0,1) = 0", ts_clampf(qnan, 0.0f, 1.0f), 0.0f);
  check_f("clamp(2,0,1) = 1", ts_clampf(2.0f, 0.0f, 1.0f), 1.0f);
  check_f("clamp(-2,0,1) = 0", ts_clampf(-2.0f, 0.0f, 1.0f), 0.0f);
  check_f("clamp(0.5,0,1) = 0.5", ts_clampf(0.5f, 0.0f, 1.0f), 0.5f);
  check_f("clamp(x,NaN,1) = min(x,1)", ts_clampf(3.0f, qnan, 1.0f), 1.0f);
  check_f("clamp(-inf,0,1) = 0", ts_clampf(-inf, 0.0f, 1.0f), 0.0f);
  check_f("saturate(NaN) = 0", ts_saturatef(qnan), 0.0f);
  check_f("saturate(-0) = +0", ts_saturatef(-0.0f), 0.0f);
  check_f("saturate(+inf) = 1", ts_saturatef(inf), 1.0f);
  check_f("saturate(0.25) = 0.25", ts_saturatef(0.25f), 0.25f);

  check_f("sign(NaN) = 0", ts_signf(qnan), 0.0f);
  check_f("sign(-0) = +0", ts_signf(-0.0f), 0.0f);
  check_f("sign(-3) = -1", ts_signf(-3.0f), -1.0f);
  check_f("sign(+inf) = 1", ts_signf(inf), 1.0f);
  check_f("floor(-0.5) = -1", ts_floorf(-0.5f), -1.0f);
  check_f("floor(-0) = -0", ts_floorf(-0.0f), -0.0f);
  check_f("floor(2.5) = 2", ts_floorf(2.5f), 2.0f);
  check_f("floor(-denormal) = -0 (DAZ)", ts_floorf(nden), -0.0f);
  check_f("floor(1e10) = 1e10", ts_floorf(1e10f), 1e10f);
  check_f("fract(1.25) = 0.25", ts_fractf(1.25f), 0.25f);
  check_f("fract(-0.25) = 0.75", ts_fractf(-0.25f), 0.75f);
  check_f("fract(-2^-26) = 1.0 (not clamped)", ts_fractf(-0x1p-26f), 1.0f);
  check_f("abs(-0) = +0", ts_absf(-0.0f), 0.0f);
  check_f("abs(-2) = 2", ts_absf(-2.0f), 2.0f);
  check_f("step(0.5,0.5) = 1", ts_stepf(0.5f, 0.5f), 1.0f);
  check_f("step(0.5,0.25) = 0", ts_stepf(0.5f, 0.25f), 0.0f);
  check_f("step(0.5,NaN) = 0", ts_stepf(0.5f, qnan), 0.0f);
  check_f("step(NaN,1) = 0", ts_stepf(qnan, 1.0f), 0.0f);
}

static void test_vectors(void) {
  ts_vec3f a = ts_v3f(1.0f, 1e8f, -1e8f), one = ts_v3f(1.0f, 1.0f, 1.0f), n;
  ts_vec4f a4 = ts_v4f(1.0f, 1.0f, 1e8f, -1e8f), one4 = ts_v4f(1.0f, 1.0f, 1.0f, 1.0f);
  ts_vec3d nd;

  /* (x0 + (x1 + x2)) = 1, whereas ((x0 + x1) + x2) would give 0 */
  check_f("dot3 order x0*y0 + (x1*y1 + x2*y2)", ts_dot3f(a, one), 1.0f);
  check_f("dot4 order x0*y0 + (x1*y1 + (x2*y2 + x3*y3))", ts_dot4f(a4, one4), 2.0f);
  check_f("dot2", ts_dot2f(ts_v2f(3.0f, 4.0f), ts_v2f(2.0f, 0.5f)), 8.0f);
  check_f("length(3,4,0) = 5", ts_length3f(ts_v3f(3.0f, 4.0f, 0.0f)), 5.0f);
  check_f("length(1e20,1e20,0) = inf (no scaling)", ts_length3f(ts_v3f(1e20f, 1e20f, 0.0f)), INFINITY);
  n = ts_normalize3f(ts_v3f(0.0f, 0.0f, 0.0f));
  check_true("normalize(0) = NaN", n.x != n.x && n.y != n.y && n.z != n.z, "components not NaN");
  n = ts_normalize3f(ts_v3f(3.0f, 0.0f, 4.0f));
  check_f("normalize(3,0,4).x = 3 * (1/sqrt(25))", n.x, 3.0f * (1.0f / 5.0f));
  n = ts_normalize3f(ts_v3f(-2.0f, 7.0f, 0.5f));
  check_true("normalize unit length", fabsf(ts_length3f(n) - 1.0f) < 3e-7f, "|n| != 1");
  nd = ts_normalize3d(ts_v3d(-2.0, 7.0, 0.5));
  check_true("normalize f vs d within 4e-7",
             fabs(n.x - nd.x) < 4e-7 && fabs(n.y - nd.y) < 4e-7 && fabs(n.z - nd.z) < 4e-7,
             "float normalize far from double");
  check_true("saturate3 / max3 / min3 / neg3",
             ts_saturate3f(ts_v3f(-1.0f, 0.5f, 9.0f)).z == 1.0f &&
                 ts_max3f(ts_v3f(1, 2, 3), ts_v3f(3, 2, 1)).x == 3.0f &&
                 ts_min3f(ts_v3f(1, 2, 3), ts_v3f(3, 2, 1)).z == 1.0f && ts_neg3f(ts_v3f(1, -2, 0)).y == 2.0f,
             "componentwise op wrong");
  check_true("add/sub/mul/scale 3 and 4",
             ts_add3f(one, one).y == 2.0f && ts_sub3f(one, one).z == 0.0f && ts_mul3f(ts_v3f(2, 3, 4), one).z == 4.0f &&
                 ts_scale3f(one, 3.0f).x == 3.0f && ts_add4f(one4, one4).w == 2.0f && ts_sub4f(one4, one4).x == 0.0f &&
                 ts_mul4f(one4, ts_v4f(1, 2, 3, 4)).w == 4.0f && ts_scale4f(one4, 2.0f).y == 2.0f &&
                 ts_saturate4f(ts_v4f(-1, 2, 0.5f, 0)).y == 1.0f,
             "componentwise op wrong");
  check_f("pow3 componentwise", ts_pow3f(ts_v3f(2, 3, 4), ts_v3f(3, 0, 0.5f)).x, ts_powf(2, 3));
}

static void test_double(void) {
  check_d("exp2d(3) = 8", ts_exp2d(3.0), 8.0, 0.0);
  check_d("log2d(1024) = 10", ts_log2d(1024.0), 10.0, 0.0);
  check_d("powd(0,0) = 1 (libm)", ts_powd(0.0, 0.0), 1.0, 0.0);
  check_d("powd(2.5,3.5)", ts_powd(2.5, 3.5), 24.705294220065465, 1e-12);
  check_d("expd(1)", ts_expd(1.0), 2.718281828459045, 1e-15);
  check_d("logd(e)", ts_logd(2.718281828459045), 1.0, 1e-15);
  check_d("inversesqrtd(4) = 0.5", ts_inversesqrtd(4.0), 0.5, 0.0);
  check_d("maxd(NaN,1) = 1", ts_maxd(NAN, 1.0), 1.0, 0.0);
  check_d("mind(1,NaN) = 1", ts_mind(1.0, NAN), 1.0, 0.0);
  check_d("clampd(NaN,0,1) = 0", ts_clampd(NAN, 0.0, 1.0), 0.0, 0.0);
  check_d("saturated(1.5) = 1", ts_saturated(1.5), 1.0, 0.0);
  check_d("signd(NaN) = 0", ts_signd(NAN), 0.0, 0.0);
  check_d("fractd(-0.25) = 0.75", ts_fractd(-0.25), 0.75, 0.0);
  check_d("stepd(1,NaN) = 0", ts_stepd(1.0, NAN), 0.0, 0.0);
  check_d("dot3d", ts_dot3d(ts_v3d(1, 2, 3), ts_v3d(4, 5, 6)), 32.0, 0.0);
  check_d("length3d(2,3,6) = 7", ts_length3d(ts_v3d(2, 3, 6)), 7.0, 0.0);
  check_d("dot4d", ts_dot4d(ts_v4d(1, 2, 3, 4), ts_v4d(1, 1, 1, 1)), 10.0, 0.0);
  check_d("dot2d", ts_dot2d(ts_v2d(1, 2), ts_v2d(3, 4)), 11.0, 0.0);
}

/* ------------------------------------------------------------------------ */
/* sampler                                                                   */
/* ------------------------------------------------------------------------ */

static float g_tex[37 * 23 * 4];

static void fill_const(float *t, int n, float v) {
  int i;
  for (i = 0; i < n * 4; i++) t[i] = v + (float)(i % 4); /* per-channel constant */
}

static void fill_ramp(float *t, int w, int h) {
  int x, y, c;
  for (y = 0; y < h; y++)
    for (x = 0; x < w; x++)
      for (c = 0; c < 4; c++) t[(y * w + x) * 4 + c] = (float)(y * 100 + x) + 0.25f * (float)c;
}

static void test_sampler_2d(int fused) {
  static const int sizes[3][2] = {{16, 8}, {37, 23}, {1, 1}};
  const char *m = fused ? "fused" : "unfused";
  char name[128];
  int si, wrap, filt, i, bad;
  ts_tex2d t;
  ts_math_set_fused(fused);

  for (si = 0; si < 3; si++)
    for (wrap = 0; wrap < 2; wrap++)
      for (filt = 0; filt < 2; filt++) {
        t.w = sizes[si][0];
        t.h = sizes[si][1];
        t.texels = g_tex;
        t.wrap_s = t.wrap_t = wrap;
        t.filter = filt;
        fill_const(g_tex, t.w * t.h, 0.3f);
        for (bad = 0, i = 0; i < 2000; i++) {
          float u = -3.0f + 0.0037f * (float)i, v = 2.5f - 0.0029f * (float)i;
          ts_vec4f r = ts_texture2Df(&t, ts_v2f(u, v));
          ts_vec4d rd = ts_texture2Dd(&t, ts_v2d(u, v));
          if (!same_bits(r.x, 0.3f) || !same_bits(r.y, 1.3f) || !same_bits(r.z, 2.3f) || !same_bits(r.w, 3.3f)) bad++;
          if (fabs(rd.x - (double)0.3f) > 1e-15 || fabs(rd.w - (double)3.3f) > 1e-15) bad++;
        }
        snprintf(name, sizeof name, "%s of constant %dx%d %s texture = constant (%s)", filt ? "bilinear" : "nearest",
                 t.w, t.h, wrap ? "CLAMP" : "REPEAT", m);
        check_true(name, bad == 0, "sample differs from the constant");
      }

  /* texel centres return the texel exactly (POT: all coordinates exact) */
  t.w = 16;
  t.h = 8;
  t.texels = g_tex;
  fill_ramp(g_tex, 16, 8);
  for (filt = 0; filt < 2; filt++)
    for (wrap = 0; wrap < 2; wrap++) {
      int x, y;
      t.filter = filt;
      t.wrap_s = t.wrap_t = wrap;
      for (bad = 0, y = 0; y < 8; y++)
        for (x = 0; x < 16; x++) {
          ts_vec4f r = ts_texture2Df(&t, ts_v2f(((float)x + 0.5f) / 16.0f, ((float)y + 0.5f) / 8.0f));
          if (!same_bits(r.y, g_tex[(y * 16 + x) * 4 + 1])) bad++;
        }
      snprintf(name, sizeof name, "%s %s at texel centres = texel (%s)", filt ? "bilinear" : "nearest",
               wrap ? "CLAMP" : "REPEAT", m);
      check_true(name, bad == 0, "centre sample != texel");
    }

  /* wrap behaviour */
  t.filter = TS_FILTER_NEAREST;
  t.wrap_s = t.wrap_t = TS_WRAP_REPEAT;
  check_f("nearest REPEAT u+1 wraps", ts_texture2Df(&t, ts_v2f(1.0f + 3.5f / 16.0f, 0.0625f)).x,
          g_tex[(0 * 16 + 3) * 4]);
  check_f("nearest REPEAT u=-1/32 -> last column", ts_texture2Df(&t, ts_v2f(-1.0f / 32.0f, 0.0625f)).x,
          g_tex[(0 * 16 + 15) * 4]);
  t.wrap_s = t.wrap_t = TS_WRAP_CLAMP;
  check_f("nearest CLAMP u=-5 -> column 0", ts_texture2Df(&t, ts_v2f(-5.0f, 0.0625f)).x, g_tex[0]);
  check_f("nearest CLAMP u=7 -> last column", ts_texture2Df(&t, ts_v2f(7.0f, 0.0625f)).x, g_tex[15 * 4]);
  t.filter = TS_FILTER_LINEAR;
  check_f("bilinear CLAMP midpoint of two texels", ts_texture2Df(&t, ts_v2f(1.0f / 16.0f, 0.0625f)).x,
          0.5f * (g_tex[0] + g_tex[4]));
  /* NaN coordinates must not read out of bounds (ASan) */
  (void)ts_texture2Df(&t, ts_v2f(NAN, INFINITY));
  t.wrap_s = t.wrap_t = TS_WRAP_REPEAT;
  (void)ts_texture2Df(&t, ts_v2f(NAN, -INFINITY));
  t.w = 37;
  t.h = 23;
  t.filter = TS_FILTER_NEAREST;
  (void)ts_texture2Df(&t, ts_v2f(NAN, 1e30f));
  t.filter = TS_FILTER_LINEAR;
  (void)ts_texture2Df(&t, ts_v2f(-INFINITY, NAN));
  (void)ts_texture2Dd(&t, ts_v2d(NAN, 1e300));
  check_true("NaN/inf coordinates stay in bounds", 1, "");
}

static void test_texel_fetch(void) {
  ts_tex2d t;
  ts_vec4f r;
  t.w = 37;
  t.h = 23;
  t.texels = g_tex;
  t.wrap_s = t.wrap_t = 0;
  t.filter = 0;
  fill_ramp(g_tex, 37, 23);
  r = ts_texelFetchf(&t, 36, 22);
  check_f("texelFetch(36,22)", r.z, g_tex[(22 * 37 + 36) * 4 + 2]);
  r = ts_texelFetchf(&t, 37, 0);
  check_true("texelFetch out of range -> 0", r.x == 0 && r.y == 0 && r.z == 0 && r.w == 0, "not zero");
  r = ts_texelFetchf(&t, -1, 5);
  check_true("texelFetch negative -> 0", r.x == 0 && r.w == 0, "not zero");
}

static float g_faces[6][4 * 4 * 4];

static void test_cube(void) {
  static const float dirs[][3] = {
      {1, 0, 0},     {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}, /* tie: Z wins */
      {1, 1, 0}, /* |x| == |y|: Y wins */
      {-1, 0.5f, 0}, /* X */
      {0, 0, 0}, /* zero: +Z centre */
      {0, 0, -0.0f}, /* sign bit of the major axis: -Z */
  };
  static const int want[] = {0, 1, 2, 3, 4, 5, 4, 2, 1, 4, 5};
  ts_texcube c;
  int f, i, filt;
  char name[96];

  c.size = 4;
  for (f = 0; f < 6; f++) {
    for (i = 0; i < 4 * 4 * 4; i++) g_faces[f][i] = (float)f;
    c.faces[f] = g_faces[f];
  }
  for (filt = 0; filt < 2; filt++) {
    c.filter = filt;
    for (i = 0; i < (int)(sizeof want / sizeof want[0]); i++) {
      ts_vec4f r = ts_textureCubef(&c, ts_v3f(dirs[i][0], dirs[i][1], dirs[i][2]));
      ts_vec4d rd = ts_textureCubed(&c, ts_v3d(dirs[i][0], dirs[i][1], dirs[i][2]));
      snprintf(name, sizeof name, "cube %s face for (%g,%g,%g%s) = %d", filt ? "LINEAR" : "NEAREST", dirs[i][0],
               dirs[i][1], dirs[i][2], signbit(dirs[i][2]) ? " (-0)" : "", want[i]);
      check_true(name, r.x == (float)want[i] && rd.x == (double)want[i], "wrong face");
    }
  }
  /* orientation: +X at (1, 0.5, 0.5): s = (-z/|x| + 1)/2 = 0.25, t = (-y/|x| + 1)/2 = 0.25 */
  for (i = 0; i < 16; i++) g_faces[0][i * 4] = (float)i;
  c.filter = TS_FILTER_NEAREST;
  check_f("cube +X orientation (s,t)=(0.25,0.25) -> texel (1,1)", ts_textureCubef(&c, ts_v3f(1.0f, 0.5f, 0.5f)).x,
          5.0f);
  check_f("cube +X orientation (s,t)=(0.75,0.75) -> texel (3,3)", ts_textureCubef(&c, ts_v3f(1.0f, -0.5f, -0.5f)).x,
          15.0f);
  (void)ts_textureCubef(&c, ts_v3f(NAN, INFINITY, -0.0f)); /* must stay in bounds */
  c.filter = TS_FILTER_LINEAR;
  (void)ts_textureCubef(&c, ts_v3f(-INFINITY, NAN, 1.0f));
}

int main(void) {
  ts_math_init();
  printf("# host fused mads: %d\n", ts_math_fused());
  {
    int fused = ts_math_fused();
    test_state();
    test_exp_log(0);
    test_exp_log(1);
    test_specials();
    test_vectors();
    test_double();
    test_sampler_2d(0);
    test_sampler_2d(1);
    test_texel_fetch();
    test_cube();
    ts_math_set_fused(fused);
  }
  printf("# %d passed, %d failed\n", g_passed, g_failed);
  return g_failed ? 1 : 0;
}

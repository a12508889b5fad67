/* tiershade math: interval arithmetic of the GLSL ES 3.00 highp precision rules, the third
 * instance of the C twins (ts_generic_interval.h: TS_SUFFIX iv, TS_REAL ts_iv). Every operation
 * returns an interval of float32 values that contains every result a conformant implementation
 * may give for any inputs inside its operands' intervals (ESSL 3.00 section 4.5.1 and the CTS,
 * VK-GL-CTS modules/glshared/glsBuiltinPrecisionTests.cpp, table in ../shared/docs/anchors.md):
 *   + - *        correctly rounded: either neighbour of the exact result (exact if representable)
 *   a / b        2.5 ULP of the exact quotient
 *   inversesqrt  2 ULP; sqrt derived as 1 / inversesqrt(x)
 *   exp2         (3 + 2|x|) ULP;  log2: absolute 2^-21 in [0.5, 2], else 3 ULP; x <= 0: any
 *   pow          derived: exp2(y * log2(x))
 *   dot          any summation order, any products fused or not (a widened exact sum)
 *   min/max/clamp/step: exact on numbers; an operand that may be NaN gives "any result"
 * Denormals may be flushed (ESSL 3.00 4.5.1): an operand or a result that touches the denormal
 * range also admits 0. Overflow admits Inf. `nan` = NaN is among the admitted results; an
 * interval with lo > hi admits no number (only NaN, when nan is set). docs/conformance.md. */
#ifndef TS_INTERVAL_H
#define TS_INTERVAL_H

#include "math/ts_math.h"
#include "math/ts_sampler.h"
#include "math/ts_sampler3d.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  float lo, hi; /* every admitted number x has lo <= x <= hi (-0 == +0) */
  int nan;      /* NaN admitted */
} ts_iv;

typedef struct {
  ts_iv x, y;
} ts_vec2iv;
typedef struct {
  ts_iv x, y, z;
} ts_vec3iv;
typedef struct {
  ts_iv x, y, z, w;
} ts_vec4iv;

/* comparison outcome of an interval test: surely false, surely true, or either */
enum { TS_IV_FALSE = 0, TS_IV_TRUE = 1, TS_IV_EITHER = 2 };

/* ---- the precision: highp (the default) or mediump, process-wide: set it before evaluating ----
 * mediump applies the CTS's mediump rules (FloatFormat(-13, 13, 9 bits): every result and every
 * input rounded outward to 9 fraction bits, normals from 2^-13, overflow past (2 - 2^-9) 2^13 to
 * Inf; exp2 (2 + 2|x|) ULP, log2 2 ULP or absolute 2^-7 in [0.5, 2], ULPs of that format). The
 * intervals then hold fp16 results (llvmpipe's mediump on GLES) and float32 ones (SwiftShader's). */
void ts_iv_set_mediump(int on);
int ts_iv_mediump(void);

/* ---- construction and queries ---- */
ts_iv ts_ivpoint(float x);        /* {x} (a NaN x gives the NaN-only interval) */
ts_iv ts_ivrange(float lo, float hi);
ts_iv ts_ivany(void);             /* every float and NaN: "undefined" */
ts_iv ts_ivjoin(ts_iv a, ts_iv b); /* hull of the union */
int ts_ivcontains(ts_iv a, float x);
/* width of a in float32 ULPs (number of floats strictly between lo and hi plus one; 0 for a
 * point; UINT32 max-ish for an interval reaching Inf or admitting NaN) */
double ts_ivwidth_ulp(ts_iv a);
/* how far x lies outside a, in float32 ULPs (0 inside) */
double ts_ivexcess_ulp(ts_iv a, float x);
/* widens a by n float ULPs at each end (n >= 0), FTZ rule applied */
ts_iv ts_ivwiden(ts_iv a, int n);
/* a = one form of mix(x, y, t), widened to contain every form an implementation may compute
 * (ts_interval_logic.c; ts_generic.h ALT_LERP) */
ts_iv ts_ivlerp_forms(ts_iv a, ts_iv x, ts_iv y, ts_iv t);

/* ---- arithmetic (names follow ts_generic.h: M(add) -> ts_addiv) ---- */
ts_iv ts_addiv(ts_iv a, ts_iv b);
ts_iv ts_subiv(ts_iv a, ts_iv b);
ts_iv ts_muliv(ts_iv a, ts_iv b);
ts_iv ts_diviv(ts_iv a, ts_iv b);
ts_iv ts_negiv(ts_iv a);

/* ---- comparisons and selection: x OP y as TS_IV_FALSE/TRUE/EITHER (NaN: EITHER) ---- */
int ts_leiv(ts_iv a, ts_iv b);
int ts_ltiv(ts_iv a, ts_iv b);
int ts_geiv(ts_iv a, ts_iv b);
int ts_gtiv(ts_iv a, ts_iv b);
ts_iv ts_seliv(int c, ts_iv a, ts_iv b); /* c ? a : b; EITHER joins both */
ts_vec3iv ts_sel3iv(int c, ts_vec3iv a, ts_vec3iv b);

/* more outcomes: ==, != (either when an interval is not one point), and ||, && of outcomes */
int ts_eqiv(ts_iv a, ts_iv b);
int ts_neiv(ts_iv a, ts_iv b);
int ts_notiv(int c);
int ts_oriv(int a, int b);
int ts_andiv(int a, int b);
ts_vec4iv ts_sel4iv(int c, ts_vec4iv a, ts_vec4iv b);
/* int(x) (truncation) when every admitted value gives the same int, else TS_IV_UNSURE_INT */
#define TS_IV_UNSURE_INT (-2147483647 - 1)
int ts_ivtoint(ts_iv x);
ts_vec4iv ts_v4ivany(void); /* every result in each channel */

/* ---- builtins ---- */
ts_iv ts_exp2iv(ts_iv x);
ts_iv ts_log2iv(ts_iv x);
ts_iv ts_powiv(ts_iv x, ts_iv y);
ts_iv ts_sqrtiv(ts_iv x);
ts_iv ts_inversesqrtiv(ts_iv x);
ts_iv ts_miniv(ts_iv a, ts_iv b);
ts_iv ts_maxiv(ts_iv a, ts_iv b);
ts_iv ts_clampiv(ts_iv x, ts_iv lo, ts_iv hi);
ts_iv ts_saturateiv(ts_iv x);
ts_iv ts_stepiv(ts_iv edge, ts_iv x);
ts_iv ts_absiv(ts_iv x);
ts_iv ts_flooriv(ts_iv x);

/* ---- vectors ---- */
ts_vec2iv ts_v2iv(ts_iv x, ts_iv y);
ts_vec3iv ts_v3iv(ts_iv x, ts_iv y, ts_iv z);
ts_vec4iv ts_v4iv(ts_iv x, ts_iv y, ts_iv z, ts_iv w);
ts_iv ts_dot3iv(ts_vec3iv a, ts_vec3iv b);
ts_vec3iv ts_add3iv(ts_vec3iv a, ts_vec3iv b);
ts_vec3iv ts_sub3iv(ts_vec3iv a, ts_vec3iv b);
ts_vec3iv ts_mul3iv(ts_vec3iv a, ts_vec3iv b);
ts_vec3iv ts_scale3iv(ts_vec3iv v, ts_iv s);
ts_vec3iv ts_saturate3iv(ts_vec3iv v);
ts_vec3iv ts_normalize3iv(ts_vec3iv v);
ts_vec3iv ts_neg3iv(ts_vec3iv v);
ts_vec3iv ts_max3iv(ts_vec3iv a, ts_vec3iv b);
ts_vec3iv ts_min3iv(ts_vec3iv a, ts_vec3iv b);

/* ---- texture lookups: every value a lookup may give with the coordinate and weight precision
 * of dEQP's tcuTexLookupVerifier as the GLES 3 filtering tests set it (coordBits 20, uvwBits 7;
 * ts_interval.c); a coordinate range over more than two texel cells: the hull of the texels. ---- */
ts_vec4iv ts_texture2Div(const ts_tex2d *t, ts_vec2iv uv);
/* with derivatives (ts_texture2D_gradf) on a mip chain: GLSL ES leaves the level of detail's
 * computation to the implementation within wide limits, so the hull of every level's lookup. */
ts_vec4iv ts_texture2D_gradiv(const ts_tex2d *t, ts_vec2iv uv, const ts_vec4f *grad);
/* explicit derivatives (ts_texture2DGradf): every level the GLES 3.0 LOD rules (3.8.10: any rho
 * between max(m_u, m_v) and m_u + m_v, log2 within 1/16) select for the pixel's (dPdx, dPdy); a
 * non-finite derivative: every level. ts_sampler_grad.c */
ts_vec4iv ts_texture2DGradiv(const ts_tex2d *t, ts_vec2iv uv, ts_vec4f dpdx_dpdy);
/* cube: every face the direction box can select (dEQP getPossibleCubeFaces), each as a 2D
 * CLAMP_TO_EDGE lookup of the face coordinates; seamless filtering at face edges covered; a box
 * holding the zero vector: any result. 3D: the 2D rule on three axes (trilinear). ts_interval.c */
ts_vec4iv ts_textureCubeiv(const ts_texcube *c, ts_vec3iv dir);
ts_vec4iv ts_texture3Div(const ts_tex3d *t, ts_vec3iv uvw);

#ifdef __cplusplus
}
#endif
#endif /* TS_INTERVAL_H */

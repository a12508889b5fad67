/* tiershade math: write a shader twin once, instantiate it twice.
 * A generic twin (files named like their GLSL: common_lights.h <-> common_lights.glsl)
 * is included once with TS_SUFFIX f / TS_REAL float (the llvmpipe-exact float32
 * reference) and once with TS_SUFFIX d / TS_REAL double (the accuracy reference).
 *   M(dot3)   -> ts_dot3f / ts_dot3d        (math layer, c_ref/math/ts_math.h)
 *   V3, V4    -> ts_vec3f / ts_vec3d ...
 *   FN(name)  -> name_f / name_d            (twin-local functions)
 *   K(0.5)    -> 0.5f / 0.5                 (literals parsed like GLSL's strtof)
 *   SPLAT(k)  -> k                          (a constant operand; on SIMD lanes, ts_generic_lanes.h,
 *                                            the constant in every lane)
 * A third instance, ts_generic_interval.h (TS_SUFFIX iv, TS_REAL ts_iv, c_ref/math/ts_interval.h),
 * gives the interval of results GLSL ES 3.00 allows. C has no operators on a struct, so a twin
 * that has an interval instance writes its arithmetic on TS_REAL through these (TS_OPS plain:
 * the C operator itself, token for token, so the float and double instances do not change):
 *   ADD(a, b) SUB MUL DIV    -> ((a) + (b)) ...      / ts_addiv(a, b) ...
 *   NEG(a)                   -> (-(a))               / ts_negiv(a)
 *   LE(a, b) LT GE GT        -> ((a) <= (b)) ...     / ts_leiv(a, b): false, true or either
 *   SEL(c, a, b)             -> ((c) ? (a) : (b))    / ts_seliv(c, a, b): c either joins a and b
 *   SEL3(c, a, b)            -> the same on a V3
 *   FROMF(x)                 -> ((TS_REAL)(x))       / ts_ivpoint(x): a float32 input as a TS_REAL
 *   KC(0.5)                  -> K(0.5)               / {0.5f, 0.5f, 0}: a literal in a static table (a
 *                                                      normal non-zero number: its own point interval)
 *   EQ(a, b) NE              -> ((a) == (b)) ...     / ts_eqiv(a, b): false, true or either
 *   OR(c, d) AND(c, d)       -> ((c) || (d)) ...     / ts_oriv(c, d) on those outcomes (C's 0 / 1
 *                                                      are TS_IV_FALSE / TS_IV_TRUE)
 *   SEL4(c, a, b)            -> the same as SEL on a V4
 *   TOINT(x)                 -> ((int)(x))           / ts_ivtoint(x): TS_IV_UNSURE_INT unless one int
 *   ANY_IF(c, v)             -> (v)                  / c ? every V4 : v (c is not even compiled in
 *                                                      the float and double instances)
 *   ALT_LERP(a, x, y, t)     -> (a)                  / ts_ivlerp_forms(a, x, y, t): a is mix(x, y, t) in
 *                                                      llvmpipe's form; the interval widens it to every
 *                                                      form an implementation may compute (x (1 - t) +
 *                                                      y t, x + (y - x) t); x, y, t are not even
 *                                                      compiled in the float and double instances
 * A value-dependent `if` becomes a SEL of both outcomes (both are evaluated in the interval
 * instance; plain SEL evaluates one, like ?:). Comparisons whose interval straddles the threshold
 * thus take both branches and join them (issue 14).
 * Operation order in a twin mirrors the GLSL statement by statement: float32
 * arithmetic is not associative, and the reference is bit-exact (0 ULP). */
#ifndef TS_GENERIC_H
#define TS_GENERIC_H
#define TS_CAT_(a, b) a##b
#define TS_CAT(a, b) TS_CAT_(a, b)
#define M(name) TS_CAT(TS_CAT(ts_, name), TS_SUFFIX)
#define FN(name) TS_CAT(TS_CAT(name, _), TS_SUFFIX)
#define V2 M(vec2)
#define V3 M(vec3)
#define V4 M(vec4)
#define K(x) TS_CAT(TS_K_, TS_OPS)(TS_CAT(x, TS_LIT))
#define SPLAT(x) (x)

#define TS_K_plain(v) v
#define TS_K_iv(v) ts_ivpoint(v)
#define TS_OP2_plain(name, op, a, b) ((a) op (b))
#define TS_OP2_iv(name, op, a, b) M(name)(a, b)
#define ADD(a, b) TS_CAT(TS_OP2_, TS_OPS)(add, +, a, b)
#define SUB(a, b) TS_CAT(TS_OP2_, TS_OPS)(sub, -, a, b)
#define MUL(a, b) TS_CAT(TS_OP2_, TS_OPS)(mul, *, a, b)
#define DIV(a, b) TS_CAT(TS_OP2_, TS_OPS)(div, /, a, b)
#define LE(a, b) TS_CAT(TS_OP2_, TS_OPS)(le, <=, a, b)
#define LT(a, b) TS_CAT(TS_OP2_, TS_OPS)(lt, <, a, b)
#define GE(a, b) TS_CAT(TS_OP2_, TS_OPS)(ge, >=, a, b)
#define GT(a, b) TS_CAT(TS_OP2_, TS_OPS)(gt, >, a, b)
#define TS_NEG_plain(a) (-(a))
#define TS_NEG_iv(a) ts_negiv(a)
#define NEG(a) TS_CAT(TS_NEG_, TS_OPS)(a)
#define TS_SEL_plain(c, a, b) ((c) ? (a) : (b))
#define TS_SEL_iv(c, a, b) ts_seliv(c, a, b)
#define TS_SEL3_iv(c, a, b) ts_sel3iv(c, a, b)
#define SEL(c, a, b) TS_CAT(TS_SEL_, TS_OPS)(c, a, b)
#define SEL3(c, a, b) TS_CAT(TS_SEL3_, TS_OPS)(c, a, b)
#define TS_SEL3_plain TS_SEL_plain
#define TS_FROMF_plain(x) ((TS_REAL)(x))
#define TS_FROMF_iv(x) ts_ivpoint(x)
#define FROMF(x) TS_CAT(TS_FROMF_, TS_OPS)(x)
#define TS_KC_plain(v) v
#define TS_KC_iv(v) {v, v, 0}
#define KC(x) TS_CAT(TS_KC_, TS_OPS)(TS_CAT(x, TS_LIT))
#define EQ(a, b) TS_CAT(TS_OP2_, TS_OPS)(eq, ==, a, b)
#define NE(a, b) TS_CAT(TS_OP2_, TS_OPS)(ne, !=, a, b)
#define TS_LOG2_plain(name, op, a, b) ((a) op (b))
#define TS_LOG2_iv(name, op, a, b) ts_##name##iv(a, b)
#define OR(a, b) TS_CAT(TS_LOG2_, TS_OPS)(or, ||, a, b)
#define AND(a, b) TS_CAT(TS_LOG2_, TS_OPS)(and, &&, a, b)
#define TS_SEL4_plain TS_SEL_plain
#define TS_SEL4_iv(c, a, b) ts_sel4iv(c, a, b)
#define SEL4(c, a, b) TS_CAT(TS_SEL4_, TS_OPS)(c, a, b)
#define TS_TOINT_plain(x) ((int)(x))
#define TS_TOINT_iv(x) ts_ivtoint(x)
#define TOINT(x) TS_CAT(TS_TOINT_, TS_OPS)(x)
#define TS_ANY_IF_plain(c, v) (v)
#define TS_ANY_IF_iv(c, v) ((c) ? ts_v4ivany() : (v))
#define ANY_IF(c, v) TS_CAT(TS_ANY_IF_, TS_OPS)(c, v)
#define TS_ALT_LERP_plain(a, x, y, t) (a)
#define TS_ALT_LERP_iv(a, x, y, t) ts_ivlerp_forms(a, x, y, t)
#define ALT_LERP(a, x, y, t) TS_CAT(TS_ALT_LERP_, TS_OPS)(a, x, y, t)
#endif

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
#define K(x) TS_CAT(x, TS_LIT)
#define SPLAT(x) (x)
#endif

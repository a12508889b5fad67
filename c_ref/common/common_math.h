/* tiershade common: generic twin of shaders/common_math.glsl (see ts_generic.h).
 * Included once per precision; no include guard on purpose. */

/* TS_MIN_LENGTH2 = 1.0e-30: zero-length vectors normalise to 0, not NaN. Not an fp16 number:
 * 0 in fp16, where a zero vector gives NaN (shaders/common_math.glsl); the twins are float32
 * and double only, like the highp shaders they mirror. */
/* TS_POW_TINY = 2^-60 (shaders/common_math.glsl): the least base of a pow() whose base may be 0,
 * which GLSL ES leaves undefined (issue 14). */
#ifndef TS_POW_TINY_C
#define TS_POW_TINY_C 0x1p-60
#endif

static inline V3 FN(safe_normalize)(V3 v) { return M(scale3)(v, M(inversesqrt)(M(max)(M(dot3)(v, v), K(1.0e-30)))); }

static inline V3 FN(xyz)(ts_vec4f v) { return M(v3)(FROMF(v.x), FROMF(v.y), FROMF(v.z)); }
static inline V4 FN(vec4_in)(ts_vec4f v) { return M(v4)(FROMF(v.x), FROMF(v.y), FROMF(v.z), FROMF(v.w)); }
static inline V3 FN(xyz4)(V4 v) { return M(v3)(v.x, v.y, v.z); }

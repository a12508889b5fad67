//------------------------------------------------------------------------------
// common_math.glsl: constants and small helpers shared by every tiershade shader.
// C twin: c_ref/common/common_math.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_MATH_GLSL
#define TS_COMMON_MATH_GLSL

#define saturate(x) clamp(x, 0.0, 1.0)

// Largest finite half float: the top of every HDR output range (fact sheet section 7, maxfloat16bits).
#define TS_FP16_MAX 65504.0

// Smallest squared length treated as non-zero. A normal float (> FLT_MIN) so that
// inversesqrt stays finite; zero and denormal lengths (flushed to zero by llvmpipe,
// ../shared/docs/platform_notes.md section 4) map the vector to 0 instead of NaN.
#define TS_MIN_LENGTH2 1.0e-30

// normalize() that returns 0 for a zero-length vector (normalize(0) is NaN on llvmpipe).
vec3 ts_safe_normalize(vec3 v) {
    return v * inversesqrt(max(dot(v, v), TS_MIN_LENGTH2));
}

#endif

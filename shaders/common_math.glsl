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
// fp16: NOT a half-float number (the smallest fp16 subnormal is 2^-24, about 6e-8). Where
// mediump floats are computed in fp16 (llvmpipe on GLES; the mediump rows of
// docs/accuracy_cost.md) the constant becomes 0, so the guard is gone: a zero-length vector
// gives inversesqrt(0) = Inf and 0 * Inf = NaN, and any length below about 2.4e-4 (whose
// square is under 2^-24) counts as zero. highp, which every conformed variant uses, keeps it.
#define TS_MIN_LENGTH2 1.0e-30

// normalize() that returns 0 for a zero-length vector (normalize(0) is NaN on llvmpipe).
vec3 ts_safe_normalize(vec3 v) {
    return v * inversesqrt(max(dot(v, v), TS_MIN_LENGTH2));
}

#endif

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

// The least base of every pow() whose base may reach 0 (issue 14): GLSL ES leaves pow(0, y)
// undefined (ESSL 3.00 section 8.2: pow = exp2(y * log2(x)), and log2(0) is undefined), so
// implementations differ there (llvmpipe 0, SwiftShader 4.2e-18 for pow(0, 0.4545)) and the error
// bounds admit anything. pow(max(x, TS_POW_TINY), y) is defined everywhere. 2^-60: a normal float
// inside ESSL 1.00's guaranteed highp range (2^-62..2^62, section 4.5.2), so WebGL 1 keeps it too,
// and small enough that no stored colour changes: for every exponent tiershade raises a base to
// that may be 0, y >= 1/2.2 (gamma 2.2 output), 2^(-60 y) <= 2^-27.3 = 6.2e-9, below half the
// smallest step of an RGBA8 target (1/510) and of an fp16 one (half its smallest subnormal,
// 2^-25); Phong and rim (k >= 1) give <= 2^-60 times the light, the LDR lightmap decode (y = 2.2)
// 2^-132, i.e. 0 after FTZ. Only bases <= 2^-60 change (0, negative, NaN; denormals are 0 on
// llvmpipe already). fp16 (mediump): 0 there, so the guard is gone, as for TS_MIN_LENGTH2.
// C twin: K(0x1p-60) in c_ref/common (TS_POW_TINY_C there).
#define TS_POW_TINY 8.6736174e-19

// normalize() that returns 0 for a zero-length vector (normalize(0) is NaN on llvmpipe).
vec3 ts_safe_normalize(vec3 v) {
    return v * inversesqrt(max(dot(v, v), TS_MIN_LENGTH2));
}

#endif

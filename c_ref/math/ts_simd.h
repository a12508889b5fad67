/* tiershade math: the llvmpipe-exact float32 math layer (c_ref/math/ts_math.c) on TSV_W lanes at once, with GCC
 * vector extensions plus a few x86 intrinsics. Included once per instruction set by a
 * *_batch.c file (no include guard), inside a `#pragma GCC target` region, with:
 *   TSV_W      4 (SSE2) or 8 (AVX2)
 *   TSV_SFX    suffix of every function of this instance (e.g. avx2fma)
 *   TSV_FUSED  1: gallivm mads are one FMA (the host has FMA and llvmpipe uses it), 0: a*b + c
 *   TSV_AVX    1: 256-bit intrinsics (AVX2), 0: 128-bit SSE2 intrinsics (software floor)
 * Every function gives, lane by lane, the bits of its scalar ts_*f twin: same operations in the
 * same order, the scalar branches written as selects (both sides are computed, as in llvmpipe's
 * SIMD code). It relies on MXCSR FTZ|DAZ (ts_math_init()) exactly like the scalar layer; the
 * hardware compares, minps/maxps and roundps then apply DAZ themselves.
 * Checked bit for bit against the scalar twin by tests/unit/test_fast_path.cpp. */

#define TSV_CAT_(a, b) a##b
#define TSV_CAT(a, b) TSV_CAT_(a, b)
#define VFN(name) TSV_CAT(TSV_CAT(name, _), TSV_SFX)
#define TSV_INL static inline __attribute__((always_inline))

#ifndef TSV_TYPES_
#define TSV_TYPES_
typedef float tsv_f8 __attribute__((vector_size(32)));
typedef int tsv_i8 __attribute__((vector_size(32)));
typedef unsigned tsv_u8 __attribute__((vector_size(32)));
typedef float tsv_f4 __attribute__((vector_size(16)));
typedef int tsv_i4 __attribute__((vector_size(16)));
typedef unsigned tsv_u4 __attribute__((vector_size(16)));
#endif
/* This instance's lanes: tsv_f8, tsv_i8, tsv_u8 (TSV_W 8) or tsv_f4, tsv_i4, tsv_u4 (TSV_W 4). */
#define VF TSV_CAT(tsv_f, TSV_W)
#define VI TSV_CAT(tsv_i, TSV_W)
#define VU TSV_CAT(tsv_u, TSV_W)

/* Vector structs are declared per width (the suffix keeps the instances apart). */
typedef struct {
  VF x, y, z;
} VFN(vec3);
typedef struct {
  VF x, y, z, w;
} VFN(vec4);
#define V3v VFN(vec3)
#define V4v VFN(vec4)

TSV_INL VF VFN(splat)(float s) {
  VF v = {0};
  return v + s;
}
TSV_INL VI VFN(spliti)(int s) {
  VI v = {0};
  return v + s;
}
TSV_INL VF VFN(asf)(VU u) { return (VF)u; }
TSV_INL VU VFN(asu)(VF f) { return (VU)f; }
/* m ? a : b for a lane mask m (all ones / all zeros, as vector compares give). */
TSV_INL VF VFN(sel)(VI m, VF a, VF b) { return (VF)(((VI)a & m) | ((VI)b & ~m)); }
TSV_INL VI VFN(seli)(VI m, VI a, VI b) { return (a & m) | (b & ~m); }
TSV_INL VF VFN(tof)(VI i) { return __builtin_convertvector(i, VF); }

#if TSV_AVX
/* SSE minps/maxps(a, b): a<b ? a : b; the second operand on NaN and on +-0 ties; DAZ. */
TSV_INL VF VFN(lp_min)(VF a, VF b) { return (VF)_mm256_min_ps((__m256)a, (__m256)b); }
TSV_INL VF VFN(lp_max)(VF a, VF b) { return (VF)_mm256_max_ps((__m256)a, (__m256)b); }
TSV_INL VI VFN(itrunc)(VF x) { return (VI)_mm256_cvttps_epi32((__m256)x); } /* NaN/range: INT32_MIN */
TSV_INL VF VFN(sqrt)(VF x) { return (VF)_mm256_sqrt_ps((__m256)x); }
/* roundps(floor) as gallivm lp_build_floor: DAZ, sign of zero kept, NaN quieted. */
TSV_INL VF VFN(floor)(VF x) { return (VF)_mm256_round_ps((__m256)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }
#if TSV_FUSED
TSV_INL VF VFN(mad)(VF a, VF b, VF c) { return (VF)_mm256_fmadd_ps((__m256)a, (__m256)b, (__m256)c); }
#endif
#else
TSV_INL VF VFN(lp_min)(VF a, VF b) { return (VF)_mm_min_ps((__m128)a, (__m128)b); }
TSV_INL VF VFN(lp_max)(VF a, VF b) { return (VF)_mm_max_ps((__m128)a, (__m128)b); }
TSV_INL VI VFN(itrunc)(VF x) { return (VI)_mm_cvttps_epi32((__m128)x); }
TSV_INL VF VFN(sqrt)(VF x) { return (VF)_mm_sqrt_ps((__m128)x); }
/* SSE2 has no roundps: the scalar layer's software floor (ts_math.c lp_floor), lane-wise. */
TSV_INL VF VFN(floor)(VF x) {
  const VU u = VFN(asu)(x);
  const VU sign = u & 0x80000000u;
  const VI denorm = (VI)((u & 0x7f800000u) == 0);
  const VF xd = VFN(sel)(denorm, VFN(asf)(sign), x);
  const VI nan = xd != xd;
  const VF ax = VFN(asf)(VFN(asu)(xd) & 0x7fffffffu);
  const VI small = ax < 8388608.0f;
  VF t = VFN(tof)(VFN(itrunc)(xd));
  t = VFN(sel)(t > xd, t - 1.0f, t);
  t = VFN(sel)(t == 0.0f, VFN(asf)(VFN(asu)(xd) & 0x80000000u), t);
  VF r = VFN(sel)(small, t, xd);
  return VFN(sel)(nan, VFN(asf)(VFN(asu)(xd) | 0x00400000u), r);
}
#endif
#if !TSV_FUSED
TSV_INL VF VFN(mad)(VF a, VF b, VF c) { return a * b + c; }
#endif

/* ts_minf/ts_maxf: the non-NaN operand (b NaN -> a), else minps/maxps. */
TSV_INL VF VFN(min)(VF a, VF b) { return VFN(sel)(b != b, a, VFN(lp_min)(a, b)); }
TSV_INL VF VFN(max)(VF a, VF b) { return VFN(sel)(b != b, a, VFN(lp_max)(a, b)); }
TSV_INL VF VFN(clamp)(VF x, VF lo, VF hi) { return VFN(min)(VFN(max)(x, lo), hi); }
TSV_INL VF VFN(saturate)(VF x) { return VFN(lp_min)(VFN(lp_max)(x, VFN(splat)(0.0f)), VFN(splat)(1.0f)); }
TSV_INL VF VFN(inversesqrt)(VF x) { return 1.0f / VFN(sqrt)(x); }

/* gallivm lp_build_polynomial (ts_math.c lp_poly) for n >= 2 coefficients: one Horner chain in
 * x^2 per parity, started by c[n-1] and c[n-2]; then odd * x + even. `hi` always holds the chain
 * that takes the next coefficient. */
TSV_INL VF VFN(poly)(VF x, const float *c, int n) {
  const VF x2 = x * x;
  VF hi = VFN(splat)(c[n - 1]), lo = VFN(splat)(c[n - 2]);
#pragma GCC unroll 8
  for (int i = n - 3; i >= 0; i--) {
    const VF t = VFN(mad)(x2, hi, VFN(splat)(c[i]));
    hi = lo;
    lo = t;
  }
  return VFN(mad)(hi, x, lo); /* hi: the chain of c[1] (odd), lo: the chain of c[0] (even) */
}

TSV_INL VF VFN(exp2)(VF x) {
  x = VFN(lp_min)(VFN(splat)(128.0f), x);
  x = VFN(lp_max)(VFN(splat)(-126.99999f), x);
  const VF fl = VFN(floor)(x);
  const VF fr = x - fl;
  const VU i = (VU)VFN(itrunc)(fl);
  const VF scale = VFN(asf)((i + 127u) << 23);
  return scale * VFN(poly)(fr, ts_lp_exp2_coeffs, 6);
}

/* log2_safe: the edge selects run inf, zero, negative; compares as the scalar `!(...)`. */
TSV_INL VF VFN(log2)(VF x) {
  const VU b = VFN(asu)(x);
  const VF e = VFN(tof)((VI)((b & 0x7f800000u) >> 23) - 127);
  const VF m = VFN(asf)((b & 0x007fffffu) | 0x3f800000u);
  const VF y = (m - 1.0f) / (m + 1.0f);
  VF r = VFN(mad)(y, VFN(poly)(y * y, ts_lp_log2_coeffs, 5), e);
  r = VFN(sel)(~(x < __builtin_inff()), VFN(splat)(__builtin_inff()), r);
  r = VFN(sel)(~(x != 0.0f), VFN(splat)(-__builtin_inff()), r);
  r = VFN(sel)(~(x >= 0.0f), VFN(splat)(__builtin_nanf("")), r);
  return r;
}

TSV_INL VF VFN(pow)(VF x, VF y) {
  const VF r = VFN(exp2)(VFN(log2)(x) * y);
  return VFN(sel)((x == 0.0f) | (x != x), VFN(splat)(0.0f), r);
}

/* ---- 3-vectors (ts_math.c order: dot from the last component, nothing fused) ---- */
TSV_INL V3v VFN(v3)(VF x, VF y, VF z) {
  V3v v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}
TSV_INL V3v VFN(xyz)(V4v v) { return VFN(v3)(v.x, v.y, v.z); }
TSV_INL V3v VFN(add3)(V3v a, V3v b) { return VFN(v3)(a.x + b.x, a.y + b.y, a.z + b.z); }
TSV_INL V3v VFN(sub3)(V3v a, V3v b) { return VFN(v3)(a.x - b.x, a.y - b.y, a.z - b.z); }
TSV_INL V3v VFN(mul3)(V3v a, V3v b) { return VFN(v3)(a.x * b.x, a.y * b.y, a.z * b.z); }
TSV_INL V3v VFN(scale3)(V3v v, VF s) { return VFN(v3)(v.x * s, v.y * s, v.z * s); }
TSV_INL V3v VFN(neg3)(V3v v) { return VFN(v3)(-v.x, -v.y, -v.z); }
TSV_INL VF VFN(dot3)(V3v a, V3v b) { return a.x * b.x + (a.y * b.y + a.z * b.z); }
TSV_INL V3v VFN(max3)(V3v a, V3v b) { return VFN(v3)(VFN(max)(a.x, b.x), VFN(max)(a.y, b.y), VFN(max)(a.z, b.z)); }
TSV_INL V3v VFN(saturate3)(V3v v) { return VFN(v3)(VFN(saturate)(v.x), VFN(saturate)(v.y), VFN(saturate)(v.z)); }
TSV_INL V3v VFN(sel3)(VI m, V3v a, V3v b) {
  return VFN(v3)(VFN(sel)(m, a.x, b.x), VFN(sel)(m, a.y, b.y), VFN(sel)(m, a.z, b.z));
}
TSV_INL V4v VFN(sel4)(VI m, V4v a, V4v b) {
  V4v r;
  r.x = VFN(sel)(m, a.x, b.x);
  r.y = VFN(sel)(m, a.y, b.y);
  r.z = VFN(sel)(m, a.z, b.z);
  r.w = VFN(sel)(m, a.w, b.w);
  return r;
}

/* Four consecutive floats at p[j] for each lane j, as x, y, z, w vectors (SoA). */
#if TSV_AVX
TSV_INL V4v VFN(gather4)(const float *const p[TSV_W]) {
  /* one 128-bit load per lane, lanes j and j+4 in one register, then a 4x4 transpose per half */
  const __m256 r0 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p[0])), _mm_loadu_ps(p[4]), 1);
  const __m256 r1 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p[1])), _mm_loadu_ps(p[5]), 1);
  const __m256 r2 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p[2])), _mm_loadu_ps(p[6]), 1);
  const __m256 r3 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p[3])), _mm_loadu_ps(p[7]), 1);
  const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);
  const __m256 t2 = _mm256_unpacklo_ps(r2, r3), t3 = _mm256_unpackhi_ps(r2, r3);
  V4v r;
  r.x = (VF)_mm256_shuffle_ps(t0, t2, 0x44);
  r.y = (VF)_mm256_shuffle_ps(t0, t2, 0xEE);
  r.z = (VF)_mm256_shuffle_ps(t1, t3, 0x44);
  r.w = (VF)_mm256_shuffle_ps(t1, t3, 0xEE);
  return r;
}
#else
TSV_INL V4v VFN(gather4)(const float *const p[TSV_W]) {
  float t[4][TSV_W];
  V4v r;
  for (int j = 0; j < TSV_W; ++j) {
    t[0][j] = p[j][0];
    t[1][j] = p[j][1];
    t[2][j] = p[j][2];
    t[3][j] = p[j][3];
  }
  __builtin_memcpy(&r.x, t[0], sizeof(VF));
  __builtin_memcpy(&r.y, t[1], sizeof(VF));
  __builtin_memcpy(&r.z, t[2], sizeof(VF));
  __builtin_memcpy(&r.w, t[3], sizeof(VF));
  return r;
}
#endif

/* Slot values of a block: lane j reads base[pix[j] * stride] (stride 0: one value, broadcast). */
TSV_INL V4v VFN(rec_load)(const ts_vec4f *base, int stride, const size_t *pix) {
  const float *p = (const float *)base;
  const size_t s = (size_t)stride * 4u;
  V4v r;
  if (s == 0) {
    r.x = VFN(splat)(p[0]);
    r.y = VFN(splat)(p[1]);
    r.z = VFN(splat)(p[2]);
    r.w = VFN(splat)(p[3]);
    return r;
  }
  const float *q[TSV_W];
  for (int j = 0; j < TSV_W; ++j) q[j] = p + pix[j] * s;
  return VFN(gather4)(q);
}

/* Slot k of a block from any batch input (a struct of slot[] and stride[], as in twins/model_lighting_batch.h). */
#define TSV_REC(in, k, pix) VFN(rec_load)((in)->slot[k], (in)->stride[k], (pix))

/* The pixels of the block that starts at `first` (a short last block repeats its last pixel);
 * returns how many are real. */
TSV_INL int VFN(block_pix)(int first, int count, size_t *pix) {
  const int n = count - first < TSV_W ? count - first : TSV_W;
  for (int j = 0; j < TSV_W; ++j) pix[j] = (size_t)first + (size_t)(j < n ? j : n - 1);
  return n;
}

/* (c, a) as one 4-vector. */
TSV_INL V4v VFN(rgba)(V3v c, VF a) {
  V4v r;
  r.x = c.x;
  r.y = c.y;
  r.z = c.z;
  r.w = a;
  return r;
}

/* The first n lanes of c to out[0..n-1]. */
TSV_INL void VFN(store4)(V4v c, ts_vec4f *out, int n) {
  for (int j = 0; j < n; ++j) {
    out[j].x = c.x[j];
    out[j].y = c.y[j];
    out[j].z = c.z[j];
    out[j].w = c.w[j];
  }
}

/* A batch twin: pixels 0..count-1 of `in`, TSV_W at a time, each block shaded by
 * block(v, in, tex, pix) -> V4v (the twin's *_simd_impl.h). */
#define TSV_BATCH(name, block, variant_t, input_t, tex_t)                                                    \
  static void VFN(name)(const variant_t *v, const input_t *in, const tex_t *tex, ts_vec4f *out, int count) { \
    for (int first = 0; first < count; first += TSV_W) {                                                     \
      size_t pix[TSV_W];                                                                                     \
      const int n = VFN(block_pix)(first, count, pix);                                                       \
      VFN(store4)(VFN(block)(v, in, tex, pix), out + first, n);                                              \
    }                                                                                                        \
  }

/* common_math.h safe_normalize: v * inversesqrt(max(dot(v, v), 1e-30)). 1e-30 is TS_MIN_LENGTH2,
 * which is not an fp16 number (shaders/common_math.glsl says what that means for mediump). */
TSV_INL V3v VFN(safe_normalize)(V3v v) {
  return VFN(scale3)(v, VFN(inversesqrt)(VFN(max)(VFN(dot3)(v, v), VFN(splat)(1.0e-30f))));
}

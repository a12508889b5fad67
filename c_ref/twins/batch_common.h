/* tiershade twins: the dispatch and scalar fallback of every batch twin, written once. A
 * <family>_batch.c defines TSV_IMPL (its <family>_simd_impl.h, as a string) and includes this
 * file once: that instantiates the SIMD twin for AVX2+FMA, AVX2 and SSE2 (ts_simd_instances.h),
 * and TS_BATCH_DEFINE then picks one instance per call (ts_batch.h: AVX2 with FMA when llvmpipe
 * fuses its mads, AVX2 or SSE2 when it does not, else the scalar twin, one call per pixel). */
#ifndef TS_BATCH_COMMON_H
#define TS_BATCH_COMMON_H
#include <stddef.h>

#include "math/ts_batch.h"
#include "math/ts_simd_instances.h"

/* The instance for this call: 2 avx2fma, 1 avx2, 0 sse2, -1 the scalar twin. */
static inline int ts_batch_pick(void) {
  switch (ts_batch_isa()) {
    case TS_BATCH_AVX2:
      return ts_math_fused() ? 2 : 1;
    case TS_BATCH_SSE2:
      return 0;
    default:
      return -1;
  }
}

/* Runs fn_<instance>(...) and returns, when an instance applies; else falls through. */
#ifdef TS_BATCH_X86
#define TS_BATCH_DISPATCH(fn, ...) \
  switch (ts_batch_pick()) {       \
    case 2:                        \
      fn##_avx2fma(__VA_ARGS__);   \
      return;                      \
    case 1:                        \
      fn##_avx2(__VA_ARGS__);      \
      return;                      \
    case 0:                        \
      fn##_sse2(__VA_ARGS__);      \
      return;                      \
    default:                       \
      break;                       \
  }
#else
#define TS_BATCH_DISPATCH(fn, ...)
#endif

/* name_f_batch (twin_api.h TS_BATCH_DECLARE): the SIMD twin simd_<instance>, else name_f per pixel. */
#define TS_BATCH_DEFINE(name, simd, variant_t, input_t, tex_t, nslots)                                     \
  void name##_f_batch(const variant_t *v, const input_t *in, const tex_t *tex, ts_vec4f *out, int count) { \
    TS_BATCH_DISPATCH(simd, v, in, tex, out, count)                                                        \
    for (int i = 0; i < count; ++i) {                                                                      \
      ts_vec4f rec[nslots];                                                                                \
      for (int k = 0; k < nslots; ++k) rec[k] = in->slot[k][(size_t)i * (size_t)in->stride[k]];            \
      out[i] = name##_f(v, rec, tex);                                                                      \
    }                                                                                                      \
  }

/* name_f_records (twin_api.h TS_BATCH_DECLARE_RECORDS): whole records as one batch input. */
#define TS_BATCH_DEFINE_RECORDS(name, variant_t, input_t, tex_t, nslots)                                        \
  void name##_f_records(const variant_t *v, const ts_vec4f *recs, const tex_t *tex, ts_vec4f *out, int count) { \
    input_t in;                                                                                                 \
    for (int k = 0; k < nslots; ++k) {                                                                          \
      in.slot[k] = recs + k;                                                                                    \
      in.stride[k] = nslots;                                                                                    \
    }                                                                                                           \
    name##_f_batch(v, &in, tex, out, count);                                                                    \
  }
#endif

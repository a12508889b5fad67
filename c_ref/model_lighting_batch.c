/* tiershade -- c_ref/model_lighting_batch.c
 * Instantiates the SIMD model_lighting twin (model_lighting_simd_impl.h over ts_simd.h and
 * ts_simd_sampler.h) for AVX2+FMA (llvmpipe fuses its mads), AVX2 without FMA (it does not)
 * and SSE2 (4 lanes, unfused only), each under `#pragma GCC target` so that no build flag
 * changes, and picks one per call (see model_lighting_batch.h). -ffp-contract=off still
 * applies: the only fused operations are the explicit FMA intrinsics of the fused instance. */
#include "model_lighting_batch.h"

#include <stddef.h>

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define TS_BATCH_X86 1
#include <immintrin.h>

#pragma GCC push_options
#pragma GCC target("avx2,fma")
#define TSV_W 8
#define TSV_SFX avx2fma
#define TSV_FUSED 1
#define TSV_AVX 1
#include "ts_simd.h"
#include "ts_simd_sampler.h"
#include "model_lighting_simd_impl.h"
#pragma GCC pop_options
#undef TSV_W
#undef TSV_SFX
#undef TSV_FUSED
#undef TSV_AVX
#undef VF
#undef VI
#undef VU
#undef V3v
#undef V4v

#pragma GCC push_options
#pragma GCC target("avx2")
#define TSV_W 8
#define TSV_SFX avx2
#define TSV_FUSED 0
#define TSV_AVX 1
#include "ts_simd.h"
#include "ts_simd_sampler.h"
#include "model_lighting_simd_impl.h"
#pragma GCC pop_options
#undef TSV_W
#undef TSV_SFX
#undef TSV_FUSED
#undef TSV_AVX
#undef VF
#undef VI
#undef VU
#undef V3v
#undef V4v

#define TSV_W 4
#define TSV_SFX sse2
#define TSV_FUSED 0
#define TSV_AVX 0
#include "ts_simd.h"
#include "ts_simd_sampler.h"
#include "model_lighting_simd_impl.h"
#endif

static void batch_scalar(const ml_variant *v, const ml_batch_input *in, const ml_textures *tex, ts_vec4f *out,
                         int count) {
  for (int i = 0; i < count; ++i) {
    ts_vec4f rec[ML_SLOTS];
    for (int k = 0; k < ML_SLOTS; ++k) rec[k] = in->slot[k][(size_t)i * (size_t)in->stride[k]];
    out[i] = model_lighting_f(v, rec, tex);
  }
}

void model_lighting_f_batch(const ml_variant *v, const ml_batch_input *in, const ml_textures *tex, ts_vec4f *out,
                            int count) {
  switch (ts_batch_isa()) {
#ifdef TS_BATCH_X86
    case TS_BATCH_AVX2:
      if (ts_math_fused()) ml_batch_avx2fma(v, in, tex, out, count);
      else ml_batch_avx2(v, in, tex, out, count);
      return;
    case TS_BATCH_SSE2: ml_batch_sse2(v, in, tex, out, count); return;
#endif
    default: batch_scalar(v, in, tex, out, count); return;
  }
}

void model_lighting_f_records(const ml_variant *v, const ts_vec4f *recs, const ml_textures *tex, ts_vec4f *out,
                              int count) {
  ml_batch_input in;
  for (int k = 0; k < ML_SLOTS; ++k) {
    in.slot[k] = recs + k;
    in.stride[k] = ML_SLOTS;
  }
  model_lighting_f_batch(v, &in, tex, out, count);
}

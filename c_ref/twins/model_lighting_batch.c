/* tiershade twins: instantiates the SIMD model_lighting twin (model_lighting_simd_impl.h over ts_simd.h and
 * ts_simd_sampler.h) for AVX2+FMA (llvmpipe fuses its mads), AVX2 without FMA (it does not)
 * and SSE2 (4 lanes, unfused only) through ts_simd_instances.h, and picks one per call (see
 * model_lighting_batch.h). */
#include "twins/model_lighting_batch.h"

#include <stddef.h>

#define TSV_IMPL "twins/model_lighting_simd_impl.h"
#include "math/ts_simd_instances.h"

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
      if (ts_math_fused())
        ml_batch_avx2fma(v, in, tex, out, count);
      else
        ml_batch_avx2(v, in, tex, out, count);
      return;
    case TS_BATCH_SSE2:
      ml_batch_sse2(v, in, tex, out, count);
      return;
#endif
    default:
      batch_scalar(v, in, tex, out, count);
      return;
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

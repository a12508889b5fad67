/* tiershade twins: instantiates the SIMD color_correction twin (color_correction_simd_impl.h) for AVX2+FMA,
 * AVX2 and SSE2 (ts_simd_instances.h) and picks one per call (color_correction_batch.h);
 * the scalar twin runs where no instance applies. */
#include "twins/color_correction_batch.h"

#include <stddef.h>

#define TSV_IMPL "twins/color_correction_simd_impl.h"
#include "math/ts_simd_instances.h"

void color_correction_f_batch(const cc_variant *v, const cc_batch_input *in, const cc_luts *luts, ts_vec4f *out,
                              int count) {
  switch (ts_batch_isa()) {
#ifdef TS_BATCH_X86
    case TS_BATCH_AVX2:
      if (ts_math_fused())
        cc_batch_avx2fma(v, in, luts, out, count);
      else
        cc_batch_avx2(v, in, luts, out, count);
      return;
    case TS_BATCH_SSE2:
      cc_batch_sse2(v, in, luts, out, count);
      return;
#endif
    default:
      break;
  }
  for (int i = 0; i < count; ++i) {
    ts_vec4f rec[CC_SLOTS];
    for (int k = 0; k < CC_SLOTS; ++k) rec[k] = in->slot[k][(size_t)i * (size_t)in->stride[k]];
    out[i] = color_correction_f(v, rec, luts);
  }
}

/* tiershade twins: instantiates the SIMD world_lighting twin (world_lighting_simd_impl.h) for AVX2+FMA, AVX2 and
 * SSE2 (ts_simd_instances.h) and dispatches per call (world_lighting_batch.h). */
#include "twins/world_lighting_batch.h"

#include <stddef.h>

#define TSV_IMPL "twins/world_lighting_simd_impl.h"
#include "math/ts_simd_instances.h"

static void batch_scalar(const wl_variant *v, const wl_batch_input *in, const wl_textures *t, ts_vec4f *out,
                         int count) {
  for (int i = 0; i < count; ++i) {
    ts_vec4f rec[WL_SLOTS];
    for (int k = 0; k < WL_SLOTS; ++k) rec[k] = in->slot[k][(size_t)i * (size_t)in->stride[k]];
    out[i] = world_lighting_f(v, rec, t);
  }
}

void world_lighting_f_batch(const wl_variant *v, const wl_batch_input *in, const wl_textures *t, ts_vec4f *out,
                            int count) {
  switch (ts_batch_isa()) {
#ifdef TS_BATCH_X86
    case TS_BATCH_AVX2:
      if (ts_math_fused())
        wl_batch_avx2fma(v, in, t, out, count);
      else
        wl_batch_avx2(v, in, t, out, count);
      return;
    case TS_BATCH_SSE2:
      wl_batch_sse2(v, in, t, out, count);
      return;
#endif
    default:
      batch_scalar(v, in, t, out, count);
      return;
  }
}

void world_lighting_f_records(const wl_variant *v, const ts_vec4f *recs, const wl_textures *t, ts_vec4f *out,
                              int count) {
  wl_batch_input in;
  for (int k = 0; k < WL_SLOTS; ++k) {
    in.slot[k] = recs + k;
    in.stride[k] = WL_SLOTS;
  }
  world_lighting_f_batch(v, &in, t, out, count);
}

/* tiershade -- c_ref/world_lighting_batch.c
 * Instantiates the SIMD world_lighting twin (world_lighting_simd_impl.h) for AVX2+FMA, AVX2 and
 * SSE2 under `#pragma GCC target`, as model_lighting_batch.c does, and dispatches per call. */
#include "world_lighting_batch.h"

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
#include "ts_simd_sampler_nearest.h"
#include "world_lighting_simd_impl.h"
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
#include "ts_simd_sampler_nearest.h"
#include "world_lighting_simd_impl.h"
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
#include "ts_simd_sampler_nearest.h"
#include "world_lighting_simd_impl.h"
#endif

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
      if (ts_math_fused()) wl_batch_avx2fma(v, in, t, out, count);
      else wl_batch_avx2(v, in, t, out, count);
      return;
    case TS_BATCH_SSE2: wl_batch_sse2(v, in, t, out, count); return;
#endif
    default: batch_scalar(v, in, t, out, count); return;
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

/* tiershade twins: instantiates the SIMD twins of the float HDR post passes (hdr_post_simd_impl.h) for
 * AVX2+FMA, AVX2 and SSE2 (ts_simd_instances.h) and picks one per call (hdr_post_batch.h);
 * the scalar twins run where no instance applies. */
#include "twins/hdr_post_batch.h"

#include <stddef.h>

#include "math/hdr_formats.h"
#include "math/ts_sampler3d.h"

#define TSV_IMPL "twins/hdr_post_simd_impl.h"
#include "math/ts_simd_instances.h"

/* The instance for this call: 2 avx2fma, 1 avx2, 0 sse2, -1 the scalar twin. */
static int pick(void) {
  switch (ts_batch_isa()) {
#ifdef TS_BATCH_X86
    case TS_BATCH_AVX2:
      return ts_math_fused() ? 2 : 1;
    case TS_BATCH_SSE2:
      return 0;
#endif
    default:
      return -1;
  }
}

#ifdef TS_BATCH_X86
#define TS_DISPATCH(fn, ...)     \
  switch (pick()) {              \
    case 2:                      \
      fn##_avx2fma(__VA_ARGS__); \
      return;                    \
    case 1:                      \
      fn##_avx2(__VA_ARGS__);    \
      return;                    \
    case 0:                      \
      fn##_sse2(__VA_ARGS__);    \
      return;                    \
    default:                     \
      break;                     \
  }
#else
#define TS_DISPATCH(fn, ...)
#endif

void bloom_downsample_f_batch(const bd_variant *v, const bd_batch_input *in, const ts_tex2d *source, ts_vec4f *out,
                              int count) {
  TS_DISPATCH(bd_batch, v, in, source, out, count)
  for (int i = 0; i < count; ++i) {
    ts_vec4f rec[BD_SLOTS];
    for (int k = 0; k < BD_SLOTS; ++k) rec[k] = in->slot[k][(size_t)i * (size_t)in->stride[k]];
    out[i] = bloom_downsample_f(v, rec, source);
  }
}

void bloom_blur_f_batch(const bb_variant *v, const bb_batch_input *in, const ts_tex2d *source, ts_vec4f *out,
                        int count) {
  TS_DISPATCH(bb_batch, v, in, source, out, count)
  for (int i = 0; i < count; ++i) {
    ts_vec4f rec[BB_SLOTS];
    for (int k = 0; k < BB_SLOTS; ++k) rec[k] = in->slot[k][(size_t)i * (size_t)in->stride[k]];
    out[i] = bloom_blur_f(v, rec, source);
  }
}

void hdr_tonemap_f_batch(const ht_variant *v, const ht_batch_input *in, const ts_tex2d *bloom, ts_vec4f *out,
                         int count) {
  TS_DISPATCH(ht_batch, v, in, bloom, out, count)
  for (int i = 0; i < count; ++i) {
    ts_vec4f rec[HT_SLOTS];
    for (int k = 0; k < HT_SLOTS; ++k) rec[k] = in->slot[k][(size_t)i * (size_t)in->stride[k]];
    out[i] = hdr_tonemap_f(v, rec, bloom);
  }
}

void ts_quantize_half_batch(const float *in, float *out, size_t n) {
  TS_DISPATCH(quantize_half_n, in, out, n)
  for (size_t i = 0; i < n; ++i) out[i] = ts_quantize_half(in[i]);
}

void ts_unorm8_from_float_batch(const float *in, uint8_t *out, size_t n) {
  TS_DISPATCH(unorm8_n, in, out, n)
  for (size_t i = 0; i < n; ++i) out[i] = ts_unorm8_from_float(in[i]);
}

/* tiershade twins: instantiates the SIMD twins of the float HDR post passes (hdr_post_simd_impl.h) for
 * AVX2+FMA, AVX2 and SSE2 (batch_common.h) and picks one per call (hdr_post_batch.h);
 * the scalar twins run where no instance applies. */
#include "twins/hdr_post_batch.h"

#include "math/hdr_formats.h"
#include "math/ts_sampler3d.h"

#define TSV_IMPL "twins/hdr_post_simd_impl.h"
#include "twins/batch_common.h"

TS_BATCH_DEFINE(bloom_downsample, bd_batch, bd_variant, bd_batch_input, ts_tex2d, BD_SLOTS)
TS_BATCH_DEFINE(bloom_blur, bb_batch, bb_variant, bb_batch_input, ts_tex2d, BB_SLOTS)
TS_BATCH_DEFINE(hdr_tonemap, ht_batch, ht_variant, ht_batch_input, ts_tex2d, HT_SLOTS)

void hdr_tonemap_f_row(const ht_variant *v, const ht_batch_input *in, const ts_tex2d *bloom, ht_bloom_rows *rows,
                       ts_vec4f *out, int count) {
  if (count > 0 && count <= rows->capacity && bloom->filter == TS_FILTER_LINEAR && in->stride[HT_SLOT_SIZE] == 0) {
    TS_BATCH_DISPATCH(ht_row, v, in, bloom, rows, out, count)
  }
  hdr_tonemap_f_batch(v, in, bloom, out, count);
}

void ts_quantize_half_batch(const float *in, float *out, size_t n) {
  TS_BATCH_DISPATCH(quantize_half_n, in, out, n)
  for (size_t i = 0; i < n; ++i) out[i] = ts_quantize_half(in[i]);
}

void ts_unorm8_from_float_batch(const float *in, uint8_t *out, size_t n) {
  TS_BATCH_DISPATCH(unorm8_n, in, out, n)
  for (size_t i = 0; i < n; ++i) out[i] = ts_unorm8_from_float(in[i]);
}

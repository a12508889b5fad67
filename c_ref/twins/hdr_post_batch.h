/* tiershade twins: the float HDR path's post passes for many pixels per call: bloom_downsample_f, bloom_blur_f
 * and hdr_tonemap_f (every variant: SHAPE 0/1, DIRECTION 0/1, OUTPUT_MODE 0/1/2), and the
 * render-target conversions of c_ref/math/hdr_formats.h (fp16 store, RGBA8 store), with the same
 * bits as one scalar call per pixel / value, computed 8 (AVX2) or 4 (SSE2) at a time.
 * The instance is chosen per call as for model_lighting_batch.h (ts_batch.h: AVX2+FMA when
 * llvmpipe fuses its mads, AVX2 or SSE2 when it does not, else the scalar twin); call
 * ts_math_init() on every thread first (FTZ/DAZ, the fused mode).
 *
 *   bd_batch_input in = {{pos_row, &size, &shape}, {1, 0, 0}};   // slot k of pixel i:
 *   bloom_downsample_f_batch(&variant, &in, &source, out, count); //   slot[k][i * stride[k]]
 *
 * A slot shared by every pixel (a uniform) has stride 0; any count >= 0 works.
 * Verified bit for bit against the scalar twins by tests/unit/test_fast_path_post.cpp. */
#ifndef TS_HDR_POST_BATCH_H
#define TS_HDR_POST_BATCH_H
#include <stddef.h>
#include <stdint.h>

#include "twins/bloom_blur.h"
#include "twins/bloom_downsample.h"
#include "twins/hdr_tonemap.h"
#include "math/ts_batch.h"

#include "twins/twin_api.h"

/* bd_batch_input, bb_batch_input, ht_batch_input; out[i] = <twin>_f(v, record of pixel i, texture) */
TS_BATCH_DECLARE(bloom_downsample, bd_batch_input, BD_SLOTS, bd_variant, ts_tex2d)
TS_BATCH_DECLARE(bloom_blur, bb_batch_input, BB_SLOTS, bb_variant, ts_tex2d)
TS_BATCH_DECLARE(hdr_tonemap, ht_batch_input, HT_SLOTS, ht_variant, ts_tex2d)

/* hdr_tonemap_f_batch on one row of a frame, with the same bits, its bloom fetches shared with the
 * rows before it: the row's pixels share pos.y and the size slot (stride 0), and every row of a
 * frame passed with one `rows` has the same pixels' pos.x and count. rows->rgb[k] hold 3 * capacity
 * floats; set rows->row[0] = rows->row[1] = -1 before a frame's first row (the bloom texture's
 * contents change between frames). Falls back to hdr_tonemap_f_batch where that does not hold. */
typedef struct ht_bloom_rows {
  int row[2]; /* the bloom rows held, filtered horizontally at the row's pixels; -1: none */
  float *rgb[2]; /* their r, g, b: rgb[k][c * count + i] */
  int capacity; /* pixels a row may have */
} ht_bloom_rows;
TS_C_API void hdr_tonemap_f_row(const ht_variant *v, const ht_batch_input *in, const ts_tex2d *bloom,
                                ht_bloom_rows *rows, ts_vec4f *out, int count);

/* out[i] = ts_quantize_half(in[i]) / ts_unorm8_from_float(in[i]), i = 0..n-1 (in == out allowed
 * for the first). Pure bit operations and an exact multiply-add: no dependence on the fused mode. */
TS_C_API void ts_quantize_half_batch(const float *in, float *out, size_t n);
TS_C_API void ts_unorm8_from_float_batch(const float *in, uint8_t *out, size_t n);
#endif

/* tiershade twins: the color_correction float32 twin for many pixels per call: the same bits as calling
 * color_correction_f() once per pixel, computed 8 (AVX2) or 4 (SSE2) pixels at a time, for
 * every variant (LUT_ATLAS 0/1, SHADER_TRILINEAR 0/1, NUM_LOOKUPS 0..4): 3D LUTs through
 * ts_simd_sampler3d.h, the atlas through ts_simd_sampler.h. The instance is chosen per call
 * as for model_lighting_batch.h (ts_batch.h); call ts_math_init() on every thread first.
 *
 *   cc_batch_input in = {{colours, &w, &p, &lut}, {1, 0, 0, 0}};  // slot k of pixel i:
 *   color_correction_f_batch(&variant, &in, &luts, out, count);    //   slot[k][i * stride[k]]
 *
 * A slot shared by every pixel (a uniform) has stride 0; any count >= 0 works.
 * Verified bit for bit against color_correction_f by tests/unit/test_fast_path_post.cpp. */
#ifndef TS_COLOR_CORRECTION_BATCH_H
#define TS_COLOR_CORRECTION_BATCH_H
#include "twins/color_correction.h"
#include "math/ts_batch.h"

#include "twins/twin_api.h"

/* cc_batch_input; color_correction_f_batch: out[i] = color_correction_f(v, record of pixel i, luts) */
TS_BATCH_DECLARE(color_correction, cc_batch_input, CC_SLOTS, cc_variant, cc_luts)
#endif

/* tiershade twins: the model_lighting float32 twin for many pixels per call: the same bits as calling
 * model_lighting_f() once per pixel, computed 8 (AVX2) or 4 (SSE2) pixels at a time.
 *
 * How to use:
 *   ts_math_init();                    // on every thread that shades, as for model_lighting_f
 *   ml_batch_input in;
 *   for (int k = 0; k < ML_SLOTS; ++k) { in.slot[k] = ...; in.stride[k] = ...; }
 *   model_lighting_f_batch(&variant, &in, &textures, out, count);
 * Slot k of pixel i is in.slot[k][i * in.stride[k]] (stride in ts_vec4f units, >= 0). A slot
 * shared by every pixel (a production uniform: lights, ambient cube, material) has stride 0 and
 * points at its one value; a G-buffer slot of a row of pixels has stride 1. For whole records
 * stored one after the other (ts_vec4f recs[count][ML_SLOTS]) use model_lighting_f_records().
 * Any count >= 0 works; a multiple of 8 is fastest. The fused-mad mode is read from ts_math
 * (ts_math_fused()) at each call, and the instruction set is chosen from the host (ts_batch.h:
 * AVX2 with FMA when llvmpipe fuses, else AVX2 or SSE2; elsewhere the scalar twin).
 * Verified bit for bit against model_lighting_f by tests/unit/test_fast_path.cpp. */
#ifndef TS_MODEL_LIGHTING_BATCH_H
#define TS_MODEL_LIGHTING_BATCH_H
#include "twins/model_lighting.h"
#include "math/ts_batch.h"

#include "twins/twin_api.h"

/* ml_batch_input; model_lighting_f_batch: out[i] = model_lighting_f(v, record of pixel i, tex) */
TS_BATCH_DECLARE(model_lighting, ml_batch_input, ML_SLOTS, ml_variant, ml_textures)
/* The same for whole records: recs[i * ML_SLOTS + k] is slot k of pixel i. */
TS_BATCH_DECLARE_RECORDS(model_lighting, ml_variant, ml_textures)
#endif

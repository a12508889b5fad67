/* tiershade twins: instantiates the SIMD model_lighting twin (model_lighting_simd_impl.h over ts_simd.h and
 * ts_simd_sampler.h) for AVX2+FMA (llvmpipe fuses its mads), AVX2 without FMA (it does not)
 * and SSE2 (4 lanes, unfused only) through batch_common.h, and picks one per call (see
 * model_lighting_batch.h). */
#include "twins/model_lighting_batch.h"

#define TSV_IMPL "twins/model_lighting_simd_impl.h"
#include "twins/batch_common.h"

TS_BATCH_DEFINE(model_lighting, ml_batch, ml_variant, ml_batch_input, ml_textures, ML_SLOTS)
TS_BATCH_DEFINE_RECORDS(model_lighting, ml_variant, ml_batch_input, ml_textures, ML_SLOTS)

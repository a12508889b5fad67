/* tiershade twins: instantiates the SIMD world_lighting twin (world_lighting_simd_impl.h) for AVX2+FMA, AVX2 and
 * SSE2 (batch_common.h) and dispatches per call (world_lighting_batch.h). */
#include "twins/world_lighting_batch.h"

#define TSV_IMPL "twins/world_lighting_simd_impl.h"
#include "twins/batch_common.h"

TS_BATCH_DEFINE(world_lighting, wl_batch, wl_variant, wl_batch_input, wl_textures, WL_SLOTS)
TS_BATCH_DEFINE_RECORDS(world_lighting, wl_variant, wl_batch_input, wl_textures, WL_SLOTS)

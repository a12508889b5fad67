/* tiershade twins: instantiates the SIMD color_correction twin (color_correction_simd_impl.h) for AVX2+FMA,
 * AVX2 and SSE2 (batch_common.h) and picks one per call (color_correction_batch.h);
 * the scalar twin runs where no instance applies. */
#include "twins/color_correction_batch.h"

#define TSV_IMPL "twins/color_correction_simd_impl.h"
#include "twins/batch_common.h"

TS_BATCH_DEFINE(color_correction, cc_batch, cc_variant, cc_batch_input, cc_luts, CC_SLOTS)

/* tiershade math: which instance the batch (SIMD) twins run (model_lighting_batch.c, world_lighting_batch.c;
 * docs/c_math_layer.md "The fast path"): AVX2 with FMA when llvmpipe fuses its mads
 * (ts_math_fused()), AVX2 or SSE2 when it does not, else the scalar twin. Chosen per call from
 * the host and the fused mode. */
#ifndef TS_BATCH_H
#define TS_BATCH_H

#ifdef __cplusplus
extern "C" {
#endif

enum { TS_BATCH_SCALAR = 0, TS_BATCH_SSE2 = 1, TS_BATCH_AVX2 = 2 };
int ts_batch_isa(void); /* what the next batch call will use (given the fused mode) */
void ts_batch_force_isa(int isa); /* -1 = automatic; a level the host lacks is lowered (tests) */

#ifdef __cplusplus
}
#endif
#endif

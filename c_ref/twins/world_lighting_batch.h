/* tiershade twins: the world_lighting float32 twin for many pixels per call: the same bits as calling
 * world_lighting_f() once per pixel, 8 (AVX2) or 4 (SSE2) pixels at a time (ts_batch.h).
 * Use it like model_lighting_batch.h: ts_math_init() on the thread, then
 *   wl_batch_input in;  // slot k of pixel i: in.slot[k][i * in.stride[k]]; stride 0 = shared
 *   world_lighting_f_batch(&variant, &in, &textures, out, count);
 * or world_lighting_f_records() for whole records (recs[i * WL_SLOTS + k]).
 * Verified bit for bit against world_lighting_f by tests/unit/test_fast_path.cpp. */
#ifndef TS_WORLD_LIGHTING_BATCH_H
#define TS_WORLD_LIGHTING_BATCH_H
#include "math/ts_batch.h"
#include "twins/world_lighting.h"

#include "twins/twin_api.h"

/* wl_batch_input; world_lighting_f_batch and world_lighting_f_records (recs[i * WL_SLOTS + k]) */
TS_BATCH_DECLARE(world_lighting, wl_batch_input, WL_SLOTS, wl_variant, wl_textures)
TS_BATCH_DECLARE_RECORDS(world_lighting, wl_variant, wl_textures)
#endif

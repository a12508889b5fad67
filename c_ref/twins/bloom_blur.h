/* c_ref/twins/bloom_blur.h: C twin of shaders/bloom_blur.fs, one direction of the separable
 * 13-tap Gaussian of the bloom (fact sheet section 8). One call shades one pixel from
 * its input record (shaders/bloom_blur_slots.glsl) and the source texture. */
#ifndef TS_BLOOM_BLUR_H
#define TS_BLOOM_BLUR_H
#include "math/ts_math.h"
#include "math/ts_sampler.h"

#ifdef __cplusplus
extern "C" {
#endif

enum bb_slot { BB_SLOT_POS = 0, BB_SLOT_SIZE = 1, BB_SLOT_PARAMS = 2, BB_SLOTS = 3, BB_PIXEL_SLOTS = 1 };

typedef struct {
  int direction; /* DIRECTION: 0 X, 1 Y */
} bb_variant;

ts_vec4f bloom_blur_f(const bb_variant *v, const ts_vec4f rec[BB_SLOTS], const ts_tex2d *source);
ts_vec4d bloom_blur_d(const bb_variant *v, const ts_vec4f rec[BB_SLOTS], const ts_tex2d *source);

#ifdef __cplusplus
}
#endif
#endif

/* tiershade twins: C twin of shaders/bloom_blur.fs, one direction of the separable
 * 13-tap Gaussian of the bloom (fact sheet section 8). One call shades one pixel from
 * its input record (shaders/bloom_blur_slots.glsl) and the source texture. */
#ifndef TS_BLOOM_BLUR_H
#define TS_BLOOM_BLUR_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"
#include "math/ts_sampler.h"

/* The input record's slots (enum bb_slot) and its counts (BB_SLOTS, BB_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/bloom_blur_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum bb_slot {
#include "../../shaders/bloom_blur_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int direction; /* DIRECTION: 0 X, 1 Y */
} bb_variant;

/* bloom_blur_f: float32, bit-exact with llvmpipe; bloom_blur_d: double, the accuracy reference */
TS_TWIN_DECLARE(bloom_blur, (const bb_variant *v, const ts_vec4f rec[BB_SLOTS], const ts_tex2d *source))
/* bloom_blur_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv bloom_blur_iv(const bb_variant *v, const ts_vec4f rec[BB_SLOTS], const ts_tex2d *source);

#endif

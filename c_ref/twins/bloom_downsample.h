/* tiershade twins: C twin of shaders/bloom_downsample.fs, the quarter-size
 * bloom source (4 bilinear taps = a 4x4 box, optionally shaped p^exp * dot(p, tint)).
 * One call shades one pixel of the quarter-size target from its input record
 * (shaders/bloom_downsample_slots.glsl) and the source texture. */
#ifndef TS_BLOOM_DOWNSAMPLE_H
#define TS_BLOOM_DOWNSAMPLE_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"
#include "math/ts_sampler.h"

/* The input record's slots (enum bd_slot) and its counts (BD_SLOTS, BD_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/bloom_downsample_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum bd_slot {
#include "../../shaders/bloom_downsample_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int shape; /* SHAPE: 0 plain box, 1 shaped taps */
} bd_variant;

/* bloom_downsample_f: float32, bit-exact with llvmpipe; bloom_downsample_d: double, the accuracy reference */
TS_TWIN_DECLARE(bloom_downsample, (const bd_variant *v, const ts_vec4f rec[BD_SLOTS], const ts_tex2d *source))
/* bloom_downsample_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv bloom_downsample_iv(const bd_variant *v, const ts_vec4f rec[BD_SLOTS], const ts_tex2d *source);

#endif

/* tiershade twins: C twin of shaders/bloom_downsample.fs, the quarter-size
 * bloom source (4 bilinear taps = a 4x4 box, optionally shaped p^exp * dot(p, tint)).
 * One call shades one pixel of the quarter-size target from its input record
 * (shaders/bloom_downsample_slots.glsl) and the source texture. */
#ifndef TS_BLOOM_DOWNSAMPLE_H
#define TS_BLOOM_DOWNSAMPLE_H
#include "math/ts_math.h"
#include "math/ts_sampler.h"

#ifdef __cplusplus
extern "C" {
#endif

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

ts_vec4f bloom_downsample_f(const bd_variant *v, const ts_vec4f rec[BD_SLOTS], const ts_tex2d *source);
ts_vec4d bloom_downsample_d(const bd_variant *v, const ts_vec4f rec[BD_SLOTS], const ts_tex2d *source);

#ifdef __cplusplus
}
#endif
#endif

/* tiershade twins: C twin of shaders/luminance_compare.fs, the bucket test
 * of the auto-exposure histogram. One call tests one pixel from its input record
 * (shaders/luminance_compare_slots.glsl): (1,1,1,1) when the pixel is marked, and
 * (0,0,0,0), the cleared target, when the shader discards it. */
#ifndef TS_LUMINANCE_COMPARE_H
#define TS_LUMINANCE_COMPARE_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"

/* The input record's slots (enum lc_slot) and its counts (LC_SLOTS, LC_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/luminance_compare_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum lc_slot {
#include "../../shaders/luminance_compare_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int input_encoding; /* INPUT_ENCODING: 0 linear x tone-map scale, 1 sRGB-encoded, 2 luminance image (.r) */
} lc_variant;

/* luminance_compare_f: float32, bit-exact with llvmpipe; luminance_compare_d: double, the accuracy reference */
TS_TWIN_DECLARE(luminance_compare, (const lc_variant *v, const ts_vec4f rec[LC_SLOTS]))
/* luminance_compare_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv luminance_compare_iv(const lc_variant *v, const ts_vec4f rec[LC_SLOTS]);
/* The luminance the test compares (before the bucket bounds), float32 and llvmpipe-exact. */
TS_C_API float luminance_compare_lum_f(const lc_variant *v, ts_vec4f color, float tone_map_scale);

#endif

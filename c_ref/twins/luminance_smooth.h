/* tiershade twins: C twin of shaders/luminance_smooth.fs, the temporal
 * prefilter of the auto-exposure luminance: S = S_prev + alpha (L - S_prev), with L the
 * (tone-mapped) luminance of the frame's pixel. One call shades one pixel from its input
 * record (shaders/luminance_smooth_slots.glsl). */
#ifndef TS_LUMINANCE_SMOOTH_H
#define TS_LUMINANCE_SMOOTH_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"

/* The input record's slots (enum ls_slot) and its counts (LS_SLOTS, LS_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/luminance_smooth_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum ls_slot {
#include "../../shaders/luminance_smooth_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int input_encoding; /* INPUT_ENCODING: 0 linear x tone-map scale, 1 sRGB-encoded */
} ls_variant;

/* luminance_smooth_f: float32, bit-exact with llvmpipe; luminance_smooth_d: double, the accuracy reference */
TS_TWIN_DECLARE(luminance_smooth, (const ls_variant *v, const ts_vec4f rec[LS_SLOTS]))
/* luminance_smooth_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv luminance_smooth_iv(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]);

#endif

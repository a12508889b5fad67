/* c_ref/twins/luminance_smooth.h: C twin of shaders/luminance_smooth.fs, the temporal
 * prefilter of the auto-exposure luminance: S = S_prev + alpha (L - S_prev), with L the
 * (tone-mapped) luminance of the frame's pixel. One call shades one pixel from its input
 * record (shaders/luminance_smooth_slots.glsl). */
#ifndef TS_LUMINANCE_SMOOTH_H
#define TS_LUMINANCE_SMOOTH_H
#include "math/ts_math.h"

#ifdef __cplusplus
extern "C" {
#endif

enum ls_slot { LS_SLOT_COLOR = 0, LS_SLOT_HISTORY = 1, LS_SLOT_PARAMS = 2, LS_SLOTS = 3, LS_PIXEL_SLOTS = 2 };

typedef struct {
  int input_encoding; /* INPUT_ENCODING: 0 linear x tone-map scale, 1 sRGB-encoded */
} ls_variant;

ts_vec4f luminance_smooth_f(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]);
ts_vec4d luminance_smooth_d(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]);

#ifdef __cplusplus
}
#endif
#endif

/* tiershade twins: C twin of shaders/hdr_tonemap.fs, the float HDR path's last
 * pass: tone-map scale, the bloom combine of floattoscreen_combine (fact sheet
 * section 7) and the output encoding. One call shades one pixel from its input
 * record (shaders/hdr_tonemap_slots.glsl) and the quarter-size bloom texture. */
#ifndef TS_HDR_TONEMAP_H
#define TS_HDR_TONEMAP_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_sampler.h"
#include "math/ts_interval.h"

/* The input record's slots (enum ht_slot) and its counts (HT_SLOTS, HT_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/hdr_tonemap_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum ht_slot {
#include "../../shaders/hdr_tonemap_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int output_mode; /* OUTPUT_MODE: 0 linear, 1 gamma 2.2, 2 exact sRGB */
} ht_variant;

/* hdr_tonemap_f: float32, bit-exact with llvmpipe; hdr_tonemap_d: double, the accuracy reference */
TS_TWIN_DECLARE(hdr_tonemap, (const ht_variant *v, const ts_vec4f rec[HT_SLOTS], const ts_tex2d *bloom))
/* hdr_tonemap_iv: per channel, the interval of every result GLSL ES 3.00 highp allows */
TS_C_API ts_vec4iv hdr_tonemap_iv(const ht_variant *v, const ts_vec4f rec[HT_SLOTS], const ts_tex2d *bloom);

#endif

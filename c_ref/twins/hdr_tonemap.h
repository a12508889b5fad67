/* c_ref/twins/hdr_tonemap.h: C twin of shaders/hdr_tonemap.fs, the float HDR path's last
 * pass: tone-map scale, the bloom combine of floattoscreen_combine (fact sheet
 * section 7) and the output encoding. One call shades one pixel from its input
 * record (shaders/hdr_tonemap_slots.glsl) and the quarter-size bloom texture. */
#ifndef TS_HDR_TONEMAP_H
#define TS_HDR_TONEMAP_H
#include "math/ts_math.h"
#include "math/ts_sampler.h"

#ifdef __cplusplus
extern "C" {
#endif

enum ht_slot {
  HT_SLOT_POS = 0,
  HT_SLOT_FRAME = 1,
  HT_SLOT_SIZE = 2,
  HT_SLOT_PARAMS = 3,
  HT_SLOTS = 4,
  HT_PIXEL_SLOTS = 2
};

typedef struct {
  int output_mode; /* OUTPUT_MODE: 0 linear, 1 gamma 2.2, 2 exact sRGB */
} ht_variant;

ts_vec4f hdr_tonemap_f(const ht_variant *v, const ts_vec4f rec[HT_SLOTS], const ts_tex2d *bloom);
ts_vec4d hdr_tonemap_d(const ht_variant *v, const ts_vec4f rec[HT_SLOTS], const ts_tex2d *bloom);

#ifdef __cplusplus
}
#endif
#endif

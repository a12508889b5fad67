/* tiershade twins: C twin of shaders/skybox.fs, the HDR skybox: a pixel's view direction from
 * the camera's three vectors, the sky's cube map in that direction, the radiance scale and the
 * linear output (tone-map scale, clamp to fp16). One call shades one pixel from its input
 * record (shaders/skybox_slots.glsl) and the sky's cube map. */
#ifndef TS_SKYBOX_H
#define TS_SKYBOX_H
#include "math/ts_math.h"
#include "math/ts_sampler.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"

/* The input record's slots (enum sb_slot) and its counts (SB_SLOTS, SB_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/skybox_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum sb_slot {
#include "../../shaders/skybox_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int tier; /* TS_TIER_ID_*: the shader is the same in every tier */
} sb_variant;

/* skybox_f: float32, bit-exact with llvmpipe; skybox_d: double, the accuracy reference */
TS_TWIN_DECLARE(skybox, (const sb_variant *v, const ts_vec4f rec[SB_SLOTS], const ts_texcube *sky))
/* skybox_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv skybox_iv(const sb_variant *v, const ts_vec4f rec[SB_SLOTS], const ts_texcube *sky);

#endif

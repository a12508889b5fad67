/* tiershade twins: C twin of shaders/model_lighting.fs (HL2 model lighting and
 * the Episode One Phong terms).
 * One call shades one pixel from its input record (the same slots the shader
 * reads in conformance mode, shaders/model_lighting_slots.glsl). */
#ifndef TS_MODEL_LIGHTING_H
#define TS_MODEL_LIGHTING_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"
#include "math/ts_sampler.h"
#include "twins/tier_id.h"

/* The input record's slots (enum ml_slot) and its counts (ML_SLOTS, ML_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/model_lighting_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum ml_slot {
#include "../../shaders/model_lighting_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int tier; /* enum ts_tier_id */
  int albedo_texture; /* ALBEDO_TEXTURE */
  int half_lambert; /* HALF_LAMBERT */
  int output_mode; /* OUTPUT_MODE: 0 linear, 1 gamma 2.2, 2 sRGB */
  int num_lights; /* NUM_LIGHTS (ps20, ps2b); sm3 reads the count from the record */
  int phong; /* PHONG (ps2b, sm3) */
  int exponent_map; /* PHONG_EXPONENT_MAP */
  int rim_light; /* RIM_LIGHT */
  int envmap; /* ENVMAP */
  int light_warp; /* LIGHT_WARP */
} ml_variant;

/* The textures a variant samples (NULL when the variant does not). */
typedef struct {
  const ts_tex2d *albedo, *normal_map, *exponent_map, *light_warp;
  const ts_texcube *envmap;
  /* The uv's quad derivatives (ds/dx, ds/dy, dt/dx, dt/dy: ts_texture2D_gradf) for the textures a
   * mip chain may minify (albedo, normal and exponent maps; the light warp ramp is indexed by
   * lighting, not by the surface, and stays one level): NULL = none (level 0). One value for
   * model_lighting_f; pixel i's at uv_grad[i * uv_grad_stride] for the batch. */
  const ts_vec4f *uv_grad;
  int uv_grad_stride;
} ml_textures;

/* model_lighting_f: float32, bit-exact with llvmpipe; model_lighting_d: double, the accuracy reference */
TS_TWIN_DECLARE(model_lighting, (const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ml_textures *tex))
/* model_lighting_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv model_lighting_iv(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ml_textures *tex);

#endif

/* tiershade twins: C twin of shaders/world_lighting.fs (Source's world
 * shading: lightmaps, radiosity normal mapping, cube-map specular). One call
 * shades one pixel from its input record (the slots the shader reads in
 * conformance mode, shaders/world_lighting_slots.glsl) and its textures. */
#ifndef TS_WORLD_LIGHTING_H
#define TS_WORLD_LIGHTING_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"
#include "math/ts_sampler.h"
#include "twins/tier_id.h"

/* The input record's slots (enum wl_slot) and its counts (WL_SLOTS, WL_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/world_lighting_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum wl_slot {
#include "../../shaders/world_lighting_slots.glsl"
};
#undef TS_SLOT

enum wl_bump { WL_BUMP_NONE = 0, WL_BUMP_RNM = 1, WL_BUMP_SSBUMP = 2 };
enum wl_encoding { WL_LM_FLOAT = 0, WL_LM_412 = 1, WL_LM_LDR = 2, WL_LM_RGBE = 3 };
enum wl_mask { WL_MASK_NONE = 0, WL_MASK_TEXTURE = 1, WL_MASK_NORMAL_ALPHA = 2, WL_MASK_INV_BASE_ALPHA = 3 };

typedef struct {
  int tier; /* enum ts_tier_id */
  int bumpmap; /* BUMPMAP */
  int encoding; /* LIGHTMAP_ENCODING */
  int envmap; /* ENVMAP */
  int envmapmask; /* ENVMAPMASK */
} wl_variant;

typedef struct {
  const ts_tex2d *base, *normalmap, *lightmap, *envmap_mask;
  const ts_texcube *envmap;
  /* The uv's quad derivatives for base, normal map and envmap mask (ts_texture2D_gradf; the
   * lightmap stays one level, LINEAR, as Source samples it): NULL = none. One value for
   * world_lighting_f; pixel i's at uv_grad[i * uv_grad_stride] for the batch. */
  const ts_vec4f *uv_grad;
  int uv_grad_stride;
} wl_textures;

/* world_lighting_f: float32, bit-exact with llvmpipe; world_lighting_d: double, the accuracy reference */
TS_TWIN_DECLARE(world_lighting, (const wl_variant *v, const ts_vec4f rec[WL_SLOTS], const wl_textures *t))
/* world_lighting_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv world_lighting_iv(const wl_variant *v, const ts_vec4f rec[WL_SLOTS], const wl_textures *t);

#endif

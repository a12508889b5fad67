/* c_ref/twins/world_lighting.h: C twin of shaders/world_lighting.fs (Source's world
 * shading: lightmaps, radiosity normal mapping, cube-map specular). One call
 * shades one pixel from its input record (the slots the shader reads in
 * conformance mode, shaders/world_lighting_slots.glsl) and its textures. */
#ifndef TS_WORLD_LIGHTING_H
#define TS_WORLD_LIGHTING_H
#include "math/ts_math.h"
#include "math/ts_sampler.h"
#include "twins/tier_id.h"

#ifdef __cplusplus
extern "C" {
#endif

enum wl_slot {
  WL_SLOT_UV = 0,         /* xy base uv, zw lightmap uv */
  WL_SLOT_LM_OFFSET = 1,  /* xy offset to the next lightmap, z fog depth */
  WL_SLOT_NORMAL = 2,
  WL_SLOT_TANGENT = 3,
  WL_SLOT_BINORMAL = 4,
  WL_SLOT_EYE = 5,        /* surface point -> eye */
  WL_SLOT_TINT_SCALE = 6, /* rgb c12, w tone-map scale */
  WL_SLOT_ENV_TINT = 7,   /* rgb tint, w ENV_MAP_SCALE */
  WL_SLOT_ENV_PARAMS = 8, /* contrast, saturation, 1 - R0, R0 */
  WL_SLOT_FOG_COLOR = 9,  /* rgb, w max density */
  WL_SLOT_FOG_PARAMS = 10, /* 1 / range, start / range */
  WL_SLOTS = 11,
  WL_PIXEL_SLOTS = 6
};

enum wl_bump { WL_BUMP_NONE = 0, WL_BUMP_RNM = 1, WL_BUMP_SSBUMP = 2 };
enum wl_encoding { WL_LM_FLOAT = 0, WL_LM_412 = 1, WL_LM_LDR = 2, WL_LM_RGBE = 3 };
enum wl_mask { WL_MASK_NONE = 0, WL_MASK_TEXTURE = 1, WL_MASK_NORMAL_ALPHA = 2, WL_MASK_INV_BASE_ALPHA = 3 };

typedef struct {
  int tier;       /* enum ts_tier_id */
  int bumpmap;    /* BUMPMAP */
  int encoding;   /* LIGHTMAP_ENCODING */
  int envmap;     /* ENVMAP */
  int envmapmask; /* ENVMAPMASK */
} wl_variant;

typedef struct {
  const ts_tex2d *base, *normalmap, *lightmap, *envmap_mask;
  const ts_texcube *envmap;
} wl_textures;

/* float32, bit-exact with llvmpipe */
ts_vec4f world_lighting_f(const wl_variant *v, const ts_vec4f rec[WL_SLOTS], const wl_textures *t);
/* double, the accuracy reference for the same variant */
ts_vec4d world_lighting_d(const wl_variant *v, const ts_vec4f rec[WL_SLOTS], const wl_textures *t);

#ifdef __cplusplus
}
#endif
#endif

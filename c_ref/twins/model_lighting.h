/* c_ref/twins/model_lighting.h: C twin of shaders/model_lighting.fs (HL2 model lighting and
 * the Episode One Phong terms).
 * One call shades one pixel from its input record (the same slots the shader
 * reads in conformance mode, shaders/model_lighting_slots.glsl). */
#ifndef TS_MODEL_LIGHTING_H
#define TS_MODEL_LIGHTING_H
#include "math/ts_math.h"
#include "math/ts_sampler.h"
#include "twins/tier_id.h"

#ifdef __cplusplus
extern "C" {
#endif

enum ml_slot {
  ML_MAX_LIGHTS = 4,
  ML_SLOT_NORMAL = 0,
  ML_SLOT_POSITION = 1,
  ML_SLOT_UV = 2,
  ML_SLOT_VERTEX_ATTEN = 3, /* ps20: attenuation of lights 0..3 from the vertex shader */
  ML_SLOT_TANGENT = 4,      /* Phong: world tangent (normal-map x axis) */
  ML_SLOT_BITANGENT = 5,    /* Phong: world bitangent (normal-map y axis) */
  ML_PIXEL_SLOTS = 6,       /* per pixel in deferred frames */
  ML_SLOT_AMBIENT = 6,      /* 6 slots: +X -X +Y -Y +Z -Z */
  ML_SLOT_PARAMS = 12,      /* x tone-map scale, y light count (sm3) */
  ML_SLOT_ALBEDO = 13,
  ML_SLOT_LIGHT0 = 14,      /* 5 slots per light: color, dir, pos, spot, atten */
  ML_SLOT_EYE = 34,
  ML_SLOT_PHONG = 35,       /* x constant exponent, y exponent factor, z boost, w mask from base alpha */
  ML_SLOT_FRESNEL = 36,     /* ((mid-min)*2, mid, (max-mid)*2), w invert the mask */
  ML_SLOT_PHONG_TINT = 37,  /* rgb tint, w > 0.5: lerp(1, albedo, exponent-map g) */
  ML_SLOT_RIM = 38,         /* x rim exponent, y rim boost, z rim-mask amount */
  ML_SLOT_ENVMAP = 39,      /* x scale, y Fresnel amount, z > 0.5: mask = spec mask */
  ML_SLOT_ENVMAP_TINT = 40,
  ML_SLOT_SELF_ILLUM = 41,  /* rgb tint, w amount */
  ML_SLOTS = 42
};

typedef struct {
  int tier;           /* enum ts_tier_id */
  int albedo_texture; /* ALBEDO_TEXTURE */
  int half_lambert;   /* HALF_LAMBERT */
  int output_mode;    /* OUTPUT_MODE: 0 linear, 1 gamma 2.2, 2 sRGB */
  int num_lights;     /* NUM_LIGHTS (ps20, ps2b); sm3 reads the count from the record */
  int phong;          /* PHONG (ps2b, sm3) */
  int exponent_map;   /* PHONG_EXPONENT_MAP */
  int rim_light;      /* RIM_LIGHT */
  int envmap;         /* ENVMAP */
  int light_warp;     /* LIGHT_WARP */
} ml_variant;

/* The textures a variant samples (NULL when the variant does not). */
typedef struct {
  const ts_tex2d *albedo, *normal_map, *exponent_map, *light_warp;
  const ts_texcube *envmap;
} ml_textures;

/* float32, bit-exact with llvmpipe */
ts_vec4f model_lighting_f(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ml_textures *tex);
/* double, the accuracy reference for the same variant */
ts_vec4d model_lighting_d(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ml_textures *tex);

#ifdef __cplusplus
}
#endif
#endif

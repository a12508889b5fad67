/* c_ref/model_lighting.h: C twin of shaders/model_lighting.fs (HL2 model lighting).
 * One call shades one pixel from its input record (the same slots the shader
 * reads in conformance mode, shaders/model_lighting_slots.glsl). */
#ifndef TS_MODEL_LIGHTING_H
#define TS_MODEL_LIGHTING_H
#include "ts_math.h"
#include "ts_sampler.h"

#ifdef __cplusplus
extern "C" {
#endif

enum ml_slot {
  ML_MAX_LIGHTS = 4,
  ML_SLOT_NORMAL = 0,
  ML_SLOT_POSITION = 1,
  ML_SLOT_UV = 2,
  ML_SLOT_VERTEX_ATTEN = 3, /* ps20: attenuation of lights 0..3 from the vertex shader */
  ML_SLOT_AMBIENT = 4,      /* 6 slots: +X -X +Y -Y +Z -Z */
  ML_SLOT_PARAMS = 10,      /* x tone-map scale, y light count (sm3) */
  ML_SLOT_ALBEDO = 11,
  ML_SLOT_LIGHT0 = 12,      /* 5 slots per light: color, dir, pos, spot, atten */
  ML_SLOTS = 32,
  ML_PIXEL_SLOTS = 4 /* normal, position, uv, vertex attenuation: per pixel in deferred frames */
};

enum ts_tier_id { TS_TIER_ID_PS20 = 0, TS_TIER_ID_PS2B = 1, TS_TIER_ID_SM3 = 2 };

typedef struct {
  int tier;           /* enum ts_tier_id */
  int albedo_texture; /* ALBEDO_TEXTURE */
  int half_lambert;   /* HALF_LAMBERT */
  int output_mode;    /* OUTPUT_MODE: 0 linear, 1 gamma 2.2, 2 sRGB */
  int num_lights;     /* NUM_LIGHTS (ps20, ps2b); sm3 reads the count from the record */
} ml_variant;

/* float32, bit-exact with llvmpipe */
ts_vec4f model_lighting_f(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ts_tex2d *albedo);
/* double, the accuracy reference for the same variant */
ts_vec4d model_lighting_d(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ts_tex2d *albedo);

#ifdef __cplusplus
}
#endif
#endif

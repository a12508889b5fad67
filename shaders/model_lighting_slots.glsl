//------------------------------------------------------------------------------
// model_lighting_slots.glsl: the input record of model_lighting (one vec4 per slot).
// Must match enum ml_slot in c_ref/model_lighting.h.
//------------------------------------------------------------------------------
#ifndef TS_MODEL_LIGHTING_SLOTS_GLSL
#define TS_MODEL_LIGHTING_SLOTS_GLSL
#define ML_MAX_LIGHTS 4
#define ML_SLOT_NORMAL 0
#define ML_SLOT_POSITION 1
#define ML_SLOT_UV 2
#define ML_SLOT_VERTEX_ATTEN 3  // ps20: attenuation of lights 0..3, interpolated from the vertex shader
#define ML_SLOT_AMBIENT 4       // 6 slots: +X -X +Y -Y +Z -Z
#define ML_SLOT_PARAMS 10       // x tone-map scale, y light count (sm3)
#define ML_SLOT_ALBEDO 11
#define ML_SLOT_LIGHT0 12       // 5 slots per light: color, dir, pos, spot, atten
#define ML_SLOTS 32
#define ML_PIXEL_SLOTS 4        // normal, position, uv, vertex attenuation: the G-buffer of TS_DEFERRED frames
#endif

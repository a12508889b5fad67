//------------------------------------------------------------------------------
// model_lighting_slots.glsl: the input record of model_lighting (one vec4 per slot).
// Must match enum ml_slot in c_ref/twins/model_lighting.h. Slots below ML_PIXEL_SLOTS are
// per pixel (varyings); the others are uniforms.
//------------------------------------------------------------------------------
#ifndef TS_MODEL_LIGHTING_SLOTS_GLSL
#define TS_MODEL_LIGHTING_SLOTS_GLSL
#define ML_MAX_LIGHTS 4
#define ML_SLOT_NORMAL 0
#define ML_SLOT_POSITION 1
#define ML_SLOT_UV 2
#define ML_SLOT_VERTEX_ATTEN 3  // ps20: attenuation of lights 0..3, interpolated from the vertex shader
#define ML_SLOT_TANGENT 4       // Phong: world tangent (normal-map x axis)
#define ML_SLOT_BITANGENT 5     // Phong: world bitangent (normal-map y axis)
#define ML_PIXEL_SLOTS 6        // the G-buffer of TS_DEFERRED frames
#define ML_SLOT_AMBIENT 6       // 6 slots: +X -X +Y -Y +Z -Z
#define ML_SLOT_PARAMS 12       // x tone-map scale, y light count (sm3)
#define ML_SLOT_ALBEDO 13
#define ML_SLOT_LIGHT0 14       // 5 slots per light: color, dir, pos, spot, atten
#define ML_SLOT_EYE 34          // xyz eye position (Phong, rim, envmap)
#define ML_SLOT_PHONG 35        // x constant exponent, y exponent factor (k = 1 + y r), z boost, w mask from base alpha
#define ML_SLOT_FRESNEL 36      // Fresnel ranges as uploaded: ((mid-min)*2, mid, (max-mid)*2), w invert the mask
#define ML_SLOT_PHONG_TINT 37   // rgb tint, w > 0.5: tint = lerp(1, albedo, exponent-map g)
#define ML_SLOT_RIM 38          // x rim exponent, y rim boost, z rim-mask amount ($rimmask)
#define ML_SLOT_ENVMAP 39       // x envmap scale, y envmap Fresnel amount, z > 0.5: mask = spec mask (else base alpha)
#define ML_SLOT_ENVMAP_TINT 40  // rgb envmap tint
#define ML_SLOT_SELF_ILLUM 41   // rgb tint, w amount (0: off); mask = base alpha
#define ML_SLOTS 42
#endif

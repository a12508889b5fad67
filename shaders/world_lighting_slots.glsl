//------------------------------------------------------------------------------
// world_lighting_slots.glsl: the input record of world_lighting (one vec4 per slot).
// Must match enum wl_slot in c_ref/twins/world_lighting.h.
//------------------------------------------------------------------------------
#ifndef TS_WORLD_LIGHTING_SLOTS_GLSL
#define TS_WORLD_LIGHTING_SLOTS_GLSL
#define WL_SLOT_UV 0           // xy base-texture uv, zw lightmap uv (flat lightmap of the face)
#define WL_SLOT_LM_OFFSET 1    // xy offset to the next lightmap of the face, z fog depth
#define WL_SLOT_NORMAL 2       // world-space tangent frame, as interpolated
#define WL_SLOT_TANGENT 3
#define WL_SLOT_BINORMAL 4
#define WL_SLOT_EYE 5          // world-space vector from the surface point to the eye
#define WL_SLOT_TINT_SCALE 6   // rgb modulation x lightmap scale (c12), w tone-map scale
#define WL_SLOT_ENV_TINT 7     // rgb envmap tint, w envmap scale (ENV_MAP_SCALE)
#define WL_SLOT_ENV_PARAMS 8   // x contrast, y saturation, z 1 - R0, w R0
#define WL_SLOT_FOG_COLOR 9    // rgb fog colour, w max density
#define WL_SLOT_FOG_PARAMS 10  // x 1 / range, y start / range
#define WL_SLOTS 11
#define WL_PIXEL_SLOTS 6       // uv .. eye: the G-buffer of TS_DEFERRED frames
#endif

//------------------------------------------------------------------------------
// model_lighting_varyings.glsl: the varyings of model_lighting, declared once for the three
// shaders that pass them: model_lighting.vs writes them, model_lighting.fs and
// scene_gbuffer.fs (the G-buffer of scene frames) read them. TS_VARYING is `out` in a vertex
// shader and `in` in a fragment shader (ts_portability.glsl). Their slots in the input
// record: the per-pixel rows of model_lighting_slots.glsl.
//------------------------------------------------------------------------------
#ifndef TS_MODEL_LIGHTING_VARYINGS_GLSL
#define TS_MODEL_LIGHTING_VARYINGS_GLSL
#if PHONG
TS_VARYING vec3 v_tangent;    // world-space tangent and bitangent of the normal map
TS_VARYING vec3 v_bitangent;
#endif
TS_VARYING vec3 v_normal;     // world-space normal, as interpolated (not unit length)
TS_VARYING vec3 v_position;   // world-space position
TS_VARYING vec2 v_uv;
#ifdef TS_TIER_PS20
TS_VARYING vec4 v_light_atten;  // per-vertex attenuation of lights 0..3 (model_lighting.vs)
#endif
#endif

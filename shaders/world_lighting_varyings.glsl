//------------------------------------------------------------------------------
// world_lighting_varyings.glsl: the varyings of world_lighting, declared once for the three
// shaders that pass them: world_lighting.vs writes them, world_lighting.fs and
// scene_gbuffer.fs read them (TS_VARYING: ts_portability.glsl). Their slots in the input
// record: the per-pixel rows of world_lighting_slots.glsl.
//------------------------------------------------------------------------------
#ifndef TS_WORLD_LIGHTING_VARYINGS_GLSL
#define TS_WORLD_LIGHTING_VARYINGS_GLSL
TS_VARYING vec4 v_uv;         // xy base uv, zw lightmap uv
TS_VARYING vec4 v_lm_offset;  // xy offset to the next lightmap, z fog depth (clip w)
// vec4 so that the production path reads them with no construction (w unused, 0).
TS_VARYING vec4 v_normal;     // world-space tangent frame (interpolated, not unit length)
TS_VARYING vec4 v_tangent;
TS_VARYING vec4 v_binormal;   // N x T times the handedness
TS_VARYING vec4 v_eye;        // surface point -> eye, world space
#endif

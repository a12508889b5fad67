//------------------------------------------------------------------------------
// world_lighting.vs: the production vertex shader of world_lighting (after
// lightmappedgeneric_vs20.fxc, fact sheet section 1): world-space brush geometry
// (no model matrix), the base and lightmap uvs, the offset to the face's next
// lightmap (uv_k = uv + k * offset), the tangent frame (binormal = N x T times the
// handedness in a_tangent.w), the vector to the eye, and the fog depth (clip w).
//------------------------------------------------------------------------------
TS_ATTRIBUTE vec3 a_position;
TS_ATTRIBUTE vec3 a_normal;
TS_ATTRIBUTE vec4 a_tangent;     // xyz tangent (S direction), w +-1 handedness
TS_ATTRIBUTE vec2 a_uv;          // base-texture uv
TS_ATTRIBUTE vec4 a_lightmap;    // xy lightmap uv of the flat lightmap, zw offset to the next one
uniform mat4 u_view_proj;
uniform vec4 u_eye_position;
#include "world_lighting_varyings.glsl"

void main() {
    gl_Position = u_view_proj * vec4(a_position, 1.0);
    v_uv = vec4(a_uv, a_lightmap.xy);
    v_lm_offset = vec4(a_lightmap.zw, gl_Position.w, 0.0);
    v_normal = vec4(a_normal, 0.0);
    v_tangent = vec4(a_tangent.xyz, 0.0);
    v_binormal = vec4(cross(a_normal, a_tangent.xyz) * a_tangent.w, 0.0);
    v_eye = vec4(u_eye_position.xyz - a_position, 0.0);
}

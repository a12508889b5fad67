//------------------------------------------------------------------------------
// model_lighting.vs: the production vertex shader of model_lighting: world-space
// position and normal for per-pixel lighting, and the albedo uv.
//------------------------------------------------------------------------------
TS_ATTRIBUTE vec3 a_position;
TS_ATTRIBUTE vec3 a_normal;
TS_ATTRIBUTE vec2 a_uv;
uniform mat4 u_model;          // object -> world (rigid or uniformly scaled)
uniform mat4 u_view_proj;
TS_VARYING_OUT vec3 v_normal;
TS_VARYING_OUT vec3 v_position;
TS_VARYING_OUT vec2 v_uv;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_position = world.xyz;
    v_normal = (u_model * vec4(a_normal, 0.0)).xyz;
    v_uv = a_uv;
    gl_Position = u_view_proj * world;
}

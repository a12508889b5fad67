//------------------------------------------------------------------------------
// model_lighting.vs: the production vertex shader of model_lighting: world-space
// position and normal for per-pixel lighting, the albedo uv, and on ps20 the
// per-vertex attenuation (distance x spot cone) of each local light, which the
// ps20 pixel shader takes interpolated (fact sheet section 4, VertexAttenInternal),
// and with PHONG the normal map's tangent frame.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_lights.glsl"
#include "model_lighting_slots.glsl"
#include "model_lighting_varyings.glsl"

TS_ATTRIBUTE vec3 a_position;
TS_ATTRIBUTE vec3 a_normal;
TS_ATTRIBUTE vec2 a_uv;
#if PHONG
TS_ATTRIBUTE vec4 a_tangent;   // xyz tangent, w handedness (+1 or -1), as glTF stores it
#endif
uniform mat4 u_model;          // object -> world (rigid or uniformly scaled)
uniform mat4 u_view_proj;
#ifdef TS_TIER_PS20
uniform vec4 u_lights[5 * ML_MAX_LIGHTS];
#endif

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_position = world.xyz;
    v_normal = (u_model * vec4(a_normal, 0.0)).xyz;
    v_uv = a_uv;
#if PHONG
    v_tangent = (u_model * vec4(a_tangent.xyz, 0.0)).xyz;
    v_bitangent = cross(v_normal, v_tangent) * a_tangent.w;
#endif
#ifdef TS_TIER_PS20
    vec4 atten = vec4(0.0);
    for (int i = 0; i < NUM_LIGHTS; ++i) {
        TsLight l;
        l.color = u_lights[5 * i + 0];
        l.dir = u_lights[5 * i + 1];
        l.pos = u_lights[5 * i + 2];
        l.spot = u_lights[5 * i + 3];
        l.atten = u_lights[5 * i + 4];
        vec3 L;
        float a = ts_light_attenuation(l, world.xyz, L);
        if (i == 0) atten.x = a;
        if (i == 1) atten.y = a;
    }
    v_light_atten = atten;
#endif
    gl_Position = u_view_proj * world;
}

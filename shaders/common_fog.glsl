//------------------------------------------------------------------------------
// common_fog.glsl: Source's pixel range fog (fact sheet section 7, FinalOutput):
//   f = saturate(min(maxDensity, depth * OORange - start / range)),
//   c = lerp(c, fog colour, f^2)   ("closer to hardware fog").
// ps_2_0 has none (vertex / fixed-function fog instead): world_lighting drops it there.
// C twin: c_ref/common/common_fog.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_FOG_GLSL
#define TS_COMMON_FOG_GLSL

// fog_color: rgb, w max density; fog_params: x 1 / range, y start / range.
vec3 ts_range_fog(vec3 c, float depth, vec4 fog_color, vec4 fog_params) {
    float f = saturate(min(fog_color.w, depth * fog_params.x - fog_params.y));
    return c + (fog_color.rgb - c) * (f * f);
}

#endif

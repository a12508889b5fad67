//------------------------------------------------------------------------------
// skybox.fs: the HDR skybox (talk: the HDR skybox of the HDR section; fact sheet section 6:
// Source's HDR sky is six faces, decoded as rgb * $color, sky_hdr_dx9.cpp). A full-screen pass
// drawn before the geometry (glue/scene/skybox_pass.h): each pixel looks up the sky's cube map
// (six faces resampled on the host from the scene's lat-long sky) in its view direction
//   d   = forward + right * ndc.x + up * ndc.y,  ndc = (pos / size) * 2 - 1
//   out = FinalOutput(min(texCUBE(d), 65504) * color): tone-map scale, no fog, linear
// (common_output.glsl: the same output path as world_lighting, so the sky composes with the
// frame on the integer and the float HDR paths). A zero or NaN direction (dot(d, d) not above
// TS_MIN_LENGTH2) looks at the zenith; the components are clamped to +-1e30, so that an
// infinite one gives a finite face coordinate.
// Variants: skybox.variants. C twin: c_ref/twins/skybox.c.
//------------------------------------------------------------------------------
#include "common_math.glsl"
#include "common_inputs.glsl"
#include "common_output.glsl"
#include "skybox_slots.glsl"

uniform vec4 u_frame_size;   // xy size in pixels, zw 1 / size
uniform vec4 u_sky_forward;  // xyz the direction through the frame's centre
uniform vec4 u_sky_right;    // xyz per unit of ndc x
uniform vec4 u_sky_up;       // xyz per unit of ndc y
uniform vec4 u_sky_color;    // rgb radiance scale, w tone-map scale
uniform samplerCube u_sky;   // the sky's six faces (fp16 values), LINEAR (NEAREST on GLES)

#define TS_SKY_MAX_COMPONENT 1.0e30

TS_DECLARE_FRAG_COLOR

void main() {
    vec2 pos = TS_PIXEL_INPUT(SB_SLOT_POS, vec4(gl_FragCoord.xy, 0.0, 0.0)).xy;
    vec4 size = TS_UNIFORM_INPUT(SB_SLOT_SIZE, u_frame_size);
    vec3 fwd = TS_UNIFORM_INPUT(SB_SLOT_FORWARD, u_sky_forward).xyz;
    vec3 right = TS_UNIFORM_INPUT(SB_SLOT_RIGHT, u_sky_right).xyz;
    vec3 up = TS_UNIFORM_INPUT(SB_SLOT_UP, u_sky_up).xyz;
    vec4 color = TS_UNIFORM_INPUT(SB_SLOT_COLOR, u_sky_color);
    vec2 ndc = (pos * size.zw) * 2.0 - 1.0;
    vec3 d = (fwd + right * ndc.x) + up * ndc.y;
    d = dot(d, d) > TS_MIN_LENGTH2 ? clamp(d, -TS_SKY_MAX_COMPONENT, TS_SKY_MAX_COMPONENT) : vec3(0.0, 1.0, 0.0);
    vec3 sky = min(TS_TEXCUBE(u_sky, d).rgb, TS_FP16_MAX);
    vec3 c = (sky * color.rgb) * color.w;
    TS_FRAG_COLOR = vec4(ts_output_linear(c), 1.0);
}

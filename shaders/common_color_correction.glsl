//------------------------------------------------------------------------------
// common_color_correction.glsl: Source's colour correction (talk: "Color Correction":
// "a mapping from one set of RGB triples to another ... a 32^3 volume texture lookup
// (sometimes several)"; fact sheet section 9, colorcorrection_ps2x / PerformColorCorrection).
//   uvw = c * (N-1)/N + 0.5/N       texel centres: 0 -> 0.5/N, 1 -> (N-0.5)/N (Source: N = 32,
//                                   c * 31/32 + 0.5/32); N comes from a uniform here
//   out = c * w_default + sum_i w_i * LUT_i(uvw)     a plain weighted sum, not normalised
// Storage: a 3D texture (x red, y green, z blue), or, for ES2/WebGL1, a 2D atlas of the N
// blue slices side by side: width N*N, height N, texel (r, g, b) at (b*N + r, g).
// Filtering: hardware (one trilinear tap; on the atlas two bilinear taps in the blue slices
// around c.b, lerped by the blue fraction), or in the shader: the 8 lattice texels sampled at
// their centres and lerped in x, y, z at full float precision (GPU filter weights often have
// only 8 fractional bits: OpenColorIO issue #1763). Shader-filtered LUTs are meant to be
// bound with NEAREST filtering; at texel centres LINEAR returns the texel too, to within
// rounding of the centre coordinate (docs/color_correction.md).
// C twin: c_ref/common/common_color_correction.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_COLOR_CORRECTION_GLSL
#define TS_COMMON_COLOR_CORRECTION_GLSL

// Texel-centre addressing (fact sheet section 9), lut = ((N-1)/N, 0.5/N, N-1, 1/N).
vec3 ts_cc_uvw(vec3 c, vec4 lut) {
    return c * lut.x + lut.y;
}

// The lattice cell around c (c in [0, 1]): corners i0 = floor(c (N-1)) and
// i1 = min(i0 + 1, N-1), in texels, and the fraction f (trilinear weights).
void ts_cc_cell(vec3 c, vec4 lut, out vec3 i0, out vec3 i1, out vec3 f) {
    vec3 p = c * lut.z;
    i0 = floor(p);
    f = p - i0;
    i1 = min(i0 + 1.0, lut.z);
}

// The normalised coordinate of the centre of texel i.
vec3 ts_cc_centre(vec3 i, vec4 lut) {
    return (i + 0.5) * lut.w;
}

// Linear interpolation, a + (b - a) t (written out: the twin mirrors this exact form).
vec3 ts_cc_lerp(vec3 a, vec3 b, float t) {
    return a + (b - a) * t;
}

#if LUT_ATLAS
// Hardware filtering on the atlas: bilinear in the slices z0 and z1, lerped by fz.
vec3 ts_cc_atlas_hw(sampler2D lut, vec2 uv0, vec2 uv1, float fz) {
    return ts_cc_lerp(TS_TEX2D(lut, uv0).rgb, TS_TEX2D(lut, uv1).rgb, fz);
}

// Shader filtering on the atlas: u = atlas u of the red centres x0, x1 in the slices
// z0, z1 as (x0 z0, x1 z0, x0 z1, x1 z1); v = the green centres (y0, y1).
vec3 ts_cc_atlas_shader(sampler2D lut, vec4 u, vec2 v, vec3 f) {
    vec3 t000 = TS_TEX2D(lut, vec2(u.x, v.x)).rgb;
    vec3 t100 = TS_TEX2D(lut, vec2(u.y, v.x)).rgb;
    vec3 t010 = TS_TEX2D(lut, vec2(u.x, v.y)).rgb;
    vec3 t110 = TS_TEX2D(lut, vec2(u.y, v.y)).rgb;
    vec3 t001 = TS_TEX2D(lut, vec2(u.z, v.x)).rgb;
    vec3 t101 = TS_TEX2D(lut, vec2(u.w, v.x)).rgb;
    vec3 t011 = TS_TEX2D(lut, vec2(u.z, v.y)).rgb;
    vec3 t111 = TS_TEX2D(lut, vec2(u.w, v.y)).rgb;
    vec3 s0 = ts_cc_lerp(ts_cc_lerp(t000, t100, f.x), ts_cc_lerp(t010, t110, f.x), f.y);
    vec3 s1 = ts_cc_lerp(ts_cc_lerp(t001, t101, f.x), ts_cc_lerp(t011, t111, f.x), f.y);
    return ts_cc_lerp(s0, s1, f.z);
}
#else
// Hardware filtering on a 3D texture: one trilinear tap.
vec3 ts_cc_volume_hw(sampler3D lut, vec3 uvw) {
    return TS_TEX3D(lut, uvw).rgb;
}

// Shader filtering on a 3D texture: c0, c1 = the centres of the cell's corners.
vec3 ts_cc_volume_shader(sampler3D lut, vec3 c0, vec3 c1, vec3 f) {
    vec3 t000 = TS_TEX3D(lut, vec3(c0.x, c0.y, c0.z)).rgb;
    vec3 t100 = TS_TEX3D(lut, vec3(c1.x, c0.y, c0.z)).rgb;
    vec3 t010 = TS_TEX3D(lut, vec3(c0.x, c1.y, c0.z)).rgb;
    vec3 t110 = TS_TEX3D(lut, vec3(c1.x, c1.y, c0.z)).rgb;
    vec3 t001 = TS_TEX3D(lut, vec3(c0.x, c0.y, c1.z)).rgb;
    vec3 t101 = TS_TEX3D(lut, vec3(c1.x, c0.y, c1.z)).rgb;
    vec3 t011 = TS_TEX3D(lut, vec3(c0.x, c1.y, c1.z)).rgb;
    vec3 t111 = TS_TEX3D(lut, vec3(c1.x, c1.y, c1.z)).rgb;
    vec3 s0 = ts_cc_lerp(ts_cc_lerp(t000, t100, f.x), ts_cc_lerp(t010, t110, f.x), f.y);
    vec3 s1 = ts_cc_lerp(ts_cc_lerp(t001, t101, f.x), ts_cc_lerp(t011, t111, f.x), f.y);
    return ts_cc_lerp(s0, s1, f.z);
}
#endif

#endif

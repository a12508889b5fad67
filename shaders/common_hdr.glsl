//------------------------------------------------------------------------------
// common_hdr.glsl: helpers of the HDR post-processing passes (docs/hdr.md).
//  - luminance: dot(c, (0.2125, 0.7154, 0.0721)) (fact sheet section 8,
//    luminance_compare: the weights of the bucket test);
//  - the bucket test step(min, lum) * step(lum, max) (fact sheet section 8);
//  - the exact sRGB decode, <= 0.04045 -> x / 12.92, else ((x + 0.055) / 1.055)^2.4
//    (fact sheet section 2), for reading an integer-path (sRGB-encoded RGBA8) frame;
//  - bright shaping of a bloom tap, p^exp * dot(p, tint) (fact sheet section 8,
//    Generate8BitBloomTexture);
//  - the texel under a fragment of a full-screen pass (texelFetch, or a NEAREST
//    sample at the texel centre where GLSL ES 1.00 has no texelFetch).
// C twin: c_ref/common/common_hdr.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_HDR_GLSL
#define TS_COMMON_HDR_GLSL

// Fact sheet section 8 (luminance_compare): Rec. 709 luminance weights as Source writes them.
float ts_luminance(vec3 c) {
    return dot(c, vec3(0.2125, 0.7154, 0.0721));
}

// Fact sheet section 8: 1 when min <= lum <= max (both ends closed), else 0; NaN gives 0.
float ts_in_bucket(float lum, float lo, float hi) {
    return step(lo, lum) * step(lum, hi);
}

// Fact sheet section 2: the exact sRGB decode.
float ts_srgb_decode(float x) {
    return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}

vec3 ts_srgb_decode3(vec3 c) {
    return vec3(ts_srgb_decode(c.r), ts_srgb_decode(c.g), ts_srgb_decode(c.b));
}

// Fact sheet section 8 (Generate8BitBloomTexture): a tap shaped as p^exp * dot(p, tint).
vec3 ts_bloom_shape(vec3 p, vec4 shape) {
    // Base >= TS_POW_TINY (common_math.glsl): a black tap is tiny^exp * 0 = 0, not pow(0, exp) * 0.
    return pow(max(p, TS_POW_TINY), vec3(shape.w)) * dot(p, shape.rgb);
}

// The texel of `s` under the fragment at `frag` (gl_FragCoord.xy) of a pass whose
// target has the texture's size; size.zw = 1 / size.
vec4 ts_frame_texel(sampler2D s, vec2 frag, vec4 size) {
#ifdef TS_HAS_TEXEL_FETCH
    return texelFetch(s, ivec2(frag), 0);
#else
    return TS_TEX2D(s, frag * size.zw);
#endif
}

#endif

//------------------------------------------------------------------------------
// common_lightmap.glsl: lightmap page addressing and texel decodes.
// Page layout (fact sheet section 1, lightmappedgeneric_vs20.fxc): a bumped face
// has four lightmaps side by side, flat first, then b0, b1, b2: uv_k = uv + k * offset.
// Encodings (fact sheet section 2; docs/world_lighting.md):
//   0 float    linear radiance (an fp16 texture where half floats filter)
//   1 "4.12"   16-bit unorm holding radiance / 16, range [0, 16) (MAX_HDR_OVERBRIGHT)
//   2 LDR      gamma-encoded and pre-divided by overbright 2: radiance = (2 t)^2.2
//              (GammaToLinear(2c), the overbright-2 decode of common_vs_fxc.h); ps20
//              uses (2 t)^2 (ts_lightmap_ldr_to_linear_fast)
//   3 RGBE     ColorRGBExp32 in an RGBA8 texture, exponent biased by 128:
//              radiance = (c/255) 2^e = t.rgb * 2^(255 t.a - 128) (TexLightToLinear)
// C twin: c_ref/common/common_lightmap.h
//------------------------------------------------------------------------------
#ifndef TS_COMMON_LIGHTMAP_GLSL
#define TS_COMMON_LIGHTMAP_GLSL

#define TS_LIGHTMAP_FLOAT 0
#define TS_LIGHTMAP_412 1
#define TS_LIGHTMAP_LDR 2
#define TS_LIGHTMAP_RGBE 3

// MAX_HDR_OVERBRIGHT (fact sheet section 2): the range of the 16-bit format.
#define TS_LIGHTMAP_412_RANGE 16.0

// The LDR gamma curve's exponent and overbright factor (fact sheet section 2).
#define TS_LIGHTMAP_LDR_GAMMA 2.2
#define TS_LIGHTMAP_OVERBRIGHT 2.0

// uv of lightmap k of a face (0 flat, 1..3 the bumped ones).
vec2 ts_lightmap_uv(vec2 uv, vec2 offset, float k) {
    return uv + k * offset;
}

vec3 ts_lightmap_ldr_to_linear(vec3 t) {
    // Base >= TS_POW_TINY (common_math.glsl): a black texel decodes to 2^-132 (0 after FTZ), not pow(0, 2.2).
    return pow(max(t * TS_LIGHTMAP_OVERBRIGHT, TS_POW_TINY), vec3(TS_LIGHTMAP_LDR_GAMMA));
}

// ps20's LDR decode: (2 t)^2 for (2 t)^2.2, the approximation Source uses on the X360 for
// overbright-2 vertex lighting (fact sheet section 2); 3 slots instead of a 9-slot vec3 pow.
// The min() (4 = the decode of t = 1, so no stored value changes) also ends the chain of
// multiplies: Mesa's GLSL compiler rebalances chains of 3+ multiplies (opt_rebalance_tree),
// and base * (s * s) * tint would be regrouped in a way the twin would have to guess.
vec3 ts_lightmap_ldr_to_linear_fast(vec3 t) {
    vec3 s = t * TS_LIGHTMAP_OVERBRIGHT;
    return min(s * s, TS_LIGHTMAP_OVERBRIGHT * TS_LIGHTMAP_OVERBRIGHT);
}

vec3 ts_lightmap_decode(vec4 t, int encoding) {
    if (encoding == TS_LIGHTMAP_412) return t.rgb * TS_LIGHTMAP_412_RANGE;
    if (encoding == TS_LIGHTMAP_LDR) return ts_lightmap_ldr_to_linear(t.rgb);
    if (encoding == TS_LIGHTMAP_RGBE) return t.rgb * exp2(t.a * 255.0 - 128.0);
    return t.rgb;
}

#endif

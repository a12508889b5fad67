/* tiershade offline: the offline side of the lightmap encodings (fact sheet
 * section 2): ColorRGBExp32 encode/decode as vrad stores it, and the quantisers that
 * give the exact values the run-time formats hold (fp16, 16-bit "4.12", LDR 8-bit
 * gamma / overbright 2). The shader decodes of the stored values are in
 * shaders/common_lightmap.glsl and their twin c_ref/common/common_lightmap.h. */
#ifndef TS_LIGHTMAP_ENCODING_H
#define TS_LIGHTMAP_ENCODING_H

#ifdef __cplusplus
extern "C" {
#endif

/* ColorRGBExp32 (mathlib.h): three 8-bit mantissas and a signed exponent. */
typedef struct {
  unsigned char r, g, b;
  signed char exponent;
} ts_rgbe;

/* VectorToColorRGBExp32 of linear radiance (vrad units = linear x 255): e = exponent of
 * the largest channel - 7, so that it lands in [128, 255]; mantissas truncated; e clamped
 * to [-128, 127] (a mantissa above 255 at e = 127 saturates). Negative channels count as 0.
 * Returns 0, or -1 for a NaN channel (*out is then zero). */
int ts_rgbe_encode(const float linear[3], ts_rgbe *out);
/* TexLightToLinear: c * 2^e / 255, in double (exact). */
void ts_rgbe_decode(ts_rgbe c, double linear[3]);
/* The RGBA8 texel of an RGBE value as the shader samples it: (r, g, b, e + 128) / 255. */
void ts_rgbe_texel(ts_rgbe c, float texel[4]);

/* The nearest IEEE half-float value (round to nearest even), as a float. Values beyond
 * the largest half (65504) saturate to +-65504 instead of overflowing to infinity; NaN
 * stays NaN; half denormals are kept (a float can hold them). */
float ts_half_quantize(float x);

/* "4.12": the 16-bit unorm texel of linear x, round(clamp(x / 16, 0, 1) * 65535) / 65535,
 * as a float (what a unorm16 fetch returns). NaN gives 0. Decoded by the shader as t x 16. */
float ts_u16_412_quantize(float x);

/* LDR: the 8-bit texel of linear x, gamma-encoded and pre-divided by overbright 2,
 * round(clamp(0.5 x^(1/2.2), 0, 1) * 255) / 255. NaN gives 0. Decoded as (2 t)^2.2. */
float ts_ldr_quantize(float x);

#ifdef __cplusplus
}
#endif
#endif

/* tiershade math: the storage conversions of the HDR render targets and
 * textures, as Mesa 22.3.6 llvmpipe performs them (measured exhaustively, docs/hdr.md):
 *   - a float written to an RGBA16F target is rounded TOWARD ZERO to half
 *     (finite values >= 65504 give 65504, half denormals are kept, NaN stays NaN);
 *   - a float written to an RGBA8 target becomes round-to-nearest-even of
 *     saturate(x) * 255, NaN -> 0 (computed as gallivm does: x * (255/256) + 2^15,
 *     whose low 8 mantissa bits are the code);
 *   - an RGBA8 texel fetched as float is code * (1.0f / 255.0f), not code / 255.0f.
 * Half values convert to float exactly. */
#ifndef TS_HDR_FORMATS_H
#define TS_HDR_FORMATS_H
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

uint16_t ts_half_from_float_rz(float x); /* RGBA16F render-target write */
float ts_half_to_float(uint16_t h); /* exact */
float ts_quantize_half(float x); /* ts_half_to_float(ts_half_from_float_rz(x)) */
uint8_t ts_unorm8_from_float(float x); /* RGBA8 render-target write */
float ts_unorm8_to_float(uint8_t c); /* RGBA8 texel fetch */

#ifdef __cplusplus
}
#endif
#endif

// tiershade base: the sRGB transfer function on the host (IEC 61966-2-1), in float or double.
// The shaders' curve and its bit-exact C twin are c_ref/common/common_output.h (encode) and
// c_ref/common/common_hdr.h (decode); the 8-bit codes of the integer HDR path are
// hdr/srgb_rgba8_codes.h, which evaluates srgb_encode<double> below.
#pragma once
#include <cmath>

#include "base/image.h"

// Linear -> encoded, for v in [0, 1] (no clamp): v <= 0.0031308 ? 12.92 v : 1.055 v^(1/2.4) - 0.055.
// Evaluated in T throughout (float: powf and float constants; double: pow), so each caller
// keeps the precision it had.
template <class T>
T srgb_encode(T v) {
  return v <= T(0.0031308) ? T(12.92) * v : T(1.055) * std::pow(v, T(1) / T(2.4)) - T(0.055);
}

// Encoded -> linear, for v in [0, 1] (no clamp): v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055)^2.4.
template <class T>
T srgb_decode(T v) {
  return v <= T(0.04045) ? v / T(12.92) : std::pow((v + T(0.055)) / T(1.055), T(2.4));
}

// srgb_encode of v clamped to [0, 1] first (NaN -> 0).
template <class T>
T srgb_encode_clamped(T v) {
  return srgb_encode(std::fmin(std::fmax(v, T(0)), T(1)));
}

// A linear image for display: every colour channel srgb_encode_clamped in float, alpha kept.
ImageF srgb_display(ImageF img);

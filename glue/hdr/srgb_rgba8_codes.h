// tiershade hdr: the 8-bit code of a linear value encoded with the exact sRGB curve, as the
// integer HDR path stores linear shader outputs (ps20, world_lighting) in its RGBA8 frame:
//   code(v) = ts_unorm8_from_float(float(srgb(double(v))))
// computed by a binary search over the 255 code thresholds instead of a pow per channel. The
// thresholds are found once by bisection over float bit patterns; since every step is monotone
// in v, the result equals the direct formula for every float (tests/unit/test_scene_render.cpp).
#pragma once
#include <cstdint>

// The direct formula (the definition).
uint8_t srgb_code_direct(float v);
// The same code through the thresholds.
uint8_t srgb_code(float v);

// tiershade base: ULP distance between floats and the false-colour difference of two images
// (what conformance, the demos and the benchmarks report).
#pragma once
#include <cstdint>

#include "base/image.h"

// ULP distance between two floats: the difference of their positions in the ordered sequence
// of float values. Conventions:
//   * bit-identical values (including identical NaNs) are 0 apart;
//   * +0 and -0 are 0 apart (they share one position), so the smallest positive and negative
//     denormals are 2 apart;
//   * +-Inf sit one step beyond +-FLT_MAX;
//   * a NaN against anything not bit-identical to it is UINT32_MAX.
uint32_t ulp_distance(float a, float b);

struct DiffStats {
  long pixels = 0;  // w * h compared
  long mismatched_pixels = 0;  // pixels where any channel is not bit-identical
  uint32_t max_ulp = 0;  // largest ulp_distance over all channels
  double max_abs = 0;  // largest |a - b| over channel pairs that are both finite
  int worst_x = -1, worst_y = -1;  // first pixel reaching max_ulp (ImageF coords, y = 0 bottom);
      // -1 when the images are bit-identical
};

// False-colour visualisation of a vs b, same size, RGBA in [0,1] (write it with
// Encode::Linear). Per pixel, with d = largest channel ulp_distance:
//   * all four channels bit-identical (even if NaN/Inf)  -> black
//   * otherwise a NaN or Inf in either input            -> magenta (1,0,1)
//   * otherwise a log2 ramp: 1 ULP dark blue (0,0,0.5) -> blue -> cyan -> green -> yellow ->
//     red (1,0,0) at >= 2^20 ULP.
// Alpha is 1. On a size mismatch (or a malformed image) the result is an empty image and
// *stats is reset to its defaults. stats may be null.
ImageF diff_image(const ImageF &a, const ImageF &b, DiffStats *stats);

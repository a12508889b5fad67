// tiershade hdr: auto exposure of a still frame. Source's running histogram (one bucket per
// frame, read AE_READ_DELAY frames later; c_ref/exposure/auto_exposure.h) and its controller
// (c_ref/exposure/exposure_control.h) run for N frames on the same fp16 linear frame, as a camera
// holding still would. The bucket counts are the exact counts of the luminance_compare twin
// (ae_exact_count), found by binary search in the window's sorted luminances instead of a
// pass over the window per frame: lum = luminance(c) * scale is monotone in luminance(c)
// for a finite scale >= 0 (tests/unit/test_static_exposure.cpp checks the equality).
#pragma once
#include <cstdint>
#include <vector>

#include "exposure/auto_exposure.h"

class StaticLuminance {
 public:
  // rgba: w x h linear frame (rows bottom-up); the centred window as the histogram measures.
  StaticLuminance(const float *rgba, int w, int h, double window_x = 0.9, double window_y = 0.85);
  // == ae_exact_count(rgba, w, h, window, 0, scale, bucket).
  uint32_t count(int bucket, float scale) const;

 private:
  std::vector<float> sorted_;  // finite luminances of the window, ascending
  std::vector<float> odd_;  // rgba of window pixels with a non-finite luminance
};

struct StaticExposure {
  double scale = 1;  // the tone-map scale after the last frame
  double goal = 1;
  int frames = 0;
};
// Runs `frames` frames at 30 fps from initial_scale with the scale clamped to [min, max].
StaticExposure run_static_exposure(const StaticLuminance &lum, double initial_scale, double min_exposure,
                                   double max_exposure, int frames);

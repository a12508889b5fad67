// tiershade hdr: auto exposure of a still frame. Source's running histogram (one bucket per
// frame, read AE_READ_DELAY frames later; c_ref/exposure/auto_exposure.h) and its controller
// (c_ref/exposure/exposure_control.h) run for N frames on the same fp16 linear frame, as a camera
// holding still would. The bucket counts are the exact counts of the luminance_compare twin
// (ae_exact_count), found by binary search in the window's sorted luminances instead of a
// pass over the window per frame: lum = luminance(c) * scale is monotone in luminance(c)
// for a finite scale >= 0 (tests/unit/test_scene_render.cpp checks the equality). The
// luminances are not sorted whole: they are grouped by the top 16 bits of their order-preserving
// key (one counting pass), so a count needs a binary search over the groups and a scan of the
// one group its boundary falls in.
#pragma once
#include <cstddef>
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
  // How many finite luminances l of the window have below(l), a predicate true for a prefix of
  // the ascending order.
  template <class Below>
  size_t count_below(Below below) const;

  std::vector<float> grouped_;  // finite luminances of the window, grouped by key >> 16, groups ascending
  std::vector<uint32_t> start_;  // group g (non-empty groups only) is grouped_[start_[g], start_[g + 1])
  std::vector<float> lo_, hi_;  // each group's least and greatest luminance
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

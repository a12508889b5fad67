// tiershade bake: Probulator's irradiance reference, reproduced so that an ambient-cube fit can be
// measured on the very metric Probulator publishes (github kayru/Probulator, Experiments.cpp and
// Experiments.h: its reference experiment "Monte Carlo [Importance Sampling]", 5000 samples, jitter
// off, every other experiment compared against it). The method, as Probulator states it: each
// lat-long pixel's direction at uv = (p + 0.5) / (size - 1); texels drawn in proportion to their
// intensity (the RGB mean) x solid angle by Walker's alias method (Vose's construction, Schwarz,
// "Darts, Dice, and Coins"), from one std::mt19937 seeded 0 for every pixel (jitter off: the same
// samples everywhere); E/pi = (1 / (N pi)) sum L A max(0, n . w) / p, in float. Our own code, written
// from that description. docs/irradiance_volume.md, "Accuracy on the shipped probes".
#pragma once
#include <vector>

#include "base/image.h"

// Probulator's pixel grid and its reference for a w x h probe, in our layout (rows bottom-up, RGB).
struct ProbulatorReference {
  int w = 0, h = 0;
  std::vector<double> dir;  // 3 per pixel: the unit direction at uv = (p + 0.5) / (size - 1)
  std::vector<double> solid_angle;  // per pixel: its texel's solid angle (the solid-angle metric)
  std::vector<double> e;  // 3 per pixel: the Monte Carlo E/pi there
};
ProbulatorReference probulator_reference(const ImageF &probe, int samples = 5000);

// The exact E/pi of the probe at the reference's directions (texels as constant radiance over their
// solid angle, glue/bake/ambient_fit.h's probe_irradiance_at), for the same grid.
ProbulatorReference exact_reference_on_probulator_grid(const ImageF &probe, int threads = 0);

// The non-negative least-squares cube against the reference's E/pi, every pixel alike (Probulator's
// ExperimentAmbientCube) or by solid angle.
void fit_cube_to_reference(const ProbulatorReference &r, bool solid_angle, float cube[6][3]);

// The cube's RMS against the reference: over pixels (Probulator's metric: the three channels' mean
// squared errors averaged) and solid-angle weighted.
struct ReferenceError {
  double rms_pixels = 0, rms_solid_angle = 0;
};
ReferenceError cube_reference_error(const float cube[6][3], const ProbulatorReference &r);

// tiershade bake: ambient cubes fitted to lat-long light probes (c_ref/offline/ambient_cube_fit.c
// does the arithmetic), and the error of a cube against the probe's exact irradiance, measured the
// way Probulator measures it (github kayru/Probulator: RMS over the lat-long pixels of the
// irradiance over pi, the three channels' mean squared errors averaged) and solid-angle weighted.
// Probe convention: glue's probe reader, +Y up, u = atan2(x, -z) / 2pi + 0.5, v = acos(y) / pi,
// ImageF rows bottom-up (row 0 is v = 1).
#pragma once
#include <string>
#include <vector>

#include "base/image.h"

// Mean: Source's per-axis cosine-weighted mean. Lsq: least squares against E/pi weighted by solid
// angle (a linear map of the radiance: costs what the mean costs). LsqPixels: least squares against
// E/pi with every lat-long pixel weighted alike, Probulator's fit (needs the probe's exact
// irradiance first: probes only). LsqRadiance: least squares against the radiance (for comparison).
enum class AmbientFit { Mean, Lsq, LsqPixels, LsqRadiance };

// "mean", "lsq", "lsq-pixels", "lsq-radiance"; false for anything else.
bool ambient_fit_from_name(const std::string &name, AmbientFit *fit);
const char *ambient_fit_name(AmbientFit fit);

// A lat-long probe from a Radiance .hdr or an OpenEXR .exr (by extension); false with *err naming
// the file otherwise.
bool read_latlong_probe(const std::string &path, ImageF *probe, std::string *err);

// The direction of texel (x, row y) of a w x h lat-long image (row 0 bottom), at its centre, and
// its exact solid angle (delta phi * (cos theta0 - cos theta1)).
void latlong_texel(int w, int h, int x, int y, double d[3], double *solid_angle);

// The six colours (+X -X +Y -Y +Z -Z) of the probe fitted with `fit`; every texel is one sample.
// LsqPixels computes the probe's exact irradiance on `threads` workers (0 = all cores) first.
void fit_probe_cube(const ImageF &probe, AmbientFit fit, float cube[6][3], int threads = 0);

// The exact irradiance over pi, E(n)/pi, at every texel centre of the probe (texels as constant
// radiance over their solid angle, summed in double; rows on `threads` workers, the same bytes for
// any count). RGB, 3 per texel, rows bottom-up.
std::vector<double> probe_irradiance(const ImageF &probe, int threads);

// The exact E(n)/pi of the probe at each of the unit directions `n` (3 per direction; texels as above:
// constant radiance over their exact solid angle, summed in double), directions on `threads` workers
// (0 = all cores; the same bytes for any count). RGB, 3 per direction. The sphere picture's reference
// (glue/demo/ambient_sphere.cpp).
std::vector<double> probe_irradiance_at(const ImageF &probe, const std::vector<double> &n, int threads);

// Probulator's way (ExperimentAmbientCube: non-negative least squares of the basis against an
// irradiance image, one equation per lat-long pixel): the cube fitted to E/pi given at every texel
// centre (from probe_irradiance), each pixel weighted alike (solid_angle false) or by its solid angle.
void fit_cube_to_irradiance(const std::vector<double> &exact, int w, int h, bool solid_angle, float cube[6][3]);

struct CubeIrradianceError {
  double rms_pixels = 0;       // Probulator's metric: every lat-long pixel counts the same
  double rms_solid_angle = 0;  // each pixel weighted by its solid angle
};
// The cube's irradiance error against the exact irradiance (from probe_irradiance) of a w x h probe.
CubeIrradianceError cube_irradiance_error(const float cube[6][3], const std::vector<double> &exact, int w, int h);

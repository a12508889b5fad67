// tiershade glue: the demo/benchmark scene of the model-lighting family: a grid of
// lit spheres (orthographic view), six coloured lights of all three types and an
// ambient cube. Lights beyond a tier's limit are folded into the cube
// (c_ref/light_folding.c, docs/light_folding.md).
#pragma once
#include <string>
#include <vector>

#include "family.h"
#include "light_folding.h"

struct SphereScene {
  int cols = 5, rows = 3;
  std::vector<ts_light> lights;
  float ambient[6][3];
  float tone_map_scale = 0.6f;
};

SphereScene default_sphere_scene();

struct SphereFrame {
  FamilyInputs in;          // G-buffer (normal, position, uv) + shared slots for the tier
  std::vector<uint8_t> hit;  // 1 where a sphere covers the pixel
  int lights_kept = 0, lights_folded = 0;
};

// Builds the frame of `scene` at w x h for a tier that shades at most max_local lights.
bool sphere_frame(const SphereScene &scene, int w, int h, int max_local, SphereFrame *out, std::string *err);

// The reference: linear radiance (rgb per pixel, double) with every light local
// (none folded), evaluated with the double twin; background pixels are 0.
void sphere_reference_linear(const SphereScene &scene, const SphereFrame &frame, std::vector<double> *rgb);

// Zeroes background pixels (rgb 0, alpha 1) so GL, C and reference frames compare alike.
void sphere_mask(const SphereFrame &frame, ImageF *img);

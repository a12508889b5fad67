// tiershade base: a 3D colour LUT in memory (Lut3D), the one type the LUT files (io/lut_files),
// the OpenColorIO bake (color/ocio_lut_bake) and the LUT textures (color/lut_texture) share.
#pragma once
#include <string>
#include <vector>

// A 3D LUT of edge n: n^3 RGB triples, red fastest, then green, then blue (the .cube order).
struct Lut3D {
  int n = 0;
  std::vector<float> rgb;  // n * n * n * 3
  std::string title;  // informative (the .cube TITLE, or where it came from)
  const float *at(int r, int g, int b) const { return &rgb[3 * ((static_cast<size_t>(b) * n + g) * n + r)]; }
  float *at(int r, int g, int b) { return &rgb[3 * ((static_cast<size_t>(b) * n + g) * n + r)]; }
};

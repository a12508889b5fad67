// tiershade glue: a 3D colour LUT as the textures color_correction samples: a 3D
// texture (x red, y green, z blue) or the 2D atlas of ES2/WebGL1 (the N blue slices
// side by side: width N*N, height N, texel (r, g, b) at (b*N + r, g)), RGBA32F with
// alpha 1; and the C sampler views of those textures (docs/color_correction.md).
#pragma once
#include <string>
#include <vector>

#include "gl/float_target.h"
#include "math/ts_sampler.h"
#include "math/ts_sampler3d.h"

// A 3D LUT of edge n: n^3 RGB triples, red fastest, then green, then blue (the .cube order).
struct Lut3D {
  int n = 0;
  std::vector<float> rgb;  // n * n * n * 3
  std::string title;       // informative (the .cube TITLE, or where it came from)
  const float *at(int r, int g, int b) const { return &rgb[3 * ((static_cast<size_t>(b) * n + g) * n + r)]; }
  float *at(int r, int g, int b) { return &rgb[3 * ((static_cast<size_t>(b) * n + g) * n + r)]; }
};

// The identity LUT of edge n: node (r, g, b) holds (r, g, b) / (n - 1).
Lut3D identity_lut(int n);

TextureDesc lut_volume_texture(const Lut3D &lut, const std::string &sampler, bool linear);
TextureDesc lut_atlas_texture(const Lut3D &lut, const std::string &sampler, bool linear);

// The C sampler's view of a 3D texture (same filtering and wrapping; see family.h for 2D).
ts_tex3d tex3d_of(const TextureDesc &t);

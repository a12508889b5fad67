// tiershade color: a 3D colour LUT as the textures color_correction samples: a 3D
// texture (x red, y green, z blue) or the 2D atlas of ES2/WebGL1 (the N blue slices
// side by side: width N*N, height N, texel (r, g, b) at (b*N + r, g)), RGBA32F with
// alpha 1; and the C sampler views of those textures (docs/color_correction.md).
#pragma once
#include <string>
#include <vector>

#include "base/lut3d.h"
#include "gl/float_target.h"
#include "math/ts_sampler.h"
#include "math/ts_sampler3d.h"

// The identity LUT of edge n: node (r, g, b) holds (r, g, b) / (n - 1).
Lut3D identity_lut(int n);

TextureDesc lut_volume_texture(const Lut3D &lut, const std::string &sampler, bool linear);
TextureDesc lut_atlas_texture(const Lut3D &lut, const std::string &sampler, bool linear);

// The C sampler's view of a 3D texture (same filtering and wrapping; see family.h for 2D).
ts_tex3d tex3d_of(const TextureDesc &t);

// tiershade scene: procedural textures for the demo scenes (normal map, exponent map,
// light-warp ramp) and cube maps and ambient cubes made from real light probes
// (latitude-longitude .hdr, ../shared/data/probes/).
#pragma once
#include <string>

#include "gl/float_target.h"

TextureDesc make_bump_normal_map(const char *sampler, int n);  // rgb tangent normal, a spec mask
TextureDesc make_exponent_map(const char *sampler, int n);  // r exponent, g tint mask, a rim mask
TextureDesc make_warp_ramp(const char *sampler);  // 64 x 1, warm to cool
TextureDesc make_sky_cube(const char *sampler, int size);  // procedural sky, no file needed

// Resamples a lat-long probe into a cube map of `size` (bilinear in the probe) and
// computes its ambient cube: the non-negative least-squares fit to the probe's irradiance
// (glue/bake/ambient_fit.h, docs/irradiance_volume.md; Source's per-axis mean is the other fit).
bool cube_from_probe(const std::string &path, const char *sampler, int size, TextureDesc *cube, float ambient[6][3],
                     std::string *err);

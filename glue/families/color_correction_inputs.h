// tiershade families: input records and LUT textures of the color_correction family, for
// the demo, the benchmark and the tests (the family itself: color_correction.cpp).
#pragma once
#include <vector>

#include "twins/color_correction.h"
#include "families/family.h"
#include "base/image.h"
#include "color/lut_texture.h"

// Sets in->textures to the eight LUT textures color_correction declares: u_lut0..3 (3D)
// then u_lut_atlas0..3 (2D atlas), from up to four LUTs of one edge (missing ones: a 2^3
// identity, never sampled). linear: GL_LINEAR for hardware filtering; shader-filtered
// variants take GL_NEAREST (docs/color_correction.md).
void cc_set_luts(FamilyInputs *in, const std::vector<const Lut3D *> &luts, bool linear);

// A deferred frame: the per-pixel colour from `frame` (rows bottom-up, as ImageF), and the
// shared weights, default weight and addressing of LUT edge lut_n.
void cc_frame_inputs(const ImageF &frame, const float weights[4], float default_weight, int lut_n, FamilyInputs *in);

// The C twin's view of in->textures (as laid out by cc_set_luts).
void cc_luts_of(const FamilyInputs &in, cc_luts *out);

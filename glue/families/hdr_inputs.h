// tiershade families: input generators shared by the HDR post-processing families
// (bloom_downsample, bloom_blur, hdr_tonemap, luminance_compare): half-quantised
// HDR textures like the fp16 frames they read, and fragment positions.
#pragma once
#include <string>

#include "families/family.h"

// A w x h RGBA32F texture holding values an fp16 target can hold (each rounded toward
// zero to half, as llvmpipe writes them: c_ref/math/hdr_formats.h): mostly a wide HDR
// range (1e-3 .. 64, log-uniform), with some zeros, 65504s and half denormals.
TextureDesc hdr_test_texture(Rng &r, const std::string &sampler, int w, int h, bool linear);

// The textures of a family that samples one such texture (bilinear, named Sampler, W x H),
// drawn after its records (families/record_family.h: record_inputs).
template <const char *Sampler, int W, int H>
void one_hdr_texture(Rng &r, InputSet, FamilyInputs *out) {
  out->textures = {hdr_test_texture(r, Sampler, W, H, true)};
}

// A fragment position in a w x h target: half of the time an exact pixel centre
// (i + 0.5, as gl_FragCoord gives), otherwise anywhere in [-1, w + 1] x [-1, h + 1].
ts_vec4f random_fragment_position(Rng &r, int w, int h);

// (w, h, 1/w, 1/h) in float, as the glue passes a texture's size to the shaders.
ts_vec4f size_slot(int w, int h);

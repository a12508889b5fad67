// tiershade demo: the frame and the example corrections of the colour-correction demo and
// benchmark (docs/color_correction.md, "Demo and benchmark").
#pragma once
#include <string>
#include <vector>

#include "base/image.h"
#include "color/ocio_lut_bake.h"
#include "color/lut_texture.h"

// A display-encoded w x h frame (rows bottom-up, alpha 1): the top two thirds are a light
// probe (TIERSHADE_PROBE_HDR, else ../shared/data/probes/grace.hdr) made displayable with a
// plain exposure (log-average luminance to 0.18), a clip at 1 and the sRGB curve; the bottom
// third is a colour chart (hue x value sweep, then a grey ramp). Without a readable probe the
// chart fills the frame. *note says which.
ImageF cc_frame(int w, int h, std::string *note);

// The example corrections, as OpenColorIO transforms: the colourist-style .cube files of
// scenes/luts (day_for_night.cube, desaturate.cube, read through FileTransform) and the ASC
// CDL scenes/luts/warm.cc. Paths are relative to the repository root.
struct CcExample {
  std::string name, file;
  ColorTransform transform;
};
bool cc_examples(std::vector<CcExample> *out, std::string *err);

// Applies `t` to every pixel of a frame with OpenColorIO's CPU processor (the reference);
// the result is clamped to [0, 1], as the shader's saturate and an 8-bit target do.
ImageF cc_apply_reference(const ColorTransform &t, const ImageF &frame);

// CIEDE2000 between two display-encoded frames of the same size: max and mean.
void cc_frame_difference(const ImageF &a, const ImageF &b, double *max, double *mean);

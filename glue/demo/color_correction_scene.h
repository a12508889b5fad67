// tiershade demo: the frame and the example corrections of the colour-correction demo and
// benchmark (docs/color_correction.md, "Demo and benchmark").
#pragma once
#include <string>
#include <vector>

#include "base/image.h"
#include "color/ocio_lut_bake.h"
#include "color/lut_texture.h"
#include "scene/frame.h"

// The frame: scenes/probe_chart.gltf (docs/scenes.md: mirror spheres reflecting the Grace
// Cathedral and Uffizi probes above a colour chart) rendered at sm3 by the scene renderer with
// cfg's backend (Backend::CPU: the C fallback) at cfg.w x cfg.h, integer HDR path: *frame is the
// display frame (codes / 255, rows bottom-up, alpha 1) before any colour correction (the scene
// has no LUTs: colour correction is what the demo and benchmark apply to it), *res the whole
// render result (times, --check counts when cfg.check), *note what the frame is.
bool cc_scene_frame(const SceneRenderConfig &cfg, ImageF *frame, SceneRenderResult *res, std::string *note,
                    std::string *err);
// The frame the demo and benchmark correct: the C fallback's, size x size (the scene's view is
// square); *frame_ms (optional) the time it took.
bool cc_frame_c(int size, ImageF *frame, std::string *note, std::string *err, double *frame_ms = nullptr);

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

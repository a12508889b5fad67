// tiershade scene: the C fallback's vertex stage: the production vertex shaders' outputs
// (model_lighting.vs, world_lighting.vs) in float, with llvmpipe's window position and clip data
// per vertex, in the layout the C fallback's interpolation reads (glue/scene/cpu_renderer.cpp).
#pragma once
#include <vector>

#include "scene/prepare.h"

const int kVary = 24;  // 6 slots x 4 (a G-buffer record)
// Per vertex: the 24 slot floats, then llvmpipe's window position (x, y, z, 1/w: lp_window_pos),
// the clip position, the clip mask (lp_clipmask, as a float), 3 floats of padding.
const int kVStride = 36;
const int kWin = 24, kClip = 28, kClipMask = 32;
const int kPixelSlots = 6;  // ML_PIXEL_SLOTS == WL_PIXEL_SLOTS

// The vertex outputs of draw d into *vary (kVStride floats a vertex), its clip positions into *clip.
void vertex_stage(const PreparedScene &p, const PreparedDraw &d, std::vector<float> *clip, std::vector<float> *vary);

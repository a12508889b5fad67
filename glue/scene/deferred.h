// tiershade scene: deferred frames of a scene: the scene renderer's G-buffer (its C rasteriser,
// glue/scene/cpu_renderer.h) as a shader family's per-pixel inputs (FamilyInputs: the pixel
// slots per pixel, the draw's shared slots as production uniforms, its textures), for the
// benchmarks and accuracy tables that run one variant after another over the same frame.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "families/family.h"
#include "base/image.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"

// The C renderer's G-buffer of `s` at w x h for `tier`: the selection, the prepared frame (which
// points into the selection: keep them together, do not copy), and per pixel its draw (-1 where
// none) and its record slots (scene_records_cpu). all_features as in scene_deferred_frame.
struct SceneGBufferCpu {
  SceneSelection sel;
  PreparedScene p;
  std::vector<int> draw;
  std::vector<float> slots;
};
bool scene_gbuffer_cpu(const Scene &s, Tier tier, int w, int h, bool all_features, SceneGBufferCpu *g,
                       std::string *err);

struct SceneDeferredFrame {
  FamilyInputs in;  // model_lighting records: ML_PIXEL_SLOTS per pixel, ML_SLOTS shared
  std::vector<uint8_t> hit;  // 1 where the draw covers the pixel
  int lights_local = 0, lights_folded = 0;
  std::vector<double> reference;  // with_reference: scene_reference_linear's rgb (3 per pixel)
};

// The frame of `s` at w x h as the C renderer rasterises it, with the lights folded for `tier`
// (ps20: 2 local, else 4). The scene's visible geometry must be one model_lighting draw (one
// glTF primitive): a frame has one set of uniforms. all_features: the selection's baseline
// variant (every feature the material has sampled: its real textures; glue/scene/selection.h).
bool scene_deferred_frame(const Scene &s, Tier tier, int w, int h, SceneDeferredFrame *out, std::string *err,
                          bool all_features = false, bool with_reference = false);

// Background pixels of img (a frame shaded from f) to rgb 0, alpha 1, so that GL, C and reference
// frames compare alike (the background's records are zero: its shading means nothing).
void scene_deferred_mask(const SceneDeferredFrame &f, ImageF *img);

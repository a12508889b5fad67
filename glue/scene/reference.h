// tiershade scene: the reference frame of a scene: linear radiance in double precision with every
// light shaded per pixel (none folded into the ambient cube) and the lightmaps unquantised, from a G-buffer of the scene renderer
// (scene_records_cpu, or SceneGl::gbuffer). The accuracy of a tier's frame is measured against it.
#pragma once
#include <string>
#include <vector>

#include "scene/prepare.h"
#include "scene/scene.h"

// rgb: 3 doubles per pixel (rows bottom-up as the frame), 0 on the background. Each world pixel runs
// the double twin (c_ref/twins/world_lighting.h) of its draw's variant at sm3 with LIGHTMAP_ENCODING 0
// on the float32 page (PreparedScene::lightmap_page, before any run-time encoding). Each model pixel
// runs the double twin (c_ref/twins/model_lighting.h) of its draw's variant at sm3 with OUTPUT_MODE
// 0 (linear, the frame's tone-map scale), once per group of ML_MAX_LIGHTS lights of the scene; the
// shading is linear in the lights, so the groups add up, and the first carries the draw's ambient
// cube before folding (PreparedDraw::ambient).
bool scene_reference_linear(const Scene &s, const PreparedScene &p, const std::vector<int> &draw,
                            const std::vector<float> &slots, std::vector<double> *rgb, std::string *err,
                            int threads = 0);

// tiershade scene: what the lightmap bake takes from a scene: its lights as the baker's lights
// (c_ref/offline/rnm_bake.h) with each sun's spread, and the ray scene of every triangle.
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "bake/ray_scene.h"
#include "bake/world_bake.h"
#include "scene/scene.h"

// The scene's lights (point, spot with vrad's cone, directional) into in->lights, and each light's
// angular spread (a sun's soft shadows, glue/bake/world_bake.h) into in->light_spread.
void bake_lights_of(const Scene &s, WorldBakeInput *in);

// The bake's quality (glue/bake/bake_quality.h): the scene's, or, for a page read from a bake
// directory, the one its manifest records (the page's layout follows the luxel density it was
// baked at); *note: what a render reports when that is not the scene's ("" otherwise).
BakeQuality scene_bake_quality(const Scene &s, std::string *note);

// The process's CPU time (every thread's), in ms: the bake's share of it (the bench's Embree share).
double process_cpu_ms();

// One Embree scene of every primitive's triangles (glue/bake/ray_scene.h): a world face's carry its
// face index (face_of_draw[primitive], the bounces and probes read its luxels), an emissive model's
// model_emitter_id((*emitter_of)[primitive]) (glue/bake/area_lights.h), other geometry -2.
// Errors name the scene file and the primitive.
bool build_scene_rays(const Scene &s, const std::vector<int> &face_of_draw, RayScene *rays, std::string *err,
                      const std::vector<int> *emitter_of = nullptr);

// The mean linear colour of a texture's image (sRGB-decoded: base colour and emissive textures are
// sRGB); 1 without an image.
glm::dvec3 texture_mean_linear(const Scene &s, const SceneTextureRef &t);

// The primitives that are no world face (face_of_draw[primitive] < 0) whose material emits
// (emissiveFactor x KHR_materials_emissive_strength x the emissive texture's mean, as a face's
// emission): the bake's model emitters, in world space; *emitter_of: per primitive, its index (-1).
std::vector<ModelEmitter> scene_model_emitters(const Scene &s, const std::vector<int> &face_of_draw,
                                               std::vector<int> *emitter_of);

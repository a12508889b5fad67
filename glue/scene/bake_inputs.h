// tiershade scene: what the lightmap bake takes from a scene: its lights as the baker's lights
// (c_ref/offline/rnm_bake.h) with each sun's spread, and the ray scene of every triangle.
#pragma once
#include <string>
#include <vector>

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
// face index (face_of_draw[primitive], the bounces and probes read its luxels), other geometry -2.
// Errors name the scene file and the primitive.
bool build_scene_rays(const Scene &s, const std::vector<int> &face_of_draw, RayScene *rays, std::string *err);

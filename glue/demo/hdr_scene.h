// tiershade demo: the HDR demo and benchmark scenes: the sphere grid before a wall, under two
// lightings with a real dynamic range: scenes/hdr_daylight.gltf (a sun, a sky ambient cube from
// the Uffizi probe, a hot spot on the wall) and scenes/hdr_dark_room.gltf (one dim lamp), both
// written by tools/make_scenes.py and framed by the scene renderer (glue/scene/deferred.h).
#pragma once
#include <string>

#include "demo/scene_files.h"
#include "scene/deferred.h"

// The scene's deferred frame at sm3 (4 local lights: none folded), every pixel lit (the wall is
// behind the spheres); *note says where its ambient cube comes from.
bool hdr_scene_frame(const char *gltf, int w, int h, SceneDeferredFrame *out, std::string *note, std::string *err);

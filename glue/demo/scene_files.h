// tiershade demo: the glTF scenes the demo and benchmark sections render (written by
// tools/make_scenes.py; docs/scenes.md), found from the executable (scene_files.cpp).
#pragma once

extern const char *const kSphereGridGltf;  // scenes/sphere_grid.gltf: the model-lighting grid
extern const char *const kSphereGridLights;  // scenes/sphere_grid.lights: its lights, their one source
extern const char *const kPhongSphereGltf;  // scenes/phong_sphere.gltf: the Episode One sphere
extern const char *const kProbeChartGltf;  // scenes/probe_chart.gltf: the colour-correction frame
extern const char *const kHdrDaylightGltf;  // scenes/hdr_daylight.gltf
extern const char *const kHdrDarkRoomGltf;  // scenes/hdr_dark_room.gltf
extern const char *const kWorldLightingGltf;  // scenes/world_lighting.gltf: the lightmapped room

// Another repository file by its name from the root ("scenes/luts/warm.cc"), found as above.
const char *repo_file(const char *rel);

// tiershade demo: the scene file names (scene_files.h).
#include "demo/scene_files.h"

const char *const kSphereGridGltf = "scenes/sphere_grid.gltf";
const char *const kSphereGridLights = "scenes/sphere_grid.lights";
const char *const kPhongSphereGltf = "scenes/phong_sphere.gltf";
const char *const kProbeChartGltf = "scenes/probe_chart.gltf";
const char *const kHdrDaylightGltf = "scenes/hdr_daylight.gltf";
const char *const kHdrDarkRoomGltf = "scenes/hdr_dark_room.gltf";
const char *const kWorldLightingGltf = "scenes/world_lighting.gltf";

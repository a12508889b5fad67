// tiershade scene: debug views of a scene, as derived scenes: what the talk's world-lighting
// comparison shows ("Light Maps Only" against "Final Rendered Scene", and a level without bump
// maps). A view changes materials only, so selection derives its variants as for any scene and
// the renderer draws it unchanged on every backend.
#pragma once
#include <string>

#include "scene/scene.h"

enum class SceneView {
  Final,  // the scene as authored
  Lightmaps,  // world materials: white base, no envmap (the lightmaps with their normal maps, RNM)
  FlatLightmaps,  // Lightmaps without the normal maps: the flat lightmap alone (BUMPMAP 0)
};

// "final" | "lightmaps" | "flat_lightmaps"
const char *scene_view_name(SceneView v);
bool scene_view_from_name(const std::string &name, SceneView *v);

// The scene as the view draws it (model materials are kept as they are).
Scene scene_view(const Scene &s, SceneView v);

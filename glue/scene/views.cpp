// tiershade scene: debug views of a scene (views.h).
#include "scene/views.h"

namespace {
const char *const kNames[] = {"final", "lightmaps", "flat_lightmaps"};
}

const char *scene_view_name(SceneView v) { return kNames[static_cast<int>(v)]; }

bool scene_view_from_name(const std::string &name, SceneView *v) {
  for (int i = 0; i < 3; ++i)
    if (name == kNames[i]) {
      *v = static_cast<SceneView>(i);
      return true;
    }
  return false;
}

Scene scene_view(const Scene &s, SceneView v) {
  Scene o = s;
  if (v == SceneView::Final) return o;
  for (SceneMaterial &m : o.materials) {
    if (m.shader != SceneShader::World) continue;
    m.base_texture = SceneTextureRef();
    for (float &c : m.base_color) c = 1.f;
    m.envmap = false;
    m.envmap_mask = SceneEnvMask::None;
    m.envmap_mask_texture = SceneTextureRef();
    if (v == SceneView::FlatLightmaps) {
      m.normal_texture = SceneTextureRef();
      m.ssbump = false;
    }
  }
  return o;
}

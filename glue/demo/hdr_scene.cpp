// tiershade demo: the HDR demo and benchmark scenes (see hdr_scene.h).
#include "demo/hdr_scene.h"

bool hdr_scene_frame(const char *gltf, int w, int h, SceneDeferredFrame *out, std::string *note, std::string *err) {
  Scene s;
  if (!load_scene(gltf, &s, err) || !scene_deferred_frame(s, Tier::SM3, w, h, out, err)) return false;
  if (!s.ambient.empty() && s.ambient[0].from_probe >= 0)
    *note =
        std::string(gltf) + ", sky ambient cube from " + s.images.at(s.probes.at(s.ambient[0].from_probe).image).path;
  else
    *note = std::string(gltf) + ", its ambient cube";
  return true;
}

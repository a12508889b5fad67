// tiershade scene: a scene's probes as its draws use them (talk: "World specular ... cube maps are
// placed in the level"): an image probe's cube map and ambient cube (glue/scene/textures.h
// cube_from_probe); a world probe's cube map, rendered in-engine from the baked world after the
// draws are prepared (glue/scene/probe_render.h; a black placeholder of its size until then) or ray
// traced by the baker (glue/bake/world_bake.h; probes[].source "rays"); and the best probe of a
// world surface: the nearest one it can see.
#pragma once
#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "gl/float_target.h"
#include "scene/scene.h"

class RayScene;

// Each probe's cube map and ambient cube, made on first use (only what an ENVMAP draw or an
// ambient sample asks for).
struct SceneProbeSet {
  explicit SceneProbeSet(const Scene &sc) : s(sc) {}
  const Scene &s;
  std::map<int, TextureDesc> cubes;  // scaled by the probe's scale
  std::map<int, std::array<std::array<float, 3>, 6>> ambient;
  std::vector<TextureDesc> traced;  // index = probe: the baker's ray-traced cube (w 0: not traced)
  bool have_world = false;  // the scene has baked world faces to render or trace a world probe from
  std::set<int> pending;  // world probes whose cube is rendered in-engine after preparation
  bool cube(int p, TextureDesc *out, float amb[6][3], std::string *err);
};

// Whether world probe p's cube is the baker's ray-traced one: its probes[].source is "rays", or an
// ambient sample's from_probe names it (that ambient cube is needed while the draws are prepared,
// before a renderer exists). Else it is rendered in-engine.
bool probe_traced(const Scene &s, int p);

// The probe of a world surface centred at `centre` (front normal `normal`, not necessarily unit):
// explicit_index when >= 0, else the nearest probe with a clear line of sight (no triangle of
// `rays` on the segment from the centre, lifted 1e-4 along the normal, to the probe), else (none
// seen, or rays null) the nearest; the lowest index on a tie; -1 without probes.
int best_probe(const Scene &s, const RayScene *rays, const double centre[3], const double normal[3],
               int explicit_index);

// tiershade demo: the world_lighting demo and benchmark scene: a room of five
// normal-mapped walls lit by three coloured point lights, baked into radiosity-
// normal-mapped lightmaps (c_ref/offline/rnm_bake.c) on one lightmap page (c_ref/offline/lightmap_page.c),
// with two cube-map probes rendered from the room itself; each wall takes the nearest
// probe unless it names one (c_ref/offline/envmap_probes.c). Frames are deferred-style:
// a per-pixel G-buffer record (ray cast from a pinhole camera) plus shared uniforms.
#pragma once
#include <string>
#include <vector>

#include "bake/world_bake.h"
#include "families/world_lighting.h"

// The room: the faces, lights and probes of a bake (glue/bake/world_bake.h) and a camera.
struct WorldScene : WorldBakeInput {
  ts_vec3d eye, target;
  double fov_y_deg = 60;
  float tone_map_scale = 0.45f;
};

WorldScene default_world_scene();

struct WorldFrame {
  FamilyInputs in;  // G-buffer slots + shared uniforms; textures set per pass
  std::vector<int> probe;  // per pixel: the cube-map probe of its face, -1 = background
  std::vector<TextureDesc> materials;  // u_base, u_normalmap, u_envmap_mask
};
bool world_frame(const WorldScene &s, const WorldBake &b, int w, int h, WorldFrame *out, std::string *err);

// The textures of one pass: the materials (or a white base for "lightmaps only"), the
// encoded page, and probe p's cube, NEAREST when `nearest_cube` (GLES: seamless cubes).
std::vector<TextureDesc> world_pass_textures(const WorldFrame &f, const TextureDesc &page, const WorldBake &b, int p,
                                             bool white_base, bool nearest_cube);

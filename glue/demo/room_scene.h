// tiershade glue: the world_lighting demo and benchmark scene: a room of five
// normal-mapped walls lit by three coloured point lights, baked into radiosity-
// normal-mapped lightmaps (c_ref/offline/rnm_bake.c) on one lightmap page (c_ref/offline/lightmap_page.c),
// with two cube-map probes rendered from the room itself; each wall takes the nearest
// probe unless it names one (c_ref/offline/envmap_probes.c). Frames are deferred-style:
// a per-pixel G-buffer record (ray cast from a pinhole camera) plus shared uniforms.
#pragma once
#include <string>
#include <vector>

#include "families/world_lighting.h"
#include "offline/lightmap_page.h"
#include "offline/rnm_bake.h"

struct WorldFace {
  const char *name;
  ts_vec3d origin, u, v;  // corner and unit edge directions (u = the S texture axis, v = T)
  double su, sv;          // edge lengths
  int probe;              // explicit cube-map probe, or -1 for the nearest
  ts_vec3d normal = {0, 0, 0};  // the face's front normal; zero: u x v turned towards the demo room's centre
};

struct WorldScene {
  std::vector<WorldFace> faces;
  std::vector<rnm_light> lights;
  std::vector<ts_vec3d> probes;
  ts_vec3d eye, target;
  double fov_y_deg = 60;
  double luxels_per_unit = 6;
  int page_w = 512, page_h = 256;
  int cube_size = 64;
  float tone_map_scale = 0.45f;
  bool bake_luxels = true;  // false: the page is left black (alpha 1) for a page read from a file
};

WorldScene default_world_scene();

// The baked lighting: the page in float32 (flat, b0, b1, b2 per face, borders filled),
// the faces' places in it, each face's probe and the probes' cube maps (linear radiance).
struct WorldBake {
  std::vector<lm_face_place> place;
  std::vector<float> page;  // page_w x page_h RGBA32F, alpha 1
  std::vector<int> face_probe;
  std::vector<TextureDesc> cubes;  // "u_envmap", LINEAR (a frame for GLES switches them to NEAREST)
};
bool bake_world(const WorldScene &s, WorldBake *out, std::string *err);

// Lightmap encodings of the page for the shader (LIGHTMAP_ENCODING 0..3, -1 = float32
// unquantised): what each run-time format stores, uploaded as RGBA32F holding exactly
// those values. RGBE is sampled NEAREST (it does not filter), the others LINEAR.
TextureDesc encode_page(const WorldScene &s, const WorldBake &b, int encoding);
// The value a texel of that encoding decodes to (double), for error measurements.
void decode_texel(int encoding, const float texel[4], double rgb[3]);

struct WorldFrame {
  FamilyInputs in;               // G-buffer slots + shared uniforms; textures set per pass
  std::vector<int> probe;        // per pixel: the cube-map probe of its face, -1 = background
  std::vector<TextureDesc> materials;  // u_base, u_normalmap, u_envmap_mask
};
bool world_frame(const WorldScene &s, const WorldBake &b, int w, int h, WorldFrame *out, std::string *err);

// The textures of one pass: the materials (or a white base for "lightmaps only"), the
// encoded page, and probe p's cube, NEAREST when `nearest_cube` (GLES: seamless cubes).
std::vector<TextureDesc> world_pass_textures(const WorldFrame &f, const TextureDesc &page, const WorldBake &b, int p,
                                             bool white_base, bool nearest_cube);

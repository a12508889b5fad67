// tiershade demo: analytic G-buffer frames of the sphere grid (orthographic view, spheres
// hit per pixel), still used by the benchmarks, the HDR scene and the Phong section; the demo's
// model-lighting tiers render scenes/sphere_grid.gltf through the scene renderer instead. Lights beyond a tier's limit are folded into the cube
// (c_ref/offline/light_folding.c, docs/light_folding.md).
#pragma once
#include <string>
#include <vector>

#include "families/family.h"
#include "offline/light_folding.h"

// The Episode One material parameters (fact sheet section 5), used by PHONG variants.
struct PhongMaterial {
  float exponent = 20.f, exponent_factor = 149.f, boost = 1.f;
  float fresnel_min = 0.15f, fresnel_mid = 0.5f, fresnel_max = 1.f;
  float tint[3] = {1, 1, 1};
  bool albedo_tint = false;
  float rim_exponent = 4.f, rim_boost = 1.f, rim_mask = 1.f;
  float envmap_scale = 0.25f, envmap_fresnel = 1.f;
  float envmap_tint[3] = {1, 1, 1};
  float self_illum[4] = {0, 0, 0, 0};  // rgb tint, amount
};

struct SphereScene {
  int cols = 5, rows = 3;
  std::vector<ts_light> lights;
  float ambient[6][3];
  float tone_map_scale = 0.6f;
  PhongMaterial phong;
  std::vector<TextureDesc> textures;  // u_albedo, u_normal_map, u_exponent_map, u_light_warp, u_envmap
};

// The grid's lights, ambient cube and tone-map scale from scenes/sphere_grid.gltf (the scene the
// demo renders through the scene renderer; its lights come from scenes/sphere_grid.lights), with
// the procedural textures of the analytic frames below.
extern const char *const kSphereGridGltf;
extern const char *const kSphereGridLights;  // scenes/sphere_grid.lights
bool sphere_grid_scene(SphereScene *out, std::string *err);
// The procedural textures: albedo bands, bump normal map, exponent map, warp ramp, sky cube.
std::vector<TextureDesc> sphere_grid_textures();
// One big sphere lit for the Episode One Phong comparison: normal map, exponent map,
// and (when the file is readable) a cube map and ambient cube from a real light probe.
bool phong_sphere_scene(const std::string &probe_path, SphereScene *out, std::string *note, std::string *err);

struct SphereFrame {
  FamilyInputs in;          // G-buffer (normal, position, uv) + shared slots for the tier
  std::vector<uint8_t> hit;  // 1 where a sphere covers the pixel
  int lights_kept = 0, lights_folded = 0;
};

// Builds the frame of `scene` at w x h for a tier that shades at most max_local lights.
bool sphere_frame(const SphereScene &scene, int w, int h, int max_local, SphereFrame *out, std::string *err);

// Zeroes background pixels (rgb 0, alpha 1) so GL, C and reference frames compare alike.
void sphere_mask(const SphereFrame &frame, ImageF *img);

// tiershade scene: everything a frame of a scene needs, derived once from the scene and its
// variant selection (glue/scene/selection.h): the camera matrices; per draw its vertex arrays,
// the shared slots (= the production uniforms) and the textures its variant samples; the
// world's baked lightmap page and probe cube maps. Only what the selection uses is made:
// no probe cube map without an ENVMAP draw, no lightmap bake without a world draw.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "bake/irradiance_volume.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/skybox_pass.h"
#include "math/ts_math.h"
#include "bake/bake_dir.h"
#include "offline/lightmap_page.h"

// A draw's vertex arrays as its vertex shader takes them: a flattened primitive's in world space,
// or a shared mesh primitive's in object space, made once and shared by every draw of it (the GL
// renderer uploads one set of buffers per DrawGeometry, the C fallback reads it in place).
struct DrawGeometry {
  std::vector<float> position, normal, uv, tangent;  // 3, 3, 2, 4 per vertex (tangent: 0,0,0,1 when absent)
  std::vector<float> lightmap;  // world: 4 per vertex (lightmap uv, offset to the next lightmap)
  std::vector<uint32_t> indices;
  size_t vertices() const { return position.size() / 3; }
  size_t bytes() const {
    return (position.size() + normal.size() + uv.size() + tangent.size() + lightmap.size()) * sizeof(float) +
        indices.size() * sizeof(uint32_t);
  }
};

struct PreparedDraw {
  const SceneDrawChoice *choice = nullptr;
  const Variant *variant = nullptr;
  bool world = false;  // world_lighting, else model_lighting
  std::shared_ptr<const DrawGeometry> geo;  // never null after prepare_scene
  // u_model (column-major, float): a shared mesh's node matrix, else the identity; instanced:
  // not the identity (the C vertex stage multiplies by it as model_lighting.vs does).
  float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  bool instanced = false;
  int lightmap_page = 0;  // world: the page its uv is on (the stacked page's rows page x page_h on)
  std::vector<ts_vec4f> shared;  // the family's full record with the shared slots set
  std::vector<int> tex;  // indices into PreparedScene::textures, in sampler order:
      // model: u_albedo u_normal_map u_exponent_map u_light_warp u_envmap;
      // world: u_base u_normalmap u_lightmap u_envmap_mask u_envmap
  bool display_encoded = false;  // output already sRGB-encoded (model OUTPUT_MODE 2)
  float ambient[6][3] = {};  // model: the draw's ambient cube before lights were folded
      // into it (the reference shades every light locally)
  int face = -1;  // world: its face (index into PreparedScene::lightmap_places)
  float reflectivity[3] = {0, 0, 0}, emission[3] = {0, 0, 0};  // world: its face's, as the bake took them
};

// A probe's cube map in PreparedScene::textures and where it came from: "image" (a lat-long probe),
// "rays" (the baker's ray-traced cube, probes[].source "rays" or an ambient sample's from_probe),
// "pending" (a world probe to render in-engine: glue/scene/probe_render.h), then "C fallback" or
// "GL <backend>/<api>" once rendered.
struct PreparedProbeCube {
  int probe = -1, texture = -1;
  std::string source;
  double ms = 0;  // rendering it (six faces)
  // GL with check: the C twin on GL's G-buffer of each face against GL's texels (-1: not run).
  long check_texels = 0, check_mismatched = -1;
};

struct PreparedScene {
  int w = 0, h = 0;
  float view_proj[16];  // column-major, float as uploaded
  float eye[3];
  std::vector<PreparedDraw> draws;
  std::vector<TextureDesc> textures;  // every texture once, shared by the draws that sample it
  // The bytes of the draws' vertex arrays, each DrawGeometry once (what instancing keeps
  // independent of the draw count; tests/unit/test_scene_instancing.cpp).
  size_t geometry_bytes() const;
  int geometries() const;  // the distinct DrawGeometry objects
  const TextureDesc &texture(const PreparedDraw &d, int k) const { return textures.at(d.tex.at(k)); }
  float tone_map_scale = 1.f;  // of the shaders' output (integer path); the float path tone-maps later
  // What was made, for the report.
  int probes_made = 0, lightmap_texels = 0;
  // The world's lightmap page in float32 before its run-time encoding (baked, or the scene's
  // lightmaps.image): lightmap_w x lightmap_h RGBA, row 0 at the bottom; empty without world draws.
  std::vector<float> lightmap_page;
  int lightmap_w = 0, lightmap_h = 0;  // lightmap_h: every page's rows (lightmap_pages pages stacked)
  int lightmap_pages = 0;
  std::vector<lm_face_place> lightmap_places;  // each world face's blocks on the page (c_ref/offline/lightmap_page.h)
  double bake_ms = 0;
  // The bake's parts (glue/bake/world_bake.h): luxels, the direct pass and the bounces (ms), the
  // bounce passes run and their gather rays.
  long bake_luxels = 0, bake_gather_rays = 0;
  int bake_passes = 0;
  double bake_direct_ms = 0, bake_bounce_ms = 0;
  BakeSummary bake_summary;  // what the bake was (glue/bake/bake_dir.h): hash, faces, passes
  // The direct pass's shadow rays, the sky pass and the area lights (rays, ms; glue/bake/sky.h,
  // area_lights.h).
  long bake_direct_rays = 0, bake_sky_rays = 0, bake_area_rays = 0;
  double bake_sky_ms = 0, bake_area_ms = 0;
  double bake_cubes_ms = 0;  // the baker's ray-traced probe cubes (probes[].source "rays")
  double bake_cpu_ms = 0;  // the bake's process CPU time, every thread's (the bench's Embree share)
  IrradianceVolume volume;  // the models' irradiance volume (docs/irradiance_volume.md); no samples: none
  std::vector<std::string> notes;
  PreparedSky sky;  // the skybox (glue/scene/skybox_pass.h); absent without a sky
  std::vector<PreparedProbeCube> probe_cubes;  // the probes the draws sample, each once
};

struct PrepareOptions {
  // The world probes' cubes are rendered by the caller on GL after preparing (render_probe_cubes_gl,
  // glue/scene/probe_render.h); false: by the C fallback, here, on `threads` workers (0: all cores).
  bool gl_probe_cubes = false;
  int threads = 0;
  // The samplers' mip chains (docs/rendering.md "Mipmaps"); false: every texture one level, for
  // the records-only paths whose records carry no derivatives (deferred frames, the reference).
  bool mipmaps = true;
};

// api: cube maps are NEAREST on GLES (Mesa forces seamless filtering there; docs/conformance.md),
// so that the C twin samples what GL samples. tone_map_scale: the scale the integer path's
// shaders apply (ignored by the float path, whose shaders write scale 1).
bool prepare_scene(const Scene &s, const SceneSelection &sel, int w, int h, Api api, float tone_map_scale,
                   PreparedScene *out, std::string *err, const PrepareOptions &opt = PrepareOptions());

// Sets the tone-map scale of every draw's shared slots (auto exposure changes it per frame).
void set_scene_tone_map_scale(PreparedScene *p, float scale);

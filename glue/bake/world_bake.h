// tiershade bake: the lightmap bake of a set of world faces: radiosity-normal-mapped luxels
// (c_ref/offline/rnm_bake.c) on one page laid out by c_ref/offline/lightmap_page.c, each face's
// cube-map probe (c_ref/offline/envmap_probes.c) and the probes' cube maps, every ray (shadows,
// probes) through one Embree scene (glue/bake/ray_scene.h); the page's run-time lightmap encodings.
#pragma once
#include <string>
#include <vector>

#include "bake/area_lights.h"
#include "bake/bake_quality.h"
#include "bake/bounce.h"
#include "bake/sky.h"
#include "bake/world_faces.h"
#include "families/world_lighting.h"
#include "offline/lightmap_page.h"
#include "offline/rnm_bake.h"

class RayScene;

struct WorldBakeInput {
  std::vector<WorldFace> faces;
  std::vector<rnm_light> lights;
  std::vector<ts_vec3d> probes;  // at least one
  double luxels_per_unit = kBakeDraft.luxels_per_unit;
  int page_w = 512, page_h = 256;
  int cube_size = 64;
  // Per probe: whether its cube is ray traced here (empty: every probe's). An untraced probe's
  // cube is left empty (w 0): the scene renders it in-engine (glue/scene/probe_render.h).
  std::vector<char> trace_cube;
  // A page read from a file (page_w x page_h RGBA, this input's layout), used instead of baking the
  // luxels; the probes still see it (their faces' exitant radiance comes from the page).
  const std::vector<float> *page_in = nullptr;
  // Visibility: shadow rays through this scene (every triangle of the scene, glue/bake/ray_scene.h)
  // from each sample point to each light it faces; null: every light reaches every point it faces.
  const RayScene *rays = nullptr;
  // Samples per luxel along each axis (vrad: 4 samples, 2 x 2, for direct lighting; fact sheet
  // section 1), a regular grid over the luxel's footprint on the face, clipped to the face.
  int supersample = kBakeDraft.supersample;
  BounceSettings bounce;  // interreflection (glue/bake/bounce.h); max_bounces 0: direct light only
  // Checkpoints and progress (glue/bake/bounce.h BakeHooks, glue/bake/bake_dir.h): resume from a
  // saved pass, a call after each finished pass (the direct one included), progress per face.
  // They change no value: a resumed bake gives the same page bytes as an uninterrupted one.
  const BakeHooks *hooks = nullptr;
  // The sky (glue/bake/sky.h): absent (the default), no sky pass.
  BakeSky sky;
  // Emitters sampled as area lights (glue/bake/area_lights.h): points per luxel and emitter;
  // 0: the emission reaches the luxels through the bounces' gather alone.
  int area_samples = kBakeDraft.area_samples;
  // The model primitives with an emissive material (glue/bake/area_lights.h): they light the faces
  // like emitting faces; in `rays` with the ids model_emitter_id(k).
  std::vector<ModelEmitter> model_emitters;
  // Per light (empty, or one per light): a sun's angular radius in radians (vrad's
  // _sunspreadangle): its shadow rays are jittered within that cone, `spread_samples` per luxel
  // (vrad: 30 per sample point) shared among its supersamples, each taking a square of strata
  // (2 x 2 supersamples: 3 x 3 rays each), so its shadows are soft. 0: one ray.
  std::vector<double> light_spread;
  int spread_samples = kBakeDraft.spread_samples;
};

// The pages a bake may fill (page_w x page_h each; c_ref/offline/lightmap_page.h stacks them):
// the faces go on the next page when one is full, each page its own texture at run time.
const int kMaxLightmapPages = 16;

// The baked lighting: the pages in float32 (flat, b0, b1, b2 per face, borders filled or dilated),
// the faces' places in it, each face's probe and the probes' cube maps (linear radiance).
struct WorldBake {
  std::vector<lm_face_place> place;
  std::vector<float> page;  // page_w x (pages x page_h) RGBA32F, alpha 1: the pages stacked
  int pages = 1;
  std::vector<int> face_probe;
  std::vector<TextureDesc> cubes;  // per probe: "u_envmap", LINEAR; w 0 when not traced (trace_cube) (a frame for GLES switches them to NEAREST)
  BounceReport bounce;  // what the interreflection passes did
  long luxels = 0;  // luxel grid points of every face (each with 4 values)
  double direct_ms = 0, bounce_ms = 0;  // the direct pass (samples, shadow rays) and the bounces
  double cubes_ms = 0;  // ray tracing the probes' cubes (trace_cube)
  long direct_rays = 0;  // shadow rays of the direct pass
  int resumed_after = -1;  // the saved pass the bake resumed after (hooks->resume), -1: none
  SkyReport sky;  // the sky pass (rays 0 without a sky)
  AreaLightReport area;  // the area-light pass
};
bool bake_world(const WorldBakeInput &s, WorldBake *out, std::string *err);

// Lightmap encodings of the page for the shader (LIGHTMAP_ENCODING 0..3, -1 = float32
// unquantised, kPageRgbeToHalf): what each run-time format stores, uploaded as RGBA32F holding
// exactly those values. RGBE is sampled NEAREST (it does not filter), the others LINEAR.
// kPageRgbeToHalf: the page stored as RGBE (vrad's ColorRGBExp32), decoded at load and held as
// fp16 ("stored in RGBE ... at run time stored in a 16-bit per channel format", fact sheet
// section 2), for LIGHTMAP_ENCODING 0 (the float path), LINEAR: what the scene encoding "rgbe" runs.
const int kPageRgbeToHalf = -2;
TextureDesc encode_page(const WorldBakeInput &s, const WorldBake &b, int encoding, int page = 0);  // one page
// The value a texel of that encoding decodes to (double), for error measurements.
void decode_texel(int encoding, const float texel[4], double rgb[3]);

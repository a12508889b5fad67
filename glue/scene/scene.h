// tiershade scene: a scene as tiershade renders it, loaded from glTF 2.0 (glue/scene/gltf_load.cpp;
// the format, the Source material keys and the tiershade extras are in docs/scenes.md).
// Everything is in world space after node transforms; the renderer (glue/scene/prepare.cpp, frame.cpp)
// derives the variants and CPU work from what this structure uses, nothing more.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bake/bake_quality.h"
#include "offline/light_folding.h"

// An image as stored: 8-bit files as code/255 (no transfer function applied: the user of the
// image decodes sRGB where the glTF says colour), .hdr/.exr as their linear float values.
struct SceneImage {
  std::string path;  // resolved file path, or "<gltf>#images[i]" for embedded data
  int w = 0, h = 0;
  std::vector<float> rgba;  // w*h*4, row 0 = the file's BOTTOM row (GL order), alpha 1 if absent
};

// A texture reference: an image and how it is sampled (glTF sampler; default linear + repeat).
struct SceneTextureRef {
  int image = -1;  // -1: none
  bool linear = true;  // the sampler's magFilter (also the image part of its minification)
  bool repeat = true;
  // the mipmap part of the sampler's minFilter: 0 none (9728 NEAREST, 9729 LINEAR, or no
  // minFilter), 1 *_MIPMAP_NEAREST (9984, 9985), 2 *_MIPMAP_LINEAR (9986, 9987)
  int mip = 0;
};

// Which Source shader a material stands for ("shader" in the material's extras).
enum class SceneShader {
  Model,  // VertexLitGeneric: model lighting (ambient cube, local lights, Phong ...)
  World  // LightmappedGeneric: lightmaps (RNM / ssbump / flat), world specular
};

// World envmap mask sources (world_lighting ENVMAPMASK values).
enum class SceneEnvMask { None = 0, Texture = 1, NormalAlpha = 2, InvBaseAlpha = 3 };

struct SceneMaterial {
  std::string name;
  std::string where;  // "materials[i]" (with name) for messages
  SceneShader shader = SceneShader::Model;
  float base_color[4] = {1, 1, 1, 1};  // pbrMetallicRoughness.baseColorFactor (linear)
  SceneTextureRef base_texture;  // baseColorTexture (sRGB-encoded colour, alpha linear)
  SceneTextureRef normal_texture;  // normalTexture (tangent space; world: $bumpmap, ssbump if `ssbump`)
  // emissiveFactor x KHR_materials_emissive_strength (linear radiance) and emissiveTexture (sRGB):
  // World materials emit light into the bake (docs/baking.md); the shaders do not draw it.
  float emission[3] = {0, 0, 0};
  SceneTextureRef emissive_texture;
  // --- Model ($-keys of VertexLitGeneric, docs/scenes.md) ---
  bool half_lambert = true;  // $halflambert (Phong materials force it, as Source's skin shader)
  bool phong = false;  // $phong
  float phong_exponent = 20.f;  // $phongexponent (used without an exponent texture)
  SceneTextureRef phong_exponent_texture;  // $phongexponenttexture (r exponent, g albedo-tint mask, a rim mask)
  float phong_exponent_factor = 149.f;  // $phongexponentfactor: k = 1 + factor * r
  float phong_boost = 1.f;  // $phongboost
  float phong_fresnel_ranges[3] = {0.15f, 0.5f, 1.f};  // $phongfresnelranges
  float phong_tint[3] = {1, 1, 1};  // $phongtint
  bool phong_albedo_tint = false;  // $phongalbedotint
  bool base_alpha_phong_mask = false;  // $basemapalphaphongmask (else the normal map's alpha)
  bool invert_phong_mask = false;  // $invertphongmask
  bool rim_light = false;  // $rimlight
  float rim_exponent = 4.f;  // $rimlightexponent
  float rim_boost = 1.f;  // $rimlightboost
  float rim_mask = 0.f;  // $rimmask (0..1: how much the exponent map's alpha masks rim)
  SceneTextureRef light_warp_texture;  // $lightwarptexture (1D ramp, read along u)
  bool envmap = false;  // $envmap (the nearest probe's cube map, or `probe`)
  float envmap_scale = 1.f;  // model: envmap scale; world: ENV_MAP_SCALE
  float envmap_tint[3] = {1, 1, 1};  // $envmaptint
  float envmap_fresnel = 0.f;  // $envmapfresnel (model)
  float self_illum_tint[3] = {1, 1, 1};  // $selfillumtint
  bool self_illum = false;  // $selfillum (mask = base alpha)
  // --- World ($-keys of LightmappedGeneric) ---
  bool ssbump = false;  // $ssbump: normal_texture holds self-shadowed bump weights
  SceneEnvMask envmap_mask = SceneEnvMask::None;  // $envmapmask / $normalmapalphaenvmapmask / $basealphaenvmapmask
  SceneTextureRef envmap_mask_texture;  // $envmapmask
  float envmap_contrast = 0.f;  // $envmapcontrast
  float envmap_saturation = 1.f;  // $envmapsaturation
  float fresnel_reflection = 1.f;  // $fresnelreflection (R0 = this; 1 = no Fresnel)
  int probe = -1;  // "probe": explicit probe index, -1 = the nearest
};

// A primitive's vertex arrays (triangles only).
struct SceneGeometry {
  std::vector<float> position;  // 3 per vertex
  std::vector<float> normal;  // 3 per vertex (the mesh's, or flat face normals if absent)
  std::vector<float> uv;  // 2 per vertex (TEXCOORD_0; zeros if absent)
  std::vector<float> tangent;  // 4 per vertex (xyz, w handedness) or empty if absent
  std::vector<float> uv1;  // 2 per vertex (TEXCOORD_1, the lightmap UVs) or empty if absent
  std::vector<uint32_t> indices;  // 3 per triangle
  // The bytes of the arrays (the prepared-geometry tests and the memory report).
  size_t bytes() const {
    return (position.size() + normal.size() + uv.size() + tangent.size() + uv1.size()) * sizeof(float) +
        indices.size() * sizeof(uint32_t);
  }
};

// One glTF primitive under one node. Most are flattened to world space (node transform applied in
// double, rounded to float: the arrays of SceneGeometry in world space). A mesh that several nodes
// instance, with a Model material and a rigid node transform (rotation and translation), is shared
// instead, as an engine instances a prop: its arrays here are empty, `shared` holds the mesh
// primitive's object-space arrays once for every node, and `model` is the node's object -> world
// matrix in float (the shaders' u_model; docs/rendering.md, "Scenes of real size").
struct ScenePrimitive : SceneGeometry {
  int material = -1;  // index into Scene::materials (glTF default material -> a plain Model material)
  int instance = -1;  // the node instance it came from (index into Scene::instances)
  std::string where;  // "meshes[i].primitives[j]" (node name) for messages
  std::shared_ptr<const SceneGeometry> shared;  // set: an instance of shared object-space geometry
  float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // column-major (shared only)
};

// A node instance: the primitives of one mesh under one node.
struct SceneInstance {
  std::string name;  // node name or "nodes[i]"
  double world[16];  // column-major object -> world
  double center[3];  // world-space centre of its bounding box (ambient-cube and probe choice)
  // Node extras.tiershade.reach [[x,y,z], [x,y,z]]: the world-space box its centre can move in (a
  // model that moves); the irradiance volume samples only where models can be (docs/scenes.md).
  bool has_reach = false;
  double reach_lo[3] = {0, 0, 0}, reach_hi[3] = {0, 0, 0};
};

struct SceneLight {
  std::string name;  // KHR_lights_punctual light name or "lights[i]"
  ts_light light;  // world space; colour = glTF colour x intensity
  double spread = 0;  // a directional light's angular radius (radians): soft shadows in the bake (docs/baking.md)
};

struct SceneCamera {
  std::string name;
  double eye[3], forward[3], up[3];  // world space, unit forward/up
  double yfov = 0.8;  // radians
  double znear = 0.05, zfar = 1000;  // zfar 0 = infinite (glTF)
  double aspect = 0;  // 0: the output's
  // glTF orthographic camera: half extents xmag x ymag (the view keeps square pixels and holds
  // both, glue/scene/camera_ortho.h); yfov and aspect are then unused.
  bool orthographic = false;
  double xmag = 0, ymag = 0;
};

// A cube-map probe ("probes" in the scene's extras): an equirectangular HDR image, or
// rendered from the world geometry when `image` is -1 (world scenes).
struct SceneProbe {
  std::string name;
  double position[3];
  int image = -1;  // index into images (.hdr/.exr equirect), -1 = from the world
  float scale = 1.f;  // radiance multiplier
  int size = 64;  // cube face edge
  // World probes (no image): "source": "render" (default: the frame's renderer draws the baked world
  // into the cube, glue/scene/probe_render.h) or "rays" (traced: true, the baker's rays per texel).
  bool traced = false;
};

// An ambient-cube sample of the irradiance volume ("ambient" in the scene's extras):
// a model instance takes the nearest sample (Source: the leaf's ambient cube).
struct SceneAmbientSample {
  double position[3];
  float cube[6][3];  // +X -X +Y -Y +Z -Z linear radiance
  int from_probe = -1;  // >= 0: the cube is the probe's irradiance (filled by the renderer)
};

struct SceneLut {
  std::string path;  // .cube / .raw / OCIO file, resolved relative to the scene
  float weight = 1.f;
};

// HDR settings ("hdr" in the scene's extras).
struct SceneHdr {
  std::string path = "integer";  // "integer" | "float" (default of --hdr)
  float tone_map_scale = 1.f;  // fixed scale (auto exposure off)
  bool auto_exposure = false;
  float exposure_min = 0.5f, exposure_max = 2.f;  // scale clamp
  float bloom_amount = 0.f;  // float path only
  std::vector<SceneLut> luts;  // colour correction after tone mapping (0..4)
  int msaa = 0;  // samples per pixel of the integer path (0/1 none, 2, 4, 8; glue/scene/msaa.h)
};

// Lightmap settings ("lightmaps" in the scene's extras), used by World materials.
struct SceneLightmaps {
  // The bake's quality (glue/bake/bake_quality.h, docs/baking.md "Quality"): the preset "quality"
  // names (the scene's key; absent: draft, what render bakes at load) with the scene's own keys
  // (luxels_per_unit, supersample, area_samples, spread_samples, bounces, gather_rays, threshold,
  // and sky.samples) applied; `tiershade bake` recomputes it from its options.
  BakeQuality quality;
  std::string quality_preset;  // the scene's "quality" key ("": none)
  BakeQualityKeys keys;  // the scene's own keys
  int threads = 0;  // the bake's threads (0: all cores; not a scene key: `tiershade bake --threads`)
  std::string encoding = "rgbe";  // "float" | "412" | "ldr" | "rgbe" (world_lighting LIGHTMAP_ENCODING),
      // or "float32": LIGHTMAP_ENCODING 0 reading the unquantised page (a reference, not a run-time format)
  int page_w = 512, page_h = 256;
  int seed = 0;  // the gather rays' random streams (another seed: independent noise)
  // "image": a baked page read from a file (EXR or Radiance HDR, relative to the scene file) in
  // tiershade's page layout (written by `tiershade bake`), instead of baking the luxels at load.
  // Empty path: baked from the scene's lights. Texels: page_w x page_h RGBA float, row 0 at the
  // bottom (GL texture rows), alpha 1; finite and >= 0 (checked at load).
  std::string image;
  std::vector<float> image_rgba;
  // "bake": a bake directory (`tiershade bake SCENE -o DIR`, relative to the scene file) to render
  // from; its manifest's hash must match the scene (a stale bake is refused; docs/baking.md).
  std::string bake;
  // Set by `tiershade bake -o DIR` (not a scene key): the bake checkpoints into DIR.partial and
  // resumes from it; progress: a progress line on stderr.
  std::string bake_checkpoint;
  bool bake_progress = false;
};

// Range fog ("fog" in the scene's extras) on World draws, as Source's pixel fog: f = saturate(min(max_density,
// (depth - start) / (end - start))), blended with f^2 (fact sheet section 7); ps20 has no pixel fog.
struct SceneFog {
  bool enabled = false;
  float color[3] = {0, 0, 0};  // linear
  double start = 0, end = 1;  // view depth, start < end
  float max_density = 1.f;
};

// The sky ("sky" in the scene's extras): a lat-long HDR radiance image lighting the bake through the
// scene's openings (docs/baking.md, "The sky"); its optional sun is one more directional light.
struct SceneSky {
  int image = -1;  // index into images (.hdr/.exr lat-long, the probes' convention); -1: no sky
  float scale = 1.f;  // radiance multiplier
  // (its bake rays per luxel and value, "samples": lightmaps.keys.sky_samples, a quality key)
};

// The irradiance volume ("volume" in the scene's extras; docs/irradiance_volume.md): baked for
// scenes with world faces and models and no hand-typed "ambient" samples (those stay an override).
struct SceneVolume {
  double spacing[3] = {1.2192, 2.4384, 1.2192};  // metres along x, y (up), z: Source's 4 x 8 x 4 ft
  std::string fit = "lsq";  // "lsq" | "mean" (glue/bake/ambient_fit.h)
  std::string lookup = "trilinear";  // "trilinear" | "inverse_square" (Source's 1/(d^2 + 1))
  bool has_bounds = false;  // "bounds": [[x,y,z], [x,y,z]], where models can be; else the world faces' bounds
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool enabled = true;  // "enabled": false turns the volume off
};

struct Scene {
  std::string path;  // the .gltf/.glb file
  std::vector<SceneImage> images;
  std::vector<SceneMaterial> materials;
  std::vector<SceneInstance> instances;
  std::vector<ScenePrimitive> primitives;
  std::vector<SceneLight> lights;
  std::vector<SceneCamera> cameras;  // cameras[camera] renders
  int camera = 0;
  std::vector<SceneProbe> probes;
  std::vector<SceneAmbientSample> ambient;
  SceneHdr hdr;
  SceneLightmaps lightmaps;
  SceneFog fog;
  SceneSky sky;
  SceneVolume volume;
};

// Loads a glTF 2.0 scene (.gltf with external or data-URI buffers and images, or .glb).
// On failure returns false with *err = "<file>: <place>: <reason>" (e.g.
// "scenes/x.gltf: materials[2].extras.source: unknown key \"$phongexp\""), and *out untouched.
bool load_scene(const std::string &path, Scene *out, std::string *err);

// The world-space positions of a primitive (3 per vertex): its own arrays, or a shared one's
// object-space positions through its node's matrix in double, rounded to float (what the loader
// flattens to; the bake's occluders and the world-space bounds read these).
std::vector<float> scene_world_positions(const Scene &s, const ScenePrimitive &p);
// A copy of p flattened to world space (shared: its arrays transformed as the loader flattens,
// `shared` cleared), for code that edits a primitive's vertices.
ScenePrimitive scene_flattened(const Scene &s, const ScenePrimitive &p);
// The geometry bytes a scene holds, every shared array counted once.
size_t scene_geometry_bytes(const Scene &s);

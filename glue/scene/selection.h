// tiershade scene: "simulate only what the scene calls for". From a loaded scene and a tier,
// derives per draw (one glTF primitive) the shader family and the combo values it needs, with
// the reason for each choice, and the deduplicated set of variants to build. A term the scene
// does not use is never compiled and never evaluated by the C fallback: no normal map -> no
// RNM/Phong normal fetch, no probe -> no cube map, constant envmap mask -> no mask fetch,
// lights beyond the tier's limit -> folded into the ambient cube (docs/scenes.md).
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shaderlib/variants.h"

// One draw: a primitive, its variant and why.
struct SceneDrawChoice {
  int primitive = -1;  // index into Scene::primitives
  std::string family;  // "model_lighting" | "world_lighting"
  const Variant *variant = nullptr;  // points into SceneSelection::variants
  std::vector<std::string> why;  // "ENVMAP=0: material has no $envmap", ...
  int lights_local = 0, lights_folded = 0;  // model draws: lights shaded per pixel / folded
  int probe = -1;  // 0 when the draw samples a probe's cube map (which one: prepare_scene picks the nearest or the material's), -1: none
  bool mask_constant = false;  // world: $envmapmask texture is constant -> folded into the tint
  float mask_value = 1.f;  //   (its value)
};

struct SceneSelection {
  std::vector<ShaderDecl> decls;  // owns the declarations
  std::vector<Variant> variants;  // the unique variants the scene needs (stable order)
  std::vector<std::vector<std::string>> variant_why;  // per variant: the draws using it and their reasons
  std::vector<SceneDrawChoice> draws;  // one per primitive, in Scene::primitives order
  int all_combos = 0;  // every variant of the families used, for this tier (the saving's baseline)
  std::vector<const Variant *> all_variants;  // that baseline set (points into decls-derived storage)
  std::vector<Variant> all_storage;
  // The HDR path the scene runs ("integer" | "float") and its output encoding.
  std::string hdr_path;
  // The skybox variant (points into variants) when the scene has a sky (extras.tiershade.sky),
  // drawn where no geometry covers a pixel (glue/scene/skybox_pass.h); nullptr: none.
  const Variant *sky = nullptr;
};

// Tier names as in the variants files: "ps20" | "ps2b" | "sm3". hdr_path: "" = the scene's.
// all_features: the baseline an engine without selection would run: every draw takes its
// family's variant with every feature compiled in (Phong, exponent map, rim, envmap, light
// warp, the tier's full light count; RNM, envmap and mask texture), features its material does
// not use switched off by uniforms (boost 0, scale 0) or fed placeholder textures.
bool select_scene_variants(const Scene &s, Tier tier, const std::string &hdr_path, SceneSelection *out,
                           std::string *err, bool all_features = false);

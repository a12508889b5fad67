// tiershade families: the model_lighting family's helpers shared by its conformance inputs
// (model_lighting.cpp), the scene renderer and the tests.
#pragma once
#include "families/family.h"
#include "twins/model_lighting.h"

// The ps20/ps2b fragment light array: n lights of the record (5 vec4 each from `lights`, the
// ML_SLOT_LIGHT0 layout) packed into 4 vec4 each at `out` (shaders/common_lights.glsl,
// ts_light_unpack, which undoes it exactly): p0 (color.rgb, atten.x), p1 (dir.xyz, flags =
// (directional ? 1 : -1) * (spot ? 2 : 1)), p2 (pos.xyz, atten.y), p3 (spot.x, atten.z, spot.z, spot.w).
void ml_pack_lights(const ts_vec4f *lights, int n, ts_vec4f *out);

// The C twin's view of a variant's combo values.
ml_variant ml_variant_of(const Variant &v);

// The C views of the family's textures (make_inputs' order: enum below), for the twin's calls.
enum ml_texture_index { ML_TEX_ALBEDO, ML_TEX_NORMAL, ML_TEX_EXPONENT, ML_TEX_WARP, ML_TEX_ENVMAP, ML_TEX_COUNT };
struct MlTextureViews {
  ts_tex2d t2[4];
  ts_texcube cube;
  ml_textures tex;
  explicit MlTextureViews(const FamilyInputs &in);
  MlTextureViews(const MlTextureViews &) = delete;
};

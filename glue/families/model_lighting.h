// tiershade families: the model_lighting family's helpers shared by its conformance inputs
// (model_lighting.cpp), the scene renderer and the tests.
#pragma once
#include "families/family.h"
#include "twins/model_lighting.h"

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

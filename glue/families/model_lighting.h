// tiershade families: the model_lighting family's helpers shared by its conformance inputs
// (family_model_lighting.cpp), the scene renderer and the tests.
#pragma once
#include "families/family.h"
#include "twins/model_lighting.h"

// The C twin's view of a variant's combo values.
ml_variant ml_variant_of(const Variant &v);

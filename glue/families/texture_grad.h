// tiershade families: what the texture_grad family (texture_grad.cpp) shares with the bounds check
// (glue/conform/bounds.cpp): its interval twin on one pixel, with the pixel's record and the
// family's textures, as its eval_f gathers them.
#pragma once
#include "families/family.h"
#include "math/ts_interval.h"

ts_vec4iv texture_grad_bounds(const Variant &v, const FamilyInputs &in, int x, int y);

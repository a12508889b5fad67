// tiershade families: the world_lighting family's helpers shared by its conformance
// inputs (world_lighting.cpp), its demo and its benchmark.
#pragma once
#include <vector>

#include "families/family.h"
#include "twins/world_lighting.h"

extern const ShaderFamily kWorldLightingFamily;

wl_variant wl_variant_of(const Variant &v);
// The conformance textures: u_base, u_normalmap, u_lightmap, u_envmap_mask, u_envmap.
void wl_test_textures(Rng &r, std::vector<TextureDesc> *out);
// Source's defaults in every slot (flat +Z frame, unit tints and scales, no fog).
void wl_defaults(ts_vec4f rec[WL_SLOTS]);
void wl_bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared);

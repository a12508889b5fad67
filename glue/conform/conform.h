// tiershade conform: per-pixel conformance of a shader variant, GL (llvmpipe) against
// its bit-exact C twin. Tolerance: 0 ULP on every channel of every pixel
// (docs/conformance.md); any other tolerance must be written here with its reason.
#pragma once
#include <string>
#include <vector>

#include "families/family.h"
#include "gl/float_target.h"

// Maximum ULP distance accepted between GL and C. Zero: the C twin mirrors
// llvmpipe's builtins (c_ref/math/ts_math.c), so any difference is a bug.
constexpr unsigned kConformMaxUlp = 0;

struct ConformResult {
  std::string shader, variant, tier, backend, api, set;
  long pixels = 0, mismatches = 0;  // channel-level mismatches counted per pixel
  long nonfinite = 0, out_of_range = 0;  // in GL or C output
  unsigned max_ulp = 0;
  double max_abs = 0;
  double seconds = 0;
  bool cube_maps_nearest = false;  // LINEAR cube maps sampled with NEAREST (GLES: adapt_textures_for_api)
  std::string error;  // compile/link/draw failure
  std::string worst;  // human report of the worst pixel (inputs, GL, C, ULP)
  bool passed() const { return error.empty() && mismatches == 0 && nonfinite == 0 && out_of_range == 0; }
};

struct ConformRun {
  GlRenderer *renderer = nullptr;
  Backend backend = Backend::OSMesa;
  Api api = Api::GL33;
  std::string float_precision = "highp";  // "mediump": --bounds against the mediump rules (GLES)
};

Target target_for_api(Api a);

// GLES 3 cube maps are always seamless (the API has no switch; Mesa turns it on for
// every ES 3 context, and our "GLES 2" contexts are ES 3.2 underneath), and llvmpipe's
// seamless LINEAR filtering is not reproducible per pixel (llvmpipe_bitexact.md: a
// packet-wide corner branch). So on GLES the harness samples cube maps with NEAREST,
// which is exact; LINEAR cube filtering is checked on desktop GL, where seamless is off.
// Returns true when it changed something.
bool adapt_textures_for_api(Api api, FamilyInputs *in);

// Builds the variant's production program (its vertex shader, varyings and uniforms).
GLuint build_production_program(GlRenderer &r, Api api, const Variant &v, std::string *err);
// Builds the variant's conformance program for the renderer's API (nullptr err on success).
GLuint build_conform_program(GlRenderer &r, Api api, const Variant &v, std::string *err,
                             const std::string &float_precision = "highp");

// Draws the grid `in` through the conformance program `prog` (its record texture, textures and
// uniforms, as every conformance run sets them), reads it back into *img and deletes prog.
bool draw_conform_grid(GlRenderer &r, GLuint prog, const FamilyInputs &in, ImageF *img, std::string *err);

// Renders `in` through variant `v` and compares every pixel with the C twin.
ConformResult conform_variant(const ConformRun &run, const ShaderFamily &fam, const Variant &v, const FamilyInputs &in,
                              InputSet set);

std::string conform_result_json(const ConformResult &r);
std::string describe_pixel(const ShaderFamily &fam, const FamilyInputs &in, int x, int y);

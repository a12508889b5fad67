// tiershade glue: a shader family = one entry shader, its C twin, its input record
// layout and its test-input generators. Conformance, probe, demo and bench work
// on families through this interface.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gl_render.h"
#include "ts_math.h"
#include "variants.h"

enum class InputSet { Random, Hard };
const char *input_set_name(InputSet s);

// Per-pixel input records: pixel (x, y) slot k lives at texel (x, y + k*h) of a
// w x (h*slots) RGBA32F texture (shaders/common_inputs.glsl).
struct FamilyInputs {
  int w = 0, h = 0, slots = 0;
  std::vector<float> records;
  std::vector<TextureDesc> textures;  // extra textures the shader samples (e.g. u_albedo)
  std::vector<std::string> case_names;  // hard set: a label per pixel (empty for random)
  ts_vec4f slot(int x, int y, int k) const;
  void set_slot(int x, int y, int k, ts_vec4f v);
  void resize(int w_, int h_, int slots_);
  TextureDesc record_texture() const;
};

struct ShaderFamily {
  const char *name;
  int slots;
  std::vector<std::string> slot_names;
  void (*make_inputs)(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out);
  ts_vec4f (*eval_f)(const Variant &v, const FamilyInputs &in, int x, int y);
  ts_vec4d (*eval_d)(const Variant &v, const FamilyInputs &in, int x, int y);
  // Allowed output range of the variant (every channel), for the hard-case checks.
  void (*output_range)(const Variant &v, float *lo, float *hi);
};

const ShaderFamily *find_family(const std::string &name);
std::vector<const ShaderFamily *> all_families();

// #defines for a variant: each combo value, the tier (TS_TIER_PS20/PS2B/SM3) and, for
// conformance/record-driven runs, TS_CONFORM.
std::vector<Define> variant_defines(const Variant &v, bool conform);

// Small deterministic PRNG (xorshift32) for reproducible test inputs.
struct Rng {
  uint32_t s;
  explicit Rng(uint32_t seed) : s(seed ? seed : 0x9e3779b9u) {}
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return s;
  }
  float uniform(float lo, float hi) { return lo + (hi - lo) * static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
  ts_vec3f unit_vector();
};

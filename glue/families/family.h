// tiershade families: a shader family = one entry shader, its C twin, its input record
// layout and its test-input generators. Conformance, probe, demo and bench work
// on families through this interface.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gl/float_target.h"
#include "math/ts_math.h"
#include "math/ts_sampler.h"
#include "shaderlib/variants.h"

enum class InputSet { Random, Hard };
// Where a shader's inputs come from (shaders/common_inputs.glsl).
enum class InputMode { Production, Conform, Deferred };
const char *input_set_name(InputSet s);

// Per-pixel input records: pixel (x, y) slot k lives at texel (x, y + k*h) of a
// w x (h*slots) RGBA32F texture (shaders/common_inputs.glsl).
struct FamilyInputs {
  int w = 0, h = 0, slots = 0;
  std::vector<float> records;
  std::vector<TextureDesc> textures;  // extra textures the shader samples (e.g. u_albedo)
  std::vector<std::string> case_names;  // hard set: a label per pixel (empty for random)
  // Deferred frames: only the first `slots` slots are per pixel (the G-buffer); the
  // others are shared by every pixel and passed to GL as the production uniforms.
  std::vector<ts_vec4f> shared;  // empty, or the family's full record with the shared slots set
  ts_vec4f slot(int x, int y, int k) const;
  void gather(int x, int y, int n, ts_vec4f *rec) const;  // rec[k] = slot(x, y, k), k < n
  void set_slot(int x, int y, int k, ts_vec4f v);
  void resize(int w_, int h_, int slots_);
  TextureDesc record_texture() const;
};

// Points a batch twin's input (ml_batch_input, wl_batch_input: `slot[]` and `stride[]`) at row y
// of the record texture from pixel x0: slot k < in.slots is a run of texels (stride 1); the slots
// past in.slots are the frame's shared ones (stride 0).
template <class BatchInput>
void point_batch_at_row(const FamilyInputs &in, int x0, int y, int nslots, BatchInput *b) {
  static_assert(sizeof(ts_vec4f) == 4 * sizeof(float), "ts_vec4f is 4 packed floats");
  for (int k = 0; k < nslots; ++k) {
    if (k < in.slots) {
      b->slot[k] = reinterpret_cast<const ts_vec4f *>(&in.records[(static_cast<size_t>(y + k * in.h) * in.w + x0) * 4]);
      b->stride[k] = 1;
    } else {
      b->slot[k] = &in.shared.at(k);
      b->stride[k] = 0;
    }
  }
}

struct ShaderFamily {
  const char *name;
  int slots;
  std::vector<std::string> slot_names;
  // The hard set applies tests/conform/<name>.cases (families/hard_cases.h: fill_record_grid).
  void (*make_inputs)(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out);
  ts_vec4f (*eval_f)(const Variant &v, const FamilyInputs &in, int x, int y);
  ts_vec4d (*eval_d)(const Variant &v, const FamilyInputs &in, int x, int y);
  // Allowed output range of the variant (every channel), for the hard-case checks.
  void (*output_range)(const Variant &v, float *lo, float *hi);
  int pixel_slots;  // slots that stay per pixel in deferred frames
  // Sets the production uniforms from the shared slots (deferred frames).
  void (*bind_uniforms)(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared);
  // Optional fast path: out[i] = eval_f(v, in, x0 + i, y) for i < count, bit for bit, computed
  // several pixels at a time (SIMD). cpu_render_frame uses it when set; nullptr = per pixel.
  void (*eval_row_f)(const Variant &v, const FamilyInputs &in, int x0, int y, int count, ts_vec4f *out) = nullptr;
};

const ShaderFamily *find_family(const std::string &name);
std::vector<const ShaderFamily *> all_families();  // sorted by name

// Each family registers itself from its own file (glue/families/<name>.cpp, built with
// families/record_family.h):
//   static const FamilyRegistrar kRegister(&kMyFamily);
struct FamilyRegistrar {
  explicit FamilyRegistrar(const ShaderFamily *f);
};

// Extra sections of `tiershade demo` and `tiershade bench`, registered the same way by the
// files that own them (glue/demo/<name>.cpp, glue/bench/<name>.cpp), run in name order
// after the model-lighting section.
struct DemoOptions {
  std::string dir;  // output directory (exists)
  int w = 640, h = 320;
  std::vector<BackendApi> configs;  // GL backends to render on (the C fallback always runs)
};
struct DemoSection {
  const char *name;
  // Writes its files into opt.dir and prints its summary; returns false (with *err) on failure,
  // including a GL frame that differs from the C frame.
  bool (*run)(const DemoOptions &opt, std::string *err);
};
struct BenchOptions {
  int size = 1024, runs = 7;
  std::string plot_dir;  // where a section may write its SVG plots ("": none)
};
struct BenchSection {
  const char *name;
  // Measures and returns its markdown section ("## ..." and its tables) for docs/accuracy_cost.md.
  bool (*run)(const BenchOptions &opt, std::string *markdown, std::string *err);
};
struct DemoRegistrar {
  explicit DemoRegistrar(const DemoSection *s);
};
struct BenchRegistrar {
  explicit BenchRegistrar(const BenchSection *s);
};
std::vector<const DemoSection *> demo_sections();
std::vector<const BenchSection *> bench_sections();

// #defines for a variant: each combo value, the tier (TS_TIER_PS20/PS2B/SM3) and
// the input mode (TS_CONFORM, TS_DEFERRED, or nothing for production).
std::vector<Define> variant_defines(const Variant &v, InputMode mode);

// An RGBA32F 2D texture of w x h zeros with the given sampler name and filtering.
TextureDesc blank_texture(const std::string &sampler, int w, int h, bool linear, bool repeat);

// The C sampler's view of a texture the shader samples (same filtering and wrapping).
ts_tex2d tex2d_of(const TextureDesc &t);
ts_texcube texcube_of(const TextureDesc &t);

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

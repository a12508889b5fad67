// tiershade families: the bloom_blur family (one direction of the separable bloom
// Gaussian): input records (random and hard cases), the half-quantised source
// texture, and the bridge to its C twin (c_ref/twins/bloom_blur.c).
#include "twins/bloom_blur.h"
#include "families/family.h"
#include "families/hard_cases.h"
#include "families/slot_table.h"
#include "families/hdr_inputs.h"

namespace {

// The quarter-size bloom texture of the grids (NPOT; the target has its size).
const int kSourceW = 27, kSourceH = 19;

bb_variant to_bb(const Variant &v) {
  bb_variant m;
  m.direction = v.value("DIRECTION");
  return m;
}

void gather(const FamilyInputs &in, int x, int y, ts_vec4f rec[BB_SLOTS]) {
  for (int k = 0; k < BB_SLOTS; ++k) rec[k] = in.slot(x, y, k);
}

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[BB_SLOTS];
  gather(in, x, y, rec);
  const bb_variant m = to_bb(v);
  const ts_tex2d t = tex2d_of(in.textures.at(0));
  return bloom_blur_f(&m, rec, &t);
}

ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[BB_SLOTS];
  gather(in, x, y, rec);
  const bb_variant m = to_bb(v);
  const ts_tex2d t = tex2d_of(in.textures.at(0));
  return bloom_blur_d(&m, rec, &t);
}

void output_range(const Variant &, float *lo, float *hi) {
  *lo = 0.f;
  *hi = 65504.f;
}

void random_pixel(Rng &r, ts_vec4f rec[BB_SLOTS]) {
  rec[BB_SLOT_POS] = random_fragment_position(r, kSourceW, kSourceH);
  rec[BB_SLOT_SIZE] = size_slot(kSourceW, kSourceH);
  rec[BB_SLOT_PARAMS] = ts_v4f(r.next() % 2 ? 1.f : r.uniform(0.f, 2.f), 0.f, 0.f, 0.f);
}

void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  Rng r(seed);
  // The hard cases: tests/conform/bloom_blur.cases.
  fill_record_grid(
      "bloom_blur", set, w, h, BB_SLOTS, r, [&](ts_vec4f *rec) { random_pixel(r, rec); }, out);
  out->textures = {hdr_test_texture(r, "u_source", kSourceW, kSourceH, true)};
}

// The record layout: shaders/bloom_blur_slots.glsl, the one table (slot_table.h).
#define TS_SLOT TS_SLOT_ROW
constexpr SlotRow kSlotRows[] = {
#include "../../shaders/bloom_blur_slots.glsl"
};
#undef TS_SLOT
static_assert(slot_rows_valid(kSlotRows, BB_SLOTS, BB_PIXEL_SLOTS), "shaders/bloom_blur_slots.glsl: bad rows");

std::vector<std::string> slot_names() { return slot_names_of(kSlotRows); }

void bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, kSlotRows, BB_PIXEL_SLOTS);
}

}  // namespace

const ShaderFamily kBloomBlurFamily = {
    "bloom_blur", BB_SLOTS, slot_names(), make_inputs, eval_f, eval_d, output_range, BB_PIXEL_SLOTS, bind_uniforms,
};
const FamilyRegistrar kRegisterBloomBlur(&kBloomBlurFamily);

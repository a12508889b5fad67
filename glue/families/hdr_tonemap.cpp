// tiershade families: the hdr_tonemap family (the float path's tone map and bloom
// combine): input records (random and hard cases), the half-quantised bloom
// texture, and the bridge to its C twin (c_ref/twins/hdr_tonemap.c).
#include "families/family.h"
#include "families/hard_cases.h"
#include "families/slot_table.h"
#include "families/hdr_inputs.h"
#include "math/hdr_formats.h"
#include "twins/hdr_tonemap.h"

namespace {

// The quarter-size bloom texture of the grids; the frame is four times its size.
const int kBloomW = 13, kBloomH = 11;

ht_variant to_ht(const Variant &v) {
  ht_variant m;
  m.output_mode = v.value("OUTPUT_MODE");
  return m;
}

void gather(const FamilyInputs &in, int x, int y, ts_vec4f rec[HT_SLOTS]) {
  for (int k = 0; k < HT_SLOTS; ++k) rec[k] = in.slot(x, y, k);
}

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[HT_SLOTS];
  gather(in, x, y, rec);
  const ht_variant m = to_ht(v);
  const ts_tex2d t = tex2d_of(in.textures.at(0));
  return hdr_tonemap_f(&m, rec, &t);
}

ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[HT_SLOTS];
  gather(in, x, y, rec);
  const ht_variant m = to_ht(v);
  const ts_tex2d t = tex2d_of(in.textures.at(0));
  return hdr_tonemap_d(&m, rec, &t);
}

void output_range(const Variant &v, float *lo, float *hi) {
  *lo = 0.f;
  *hi = v.value("OUTPUT_MODE") == 0 ? 65504.f : 1.f;
}

float half_uniform(Rng &r, float lo, float hi) { return ts_quantize_half(r.uniform(lo, hi)); }

void random_pixel(Rng &r, ts_vec4f rec[HT_SLOTS]) {
  rec[HT_SLOT_POS] = random_fragment_position(r, kBloomW * 4, kBloomH * 4);
  const float top = r.next() % 2 ? 1.f : 64.f;
  rec[HT_SLOT_FRAME] = ts_v4f(half_uniform(r, 0, top), half_uniform(r, 0, top), half_uniform(r, 0, top), 1.f);
  rec[HT_SLOT_SIZE] = size_slot(kBloomW * 4, kBloomH * 4);
  rec[HT_SLOT_PARAMS] = ts_v4f(r.uniform(0.05f, 4.f), r.uniform(0.f, 2.f), r.uniform(0.5f, 3.f), 0.f);
}

void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  Rng r(seed);
  // The hard cases: tests/conform/hdr_tonemap.cases.
  fill_record_grid(
      "hdr_tonemap", set, w, h, HT_SLOTS, r, [&](ts_vec4f *rec) { random_pixel(r, rec); }, out);
  out->textures = {hdr_test_texture(r, "u_bloom", kBloomW, kBloomH, true)};
}

// The record layout: shaders/hdr_tonemap_slots.glsl, the one table (slot_table.h).
#define TS_SLOT TS_SLOT_ROW
constexpr SlotRow kSlotRows[] = {
#include "../../shaders/hdr_tonemap_slots.glsl"
};
#undef TS_SLOT
static_assert(slot_rows_valid(kSlotRows, HT_SLOTS, HT_PIXEL_SLOTS), "shaders/hdr_tonemap_slots.glsl: bad rows");

std::vector<std::string> slot_names() { return slot_names_of(kSlotRows); }

void bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, kSlotRows, HT_PIXEL_SLOTS);
}

}  // namespace

const ShaderFamily kHdrTonemapFamily = {
    "hdr_tonemap", HT_SLOTS, slot_names(), make_inputs, eval_f, eval_d, output_range, HT_PIXEL_SLOTS, bind_uniforms,
};
const FamilyRegistrar kRegisterHdrTonemap(&kHdrTonemapFamily);

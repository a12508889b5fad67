// tiershade families: the luminance_compare family (the auto-exposure bucket test):
// input records (random and hard cases) and the bridge to its C twin
// (c_ref/twins/luminance_compare.c).
#include <cmath>

#include "families/family.h"
#include "families/hard_cases.h"
#include "families/slot_table.h"
#include "families/hdr_inputs.h"
#include "twins/luminance_compare.h"

namespace {

lc_variant to_lc(const Variant &v) {
  lc_variant m;
  m.input_encoding = v.value("INPUT_ENCODING");
  return m;
}

void gather(const FamilyInputs &in, int x, int y, ts_vec4f rec[LC_SLOTS]) {
  for (int k = 0; k < LC_SLOTS; ++k) rec[k] = in.slot(x, y, k);
}

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[LC_SLOTS];
  gather(in, x, y, rec);
  const lc_variant m = to_lc(v);
  return luminance_compare_f(&m, rec);
}

ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[LC_SLOTS];
  gather(in, x, y, rec);
  const lc_variant m = to_lc(v);
  return luminance_compare_d(&m, rec);
}

void output_range(const Variant &, float *lo, float *hi) {
  *lo = 0.f;
  *hi = 1.f;
}

// A bucket of the 17-bucket layout (fact sheet section 8), or the all-pixel bucket.
ts_vec4f random_range(Rng &r, float tscale) {
  const int i = static_cast<int>(r.next() % 17);
  if (i == 16) return ts_v4f(0.f, 100000.f, tscale, 0.f);
  const float lo = std::pow(i / 16.f, 1.5f);
  const float hi = i == 15 ? 10000.f : std::pow((i + 1) / 16.f, 1.5f);
  return ts_v4f(lo, hi, tscale, 0.f);
}

void random_pixel(Rng &r, ts_vec4f rec[LC_SLOTS]) {
  // Colours of an 8-bit frame ([0, 1]) and of an HDR frame (up to 64), tone-map scales 0.05 .. 4.
  const float top = r.next() % 2 ? 1.f : 64.f;
  rec[LC_SLOT_COLOR] = ts_v4f(r.uniform(0, top), r.uniform(0, top), r.uniform(0, top), 1.f);
  rec[LC_SLOT_RANGE] = random_range(r, r.uniform(0.05f, 4.f));
}

// lum(color, scale): the luminance the twin computes for the pixel's INPUT_ENCODING (the
// [repeat INPUT_ENCODING] of tests/conform/luminance_compare.cases), for exact bucket edges.
const CaseFunctionRegistrar kCaseFunctions(
    "luminance_compare", {{"lum", {4, 1}, 1, "INPUT_ENCODING", [](const float *a, const CaseEval &env, float *out) {
                             const lc_variant v = {env.repeat_value};
                             out[0] = luminance_compare_lum_f(&v, ts_v4f(a[0], a[1], a[2], a[3]), a[4]);
                           }}});

void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  out->textures.clear();
  Rng r(seed);
  // The hard cases: tests/conform/luminance_compare.cases, repeated once per INPUT_ENCODING.
  fill_record_grid(
      "luminance_compare", set, w, h, LC_SLOTS, r, [&](ts_vec4f *rec) { random_pixel(r, rec); }, out);
}

// The record layout: shaders/luminance_compare_slots.glsl, the one table (slot_table.h).
#define TS_SLOT TS_SLOT_ROW
constexpr SlotRow kSlotRows[] = {
#include "../../shaders/luminance_compare_slots.glsl"
};
#undef TS_SLOT
static_assert(slot_rows_valid(kSlotRows, LC_SLOTS, LC_PIXEL_SLOTS), "shaders/luminance_compare_slots.glsl: bad rows");

std::vector<std::string> slot_names() { return slot_names_of(kSlotRows); }

void bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, kSlotRows, LC_PIXEL_SLOTS);
}

}  // namespace

const ShaderFamily kLuminanceCompareFamily = {
    "luminance_compare", LC_SLOTS,       slot_names(),  make_inputs, eval_f, eval_d,
    output_range,        LC_PIXEL_SLOTS, bind_uniforms,
};
const FamilyRegistrar kRegisterLuminanceCompare(&kLuminanceCompareFamily);

// tiershade families: the luminance_compare family (the auto-exposure bucket test):
// input records (random and hard cases) and the bridge to its C twin
// (c_ref/twins/luminance_compare.c).
#include <cmath>
#include <iterator>

#include "families/hdr_inputs.h"
#include "families/record_family.h"
#include "twins/luminance_compare.h"

namespace {

lc_variant to_lc(const Variant &v) { return {v.value("INPUT_ENCODING")}; }

// A bucket of the 17-bucket layout (fact sheet section 8), or the all-pixel bucket.
ts_vec4f random_range(Rng &r, float tscale) {
  const int i = static_cast<int>(r.next() % 17);
  if (i == 16) return ts_v4f(0.f, 100000.f, tscale, 0.f);
  const float lo = std::pow(i / 16.f, 1.5f);
  const float hi = i == 15 ? 10000.f : std::pow((i + 1) / 16.f, 1.5f);
  return ts_v4f(lo, hi, tscale, 0.f);
}

void random_pixel(Rng &r, InputSet, ts_vec4f rec[LC_SLOTS]) {
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

// The record layout: shaders/luminance_compare_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/luminance_compare_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"luminance_compare",  LC_SLOTS,         LC_PIXEL_SLOTS, kSlotRows,
                                  std::size(kSlotRows), output_range_unit};

}  // namespace

// The hard cases: tests/conform/luminance_compare.cases, repeated once per INPUT_ENCODING. No textures.
const ShaderFamily kLuminanceCompareFamily =
    twin_family<kLayout, to_lc, no_textures, luminance_compare_f, luminance_compare_d, random_pixel, clear_textures>();
const FamilyRegistrar kRegisterLuminanceCompare(&kLuminanceCompareFamily);

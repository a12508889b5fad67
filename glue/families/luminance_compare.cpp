// tiershade glue: the luminance_compare family (the auto-exposure bucket test):
// input records (random and hard cases) and the bridge to its C twin
// (c_ref/twins/luminance_compare.c).
#include <cmath>

#include "families/family.h"
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

const char *const kHardCases[] = {
    "lum exactly at the bucket min", "lum exactly at the bucket max", "colour 65504, tone-map scale 4 (Inf lum)",
    "NaN colour",                    "Inf colour",                    "negative colour",
    "black, bucket [0, x]",          "NaN tone-map scale",            "zero tone-map scale",
    "negative tone-map scale",       "empty range (min > max)",       "sRGB decode edge 0.04045",
    "denormal colour",               "top bucket widened to 10000",   "the all-pixel bucket [0, 100000]",
    "NaN bucket bounds",
};
const int kNumHardCases = sizeof kHardCases / sizeof kHardCases[0];

void hard_pixel(Rng &r, int c, int encoding, ts_vec4f rec[LC_SLOTS]) {
  random_pixel(r, rec);
  ts_vec4f &col = rec[LC_SLOT_COLOR];
  ts_vec4f &rg = rec[LC_SLOT_RANGE];
  const lc_variant v = {encoding};
  switch (c) {
    case 0: rg.x = luminance_compare_lum_f(&v, col, rg.z); rg.y = rg.x * 2.f + 1.f; break;
    case 1: rg.y = luminance_compare_lum_f(&v, col, rg.z); rg.x = rg.y * 0.5f; break;
    case 2: col = ts_v4f(65504.f, 65504.f, 65504.f, 1.f); rg.z = 4.f; rg.y = 10000.f; break;
    case 3: col.y = kHdrNaN; rg = ts_v4f(0.f, 100000.f, 1.f, 0.f); break;
    case 4: col.x = kHdrInf; rg = ts_v4f(0.f, 100000.f, 1.f, 0.f); break;
    case 5: col = ts_v4f(-0.5f, -2.f, -1.f, 1.f); rg = ts_v4f(-10.f, 10.f, 1.f, 0.f); break;
    case 6: col = ts_v4f(0.f, 0.f, 0.f, 1.f); rg = ts_v4f(0.f, 0.015625f, 1.f, 0.f); break;
    case 7: rg.z = kHdrNaN; break;
    case 8: rg.z = 0.f; rg.x = 0.f; break;
    case 9: rg.z = -1.f; rg.x = -100.f; rg.y = 100.f; break;
    case 10: rg.x = 0.5f; rg.y = 0.25f; break;
    case 11: col = ts_v4f(0.04045f, 0.04045f, 0.04045f, 1.f); rg = ts_v4f(0.f, 1.f, 1.f, 0.f); break;
    case 12: col = ts_v4f(1e-39f, 2e-39f, 0.f, 1.f); rg = ts_v4f(0.f, 0.01f, 1.f, 0.f); break;
    case 13: rg.x = 1.f; rg.y = 10000.f; col = ts_v4f(r.uniform(0.9f, 3.f), r.uniform(0.9f, 3.f), 1.f, 1.f); break;
    case 14: rg = ts_v4f(0.f, 100000.f, rg.z, 0.f); break;
    case 15: rg.x = kHdrNaN; rg.y = kHdrNaN; break;
    default: break;
  }
}

// One hard set serves every INPUT_ENCODING variant. Exact bucket edges depend on the
// encoding (they are computed with the twin), so each edge case cycles through an edge
// of the linear, the sRGB and the luminance-image variant.
void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  out->resize(w, h, LC_SLOTS);
  out->case_names.clear();
  out->textures.clear();
  Rng r(seed);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      ts_vec4f rec[LC_SLOTS];
      if (set == InputSet::Random) {
        random_pixel(r, rec);
      } else {
        const int idx = y * w + x;
        const int c = idx % kNumHardCases;
        const int enc = (idx / kNumHardCases) % 3;
        hard_pixel(r, c, enc, rec);
        static const char *const kEdgeOf[3] = {" (edge of the linear variant)", " (edge of the sRGB variant)",
                                               " (edge of the luminance-image variant)"};
        out->case_names.push_back(std::string(kHardCases[c]) + kEdgeOf[enc]);
      }
      for (int k = 0; k < LC_SLOTS; ++k) out->set_slot(x, y, k, rec[k]);
    }
  }
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
    "luminance_compare", LC_SLOTS, slot_names(), make_inputs, eval_f, eval_d, output_range, LC_PIXEL_SLOTS,
    bind_uniforms,
};
const FamilyRegistrar kRegisterLuminanceCompare(&kLuminanceCompareFamily);

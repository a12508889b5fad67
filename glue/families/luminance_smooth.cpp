// tiershade families: the luminance_smooth family (the temporal prefilter of the
// auto-exposure luminance): input records (random and hard cases) and the bridge
// to its C twin (c_ref/twins/luminance_smooth.c).
#include "families/family.h"
#include "families/hard_cases.h"
#include "families/slot_table.h"
#include "families/hdr_inputs.h"
#include "math/hdr_formats.h"
#include "twins/luminance_smooth.h"

namespace {

ls_variant to_ls(const Variant &v) {
  ls_variant m;
  m.input_encoding = v.value("INPUT_ENCODING");
  return m;
}

void gather(const FamilyInputs &in, int x, int y, ts_vec4f rec[LS_SLOTS]) {
  for (int k = 0; k < LS_SLOTS; ++k) rec[k] = in.slot(x, y, k);
}

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[LS_SLOTS];
  gather(in, x, y, rec);
  const ls_variant m = to_ls(v);
  return luminance_smooth_f(&m, rec);
}

ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[LS_SLOTS];
  gather(in, x, y, rec);
  const ls_variant m = to_ls(v);
  return luminance_smooth_d(&m, rec);
}

void output_range(const Variant &, float *lo, float *hi) {
  *lo = 0.f;
  *hi = 65504.f;
}

void random_pixel(Rng &r, ts_vec4f rec[LS_SLOTS]) {
  const float top = r.next() % 2 ? 1.f : 64.f;
  rec[LS_SLOT_COLOR] = ts_v4f(r.uniform(0, top), r.uniform(0, top), r.uniform(0, top), 1.f);
  const float h = ts_quantize_half(r.uniform(0.f, 8.f));  // the history is an fp16 texture
  rec[LS_SLOT_HISTORY] = ts_v4f(h, h, h, 1.f);
  const uint32_t k = r.next() % 4;
  rec[LS_SLOT_PARAMS] = ts_v4f(k == 0 ? 1.f : k == 1 ? 0.0625f : r.uniform(0.f, 1.f), r.uniform(0.05f, 4.f), 0.f, 0.f);
}

void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  Rng r(seed);
  out->textures.clear();
  // The hard cases: tests/conform/luminance_smooth.cases.
  fill_record_grid(
      "luminance_smooth", set, w, h, LS_SLOTS, r, [&](ts_vec4f *rec) { random_pixel(r, rec); }, out);
}

// The record layout: shaders/luminance_smooth_slots.glsl, the one table (slot_table.h).
#define TS_SLOT TS_SLOT_ROW
constexpr SlotRow kSlotRows[] = {
#include "../../shaders/luminance_smooth_slots.glsl"
};
#undef TS_SLOT
static_assert(slot_rows_valid(kSlotRows, LS_SLOTS, LS_PIXEL_SLOTS), "shaders/luminance_smooth_slots.glsl: bad rows");

std::vector<std::string> slot_names() { return slot_names_of(kSlotRows); }

void bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, kSlotRows, LS_PIXEL_SLOTS);
}

}  // namespace

const ShaderFamily kLuminanceSmoothFamily = {
    "luminance_smooth", LS_SLOTS,       slot_names(),  make_inputs, eval_f, eval_d,
    output_range,       LS_PIXEL_SLOTS, bind_uniforms,
};
const FamilyRegistrar kRegisterLuminanceSmooth(&kLuminanceSmoothFamily);

// tiershade families: the luminance_smooth family (the temporal prefilter of the
// auto-exposure luminance): input records (random and hard cases) and the bridge
// to its C twin (c_ref/twins/luminance_smooth.c).
#include <iterator>

#include "families/record_family.h"
#include "math/hdr_formats.h"
#include "twins/luminance_smooth.h"

namespace {

// The record layout: shaders/luminance_smooth_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/luminance_smooth_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"luminance_smooth",   LS_SLOTS,         LS_PIXEL_SLOTS, kSlotRows,
                                  std::size(kSlotRows), output_range_half};

void random_pixel(Rng &r, InputSet, ts_vec4f rec[LS_SLOTS]) {
  const float top = r.next() % 2 ? 1.f : 64.f;
  rec[LS_SLOT_COLOR] = ts_v4f(r.uniform(0, top), r.uniform(0, top), r.uniform(0, top), 1.f);
  const float h = ts_quantize_half(r.uniform(0.f, 8.f));  // the history is an fp16 texture
  rec[LS_SLOT_HISTORY] = ts_v4f(h, h, h, 1.f);
  const uint32_t k = r.next() % 4;
  rec[LS_SLOT_PARAMS] = ts_v4f(k == 0 ? 1.f : k == 1 ? 0.0625f : r.uniform(0.f, 1.f), r.uniform(0.05f, 4.f), 0.f, 0.f);
}

ls_variant to_ls(const Variant &v) { return {v.value("INPUT_ENCODING")}; }

}  // namespace

// The hard cases: tests/conform/luminance_smooth.cases. No textures.
const ShaderFamily kLuminanceSmoothFamily =
    twin_family<kLayout, to_ls, no_textures, luminance_smooth_f, luminance_smooth_d, random_pixel, clear_textures>();
const FamilyRegistrar kRegisterLuminanceSmooth(&kLuminanceSmoothFamily);

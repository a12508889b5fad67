// tiershade families: the hdr_tonemap family (the float path's tone map and bloom
// combine): input records (random and hard cases), the half-quantised bloom
// texture, and the bridge to its C twin (c_ref/twins/hdr_tonemap.c).
#include <iterator>

#include "families/hdr_inputs.h"
#include "families/record_family.h"
#include "math/hdr_formats.h"
#include "twins/hdr_tonemap.h"

namespace {

// The record layout: shaders/hdr_tonemap_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/hdr_tonemap_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {
    "hdr_tonemap", HT_SLOTS, HT_PIXEL_SLOTS, kSlotRows, std::size(kSlotRows), output_range_by_output_mode};

ht_variant to_ht(const Variant &v) { return {v.value("OUTPUT_MODE")}; }

// The quarter-size bloom texture of the grids; the frame is four times its size.
constexpr char kBloom[] = "u_bloom";
constexpr int kBloomW = 13, kBloomH = 11;

float half_uniform(Rng &r, float lo, float hi) { return ts_quantize_half(r.uniform(lo, hi)); }

void random_pixel(Rng &r, InputSet, ts_vec4f rec[HT_SLOTS]) {
  rec[HT_SLOT_POS] = random_fragment_position(r, kBloomW * 4, kBloomH * 4);
  const float top = r.next() % 2 ? 1.f : 64.f;
  rec[HT_SLOT_FRAME] = ts_v4f(half_uniform(r, 0, top), half_uniform(r, 0, top), half_uniform(r, 0, top), 1.f);
  rec[HT_SLOT_SIZE] = size_slot(kBloomW * 4, kBloomH * 4);
  rec[HT_SLOT_PARAMS] = ts_v4f(r.uniform(0.05f, 4.f), r.uniform(0.f, 2.f), r.uniform(0.5f, 3.f), 0.f);
}

}  // namespace

const ShaderFamily kHdrTonemapFamily = twin_family<kLayout, to_ht, first_tex2d, hdr_tonemap_f, hdr_tonemap_d,
                                                   random_pixel, one_hdr_texture<kBloom, kBloomW, kBloomH>>();
const FamilyRegistrar kRegisterHdrTonemap(&kHdrTonemapFamily);

// tiershade families: the bloom_blur family (one direction of the separable bloom
// Gaussian): input records (random and hard cases), the half-quantised source
// texture, and the bridge to its C twin (c_ref/twins/bloom_blur.c).
#include <iterator>

#include "families/hdr_inputs.h"
#include "families/record_family.h"
#include "twins/bloom_blur.h"

namespace {

// The record layout: shaders/bloom_blur_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/bloom_blur_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"bloom_blur",         BB_SLOTS,         BB_PIXEL_SLOTS, kSlotRows,
                                  std::size(kSlotRows), output_range_half};

// The quarter-size bloom texture of the grids (NPOT; the target has its size).
constexpr char kSource[] = "u_source";
constexpr int kSourceW = 27, kSourceH = 19;

bb_variant to_bb(const Variant &v) { return {v.value("DIRECTION")}; }

void random_pixel(Rng &r, InputSet, ts_vec4f rec[BB_SLOTS]) {
  rec[BB_SLOT_POS] = random_fragment_position(r, kSourceW, kSourceH);
  rec[BB_SLOT_SIZE] = size_slot(kSourceW, kSourceH);
  rec[BB_SLOT_PARAMS] = ts_v4f(r.next() % 2 ? 1.f : r.uniform(0.f, 2.f), 0.f, 0.f, 0.f);
}

}  // namespace

const ShaderFamily kBloomBlurFamily = twin_family<kLayout, to_bb, first_tex2d, bloom_blur_f, bloom_blur_d, random_pixel,
                                                  one_hdr_texture<kSource, kSourceW, kSourceH>>();
const FamilyRegistrar kRegisterBloomBlur(&kBloomBlurFamily);

// tiershade families: the bloom_downsample family (the quarter-size bloom source):
// input records (random and hard cases), the half-quantised source texture, and
// the bridge to its C twin (c_ref/twins/bloom_downsample.c).
#include <iterator>

#include "families/hdr_inputs.h"
#include "families/record_family.h"
#include "twins/bloom_downsample.h"

namespace {

// The source frame of the conformance grids: NPOT, so that both addressing paths
// of the sampler mirror are exercised elsewhere; the target is a quarter of it.
constexpr char kSource[] = "u_source";
constexpr int kSourceW = 44, kSourceH = 36;

// The record layout: shaders/bloom_downsample_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/bloom_downsample_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"bloom_downsample",   BD_SLOTS,         BD_PIXEL_SLOTS, kSlotRows,
                                  std::size(kSlotRows), output_range_half};

void random_pixel(Rng &r, InputSet, ts_vec4f rec[BD_SLOTS]) {
  rec[BD_SLOT_POS] = random_fragment_position(r, kSourceW / 4, kSourceH / 4);
  rec[BD_SLOT_SIZE] = size_slot(kSourceW, kSourceH);
  // Source's defaults are tint (0.3, 0.59, 0.11) and exponent 2.2 (fact sheet section 8).
  rec[BD_SLOT_SHAPE] = ts_v4f(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), r.uniform(0.5f, 3.f));
}

bd_variant to_bd(const Variant &v) { return {v.value("SHAPE")}; }

}  // namespace

const ShaderFamily kBloomDownsampleFamily =
    twin_family<kLayout, to_bd, first_tex2d, bloom_downsample_f, bloom_downsample_d, random_pixel,
                one_hdr_texture<kSource, kSourceW, kSourceH>>();
const FamilyRegistrar kRegisterBloomDownsample(&kBloomDownsampleFamily);

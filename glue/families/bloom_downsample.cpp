// tiershade families: the bloom_downsample family (the quarter-size bloom source):
// input records (random and hard cases), the half-quantised source texture, and
// the bridge to its C twin (c_ref/twins/bloom_downsample.c).
#include "twins/bloom_downsample.h"
#include "families/family.h"
#include "families/hard_cases.h"
#include "families/slot_table.h"
#include "families/hdr_inputs.h"

namespace {

// The source frame of the conformance grids: NPOT, so that both addressing paths
// of the sampler mirror are exercised elsewhere; the target is a quarter of it.
const int kSourceW = 44, kSourceH = 36;

bd_variant to_bd(const Variant &v) {
  bd_variant m;
  m.shape = v.value("SHAPE");
  return m;
}

void gather(const FamilyInputs &in, int x, int y, ts_vec4f rec[BD_SLOTS]) {
  for (int k = 0; k < BD_SLOTS; ++k) rec[k] = in.slot(x, y, k);
}

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[BD_SLOTS];
  gather(in, x, y, rec);
  const bd_variant m = to_bd(v);
  const ts_tex2d t = tex2d_of(in.textures.at(0));
  return bloom_downsample_f(&m, rec, &t);
}

ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[BD_SLOTS];
  gather(in, x, y, rec);
  const bd_variant m = to_bd(v);
  const ts_tex2d t = tex2d_of(in.textures.at(0));
  return bloom_downsample_d(&m, rec, &t);
}

void output_range(const Variant &, float *lo, float *hi) {
  *lo = 0.f;
  *hi = 65504.f;
}

void random_pixel(Rng &r, ts_vec4f rec[BD_SLOTS]) {
  rec[BD_SLOT_POS] = random_fragment_position(r, kSourceW / 4, kSourceH / 4);
  rec[BD_SLOT_SIZE] = size_slot(kSourceW, kSourceH);
  // Source's defaults are tint (0.3, 0.59, 0.11) and exponent 2.2 (fact sheet section 8).
  rec[BD_SLOT_SHAPE] = ts_v4f(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), r.uniform(0.5f, 3.f));
}

void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  Rng r(seed);
  // The hard cases: tests/conform/bloom_downsample.cases.
  fill_record_grid(
      "bloom_downsample", set, w, h, BD_SLOTS, r, [&](ts_vec4f *rec) { random_pixel(r, rec); }, out);
  out->textures = {hdr_test_texture(r, "u_source", kSourceW, kSourceH, true)};
}

// The record layout: shaders/bloom_downsample_slots.glsl, the one table (slot_table.h).
#define TS_SLOT TS_SLOT_ROW
constexpr SlotRow kSlotRows[] = {
#include "../../shaders/bloom_downsample_slots.glsl"
};
#undef TS_SLOT
static_assert(slot_rows_valid(kSlotRows, BD_SLOTS, BD_PIXEL_SLOTS), "shaders/bloom_downsample_slots.glsl: bad rows");

std::vector<std::string> slot_names() { return slot_names_of(kSlotRows); }

void bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, kSlotRows, BD_PIXEL_SLOTS);
}

}  // namespace

const ShaderFamily kBloomDownsampleFamily = {
    "bloom_downsample", BD_SLOTS,       slot_names(),  make_inputs, eval_f, eval_d,
    output_range,       BD_PIXEL_SLOTS, bind_uniforms,
};
const FamilyRegistrar kRegisterBloomDownsample(&kBloomDownsampleFamily);

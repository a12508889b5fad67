// tiershade families: the color_correction family: input records (random and hard cases),
// the LUT textures, and the bridge to its C twin (c_ref/twins/color_correction.c).
#include <cmath>
#include <limits>

#include "families/color_correction_inputs.h"
#include "twins/color_correction.h"
#include "families/family.h"
#include "families/hard_cases.h"
#include "families/slot_table.h"

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

const char *const kVolumeSamplers[CC_MAX_LOOKUPS] = {"u_lut0", "u_lut1", "u_lut2", "u_lut3"};
const char *const kAtlasSamplers[CC_MAX_LOOKUPS] = {"u_lut_atlas0", "u_lut_atlas1", "u_lut_atlas2", "u_lut_atlas3"};

cc_variant to_cc(const Variant &v) {
  cc_variant c;
  c.atlas = v.value("LUT_ATLAS");
  c.shader_trilinear = v.value("SHADER_TRILINEAR");
  c.num_lookups = v.value("NUM_LOOKUPS");
  return c;
}

void gather(const FamilyInputs &in, int x, int y, ts_vec4f rec[CC_SLOTS]) {
  for (int k = 0; k < CC_SLOTS; ++k) rec[k] = in.slot(x, y, k);
}

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[CC_SLOTS];
  gather(in, x, y, rec);
  const cc_variant c = to_cc(v);
  cc_luts luts;
  cc_luts_of(in, &luts);
  return color_correction_f(&c, rec, &luts);
}

ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[CC_SLOTS];
  gather(in, x, y, rec);
  const cc_variant c = to_cc(v);
  cc_luts luts;
  cc_luts_of(in, &luts);
  return color_correction_d(&c, rec, &luts);
}

void output_range(const Variant &, float *lo, float *hi) {
  *lo = 0.f;  // the output is saturated (an 8-bit display target)
  *hi = 1.f;
}

// A LUT with random nodes in [-0.25, 1.25] (random, so that every tap and weight shows in
// the bits); the hard set also gets extreme and non-finite nodes.
Lut3D random_lut(Rng &r, int n, bool hard) {
  Lut3D l;
  l.n = n;
  l.rgb.resize(static_cast<size_t>(n) * n * n * 3);
  const float extremes[] = {0.f, 1.f, -0.f, 65504.f, -65504.f, 1e-39f, kNaN, kInf, -kInf, 3e38f};
  for (float &x : l.rgb) {
    x = r.uniform(-0.25f, 1.25f);
    if (hard && r.next() % 16 == 0) x = extremes[r.next() % (sizeof extremes / sizeof extremes[0])];
  }
  l.title = "random";
  return l;
}

void random_pixel(Rng &r, int n, ts_vec4f rec[CC_SLOTS]) {
  rec[CC_SLOT_COLOR] = ts_v4f(r.uniform(-0.1f, 1.1f), r.uniform(-0.1f, 1.1f), r.uniform(-0.1f, 1.1f), r.uniform(0, 1));
  rec[CC_SLOT_WEIGHTS] =
      ts_v4f(r.uniform(-0.25f, 1.25f), r.uniform(-0.25f, 1.25f), r.uniform(-0.25f, 1.25f), r.uniform(-0.25f, 1.25f));
  rec[CC_SLOT_PARAMS] = ts_v4f(r.uniform(-0.25f, 1.25f), 0, 0, 0);
  rec[CC_SLOT_LUT] = cc_lut_params(n);
}

// The hard grid's LUT edge: an odd 17^3 (a common .cube edge), so that both power-of-two and
// other edges are addressed (the random grid has Source's 32^3).
constexpr int kHardLutEdge = 17;

// lattice(): a random lattice node k/(N-1) of the hard grid's LUTs, for tests/conform/color_correction.cases.
const CaseFunctionRegistrar kCaseFunctions("color_correction",
                                           {{"lattice", {}, 1, "", [](const float *, const CaseEval &env, float *out) {
                                               const uint32_t n = kHardLutEdge;
                                               out[0] =
                                                   static_cast<float>(env.rng->next() % n) / static_cast<float>(n - 1);
                                             }}});

void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  const int n = set == InputSet::Random ? 32 : kHardLutEdge;
  Rng r(seed);
  // The hard cases: tests/conform/color_correction.cases.
  fill_record_grid(
      "color_correction", set, w, h, CC_SLOTS, r, [&](ts_vec4f *rec) { random_pixel(r, n, rec); }, out);
  std::vector<Lut3D> luts;
  for (int i = 0; i < CC_MAX_LOOKUPS; ++i) luts.push_back(random_lut(r, n, set == InputSet::Hard));
  cc_set_luts(out, {&luts[0], &luts[1], &luts[2], &luts[3]}, true);
  // LUTs 1 and 3 are NEAREST, so that both filters meet both filtering variants
  // (shader filtering samples texel centres: docs/color_correction.md).
  for (int i : {1, 3}) {
    out->textures[i].linear = false;
    out->textures[CC_MAX_LOOKUPS + i].linear = false;
  }
}

// The record layout: shaders/color_correction_slots.glsl, the one table (slot_table.h).
#define TS_SLOT TS_SLOT_ROW
constexpr SlotRow kSlotRows[] = {
#include "../../shaders/color_correction_slots.glsl"
};
#undef TS_SLOT
static_assert(slot_rows_valid(kSlotRows, CC_SLOTS, CC_PIXEL_SLOTS), "shaders/color_correction_slots.glsl: bad rows");

std::vector<std::string> slot_names() { return slot_names_of(kSlotRows); }

void bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, kSlotRows, CC_PIXEL_SLOTS);
}

}  // namespace

void cc_set_luts(FamilyInputs *in, const std::vector<const Lut3D *> &luts, bool linear) {
  static const Lut3D kUnused = identity_lut(2);
  in->textures.clear();
  for (int i = 0; i < CC_MAX_LOOKUPS; ++i) {
    const Lut3D &l = i < static_cast<int>(luts.size()) && luts[i] ? *luts[i] : kUnused;
    in->textures.push_back(lut_volume_texture(l, kVolumeSamplers[i], linear));
  }
  for (int i = 0; i < CC_MAX_LOOKUPS; ++i) {
    const Lut3D &l = i < static_cast<int>(luts.size()) && luts[i] ? *luts[i] : kUnused;
    in->textures.push_back(lut_atlas_texture(l, kAtlasSamplers[i], linear));
  }
}

void cc_frame_inputs(const ImageF &frame, const float weights[4], float default_weight, int lut_n, FamilyInputs *in) {
  in->resize(frame.w, frame.h, CC_PIXEL_SLOTS);
  in->case_names.clear();
  for (int y = 0; y < frame.h; ++y)
    for (int x = 0; x < frame.w; ++x) {
      const float *p = &frame.rgba[(static_cast<size_t>(y) * frame.w + x) * 4];
      in->set_slot(x, y, CC_SLOT_COLOR, ts_v4f(p[0], p[1], p[2], p[3]));
    }
  in->shared.assign(CC_SLOTS, ts_v4f(0, 0, 0, 0));
  in->shared[CC_SLOT_WEIGHTS] = ts_v4f(weights[0], weights[1], weights[2], weights[3]);
  in->shared[CC_SLOT_PARAMS] = ts_v4f(default_weight, 0, 0, 0);
  in->shared[CC_SLOT_LUT] = cc_lut_params(lut_n);
}

void cc_luts_of(const FamilyInputs &in, cc_luts *out) {
  for (int i = 0; i < CC_MAX_LOOKUPS; ++i) {
    out->volume[i] = tex3d_of(in.textures.at(i));
    out->atlas[i] = tex2d_of(in.textures.at(CC_MAX_LOOKUPS + i));
  }
}

const ShaderFamily kColorCorrectionFamily = {
    "color_correction", CC_SLOTS,       slot_names(),  make_inputs, eval_f, eval_d,
    output_range,       CC_PIXEL_SLOTS, bind_uniforms,
};
const FamilyRegistrar kRegister(&kColorCorrectionFamily);

// tiershade families: the color_correction family: input records (random and hard cases),
// the LUT textures, and the bridge to its C twin (c_ref/twins/color_correction.c).
#include <cmath>
#include <iterator>
#include <limits>

#include "families/color_correction_inputs.h"
#include "families/record_family.h"
#include "twins/color_correction.h"

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

cc_luts luts_of(const FamilyInputs &in) {
  cc_luts luts;
  cc_luts_of(in, &luts);
  return luts;
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

// The grids' LUT edge: Source's 32^3 on the random grid; on the hard grid an odd 17^3 (a common
// .cube edge), so that both power-of-two and other edges are addressed.
constexpr int kHardLutEdge = 17;
int lut_edge(InputSet set) { return set == InputSet::Random ? 32 : kHardLutEdge; }

void random_pixel(Rng &r, InputSet set, ts_vec4f rec[CC_SLOTS]) {
  rec[CC_SLOT_COLOR] = ts_v4f(r.uniform(-0.1f, 1.1f), r.uniform(-0.1f, 1.1f), r.uniform(-0.1f, 1.1f), r.uniform(0, 1));
  rec[CC_SLOT_WEIGHTS] =
      ts_v4f(r.uniform(-0.25f, 1.25f), r.uniform(-0.25f, 1.25f), r.uniform(-0.25f, 1.25f), r.uniform(-0.25f, 1.25f));
  rec[CC_SLOT_PARAMS] = ts_v4f(r.uniform(-0.25f, 1.25f), 0, 0, 0);
  rec[CC_SLOT_LUT] = cc_lut_params(lut_edge(set));
}

// lattice(): a random lattice node k/(N-1) of the hard grid's LUTs, for tests/conform/color_correction.cases.
const CaseFunctionRegistrar kCaseFunctions("color_correction",
                                           {{"lattice", {}, 1, "", [](const float *, const CaseEval &env, float *out) {
                                               const uint32_t n = kHardLutEdge;
                                               out[0] =
                                                   static_cast<float>(env.rng->next() % n) / static_cast<float>(n - 1);
                                             }}});

// The LUTs, drawn after the records (and the hard cases of tests/conform/color_correction.cases).
void random_luts(Rng &r, InputSet set, FamilyInputs *out) {
  std::vector<Lut3D> luts;
  for (int i = 0; i < CC_MAX_LOOKUPS; ++i) luts.push_back(random_lut(r, lut_edge(set), set == InputSet::Hard));
  cc_set_luts(out, {&luts[0], &luts[1], &luts[2], &luts[3]}, true);
  // LUTs 1 and 3 are NEAREST, so that both filters meet both filtering variants
  // (shader filtering samples texel centres: docs/color_correction.md).
  for (int i : {1, 3}) {
    out->textures[i].linear = false;
    out->textures[CC_MAX_LOOKUPS + i].linear = false;
  }
}

// The record layout: shaders/color_correction_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/color_correction_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {
    "color_correction",   CC_SLOTS,         CC_PIXEL_SLOTS, kSlotRows,
    std::size(kSlotRows), output_range_unit};  // the output is saturated (an 8-bit display target)

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

const ShaderFamily kColorCorrectionFamily =
    twin_family<kLayout, to_cc, luts_of, color_correction_f, color_correction_d, random_pixel, random_luts>();
const FamilyRegistrar kRegister(&kColorCorrectionFamily);

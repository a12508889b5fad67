// tiershade families: the texture_grad family (a mip chain sampled with explicit derivatives,
// docs/conformance.md "Explicit derivatives"): its records (random and hard), its two mip-mapped
// textures, and the bridge to its C twin (c_ref/twins/texture_grad.c).
#include "families/texture_grad.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "families/record_family.h"
#include "gl/mipmaps.h"
#include "math/hdr_formats.h"
#include "twins/texture_grad.h"

namespace {

// Both POT (GLES 2 / WebGL 1 have no NPOT mipmaps); 6 levels each, different aspect ratios so
// that the s and t terms of rho are not interchangeable.
constexpr int kLinearW = 32, kLinearH = 16, kNearestW = 16, kNearestH = 32;

#define TS_SLOT_FILE "../../shaders/texture_grad_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"texture_grad", TG_SLOTS, TG_PIXEL_SLOTS, kSlotRows, std::size(kSlotRows),
                                  output_range_half};

// A derivative spanning the chain: |d| * size from 2^-4 (magnified) to 2^8 (past the 1x1 level),
// either sign, sometimes exactly 0 (an axis-aligned footprint) or a power of two (lambda an
// integer: the level edges of the LINEAR and NEAREST filters).
float random_derivative(Rng &r) {
  const uint32_t k = r.next() % 8;
  if (k == 0) return 0.f;
  const float m = k == 1 ? std::exp2(std::floor(r.uniform(-9.f, 4.f))) : std::exp2(r.uniform(-9.f, 4.f));
  return r.next() % 2 ? -m : m;
}

void random_pixel(Rng &r, InputSet, ts_vec4f rec[TG_SLOTS]) {
  rec[TG_SLOT_UV] = ts_v4f(r.uniform(-1.5f, 2.5f), r.uniform(-1.5f, 2.5f), 0.f, 0.f);
  const float a = random_derivative(r), b = random_derivative(r), c = random_derivative(r), d = random_derivative(r);
  // a quarter anisotropic: one axis 2^3 .. 2^6 times the other
  if (r.next() % 4 == 0) {
    rec[TG_SLOT_GRAD] = ts_v4f(a, 0.f, 0.f, (b < 0 ? -a : a) * std::exp2(r.uniform(3.f, 6.f)));
  } else {
    rec[TG_SLOT_GRAD] = ts_v4f(a, b, c, d);
  }
}

TextureDesc mip_texture(Rng &r, const char *sampler, int w, int h, bool repeat, int mip_filter) {
  TextureDesc t = blank_texture(sampler, w, h, true, repeat);
  for (float &v : t.rgba) v = ts_quantize_half(r.uniform(0.f, 64.f));
  build_mip_chain(&t, MipContent::Color);
  t.mip_filter = mip_filter;
  return t;
}

void textures(Rng &r, InputSet, FamilyInputs *out) {
  out->textures = {mip_texture(r, "u_mips_linear", kLinearW, kLinearH, true, TS_MIP_LINEAR),
                   mip_texture(r, "u_mips_nearest", kNearestW, kNearestH, false, TS_MIP_NEAREST)};
}

tg_variant to_tg(const Variant &v) { return {v.value("MIP_NEAREST")}; }

// The twin's textures (the variant picks one of the two).
struct TgViews {
  ts_tex2d lin, nea;
  tg_textures t;
  explicit TgViews(const FamilyInputs &in) : lin(tex2d_of(in.textures.at(0))), nea(tex2d_of(in.textures.at(1))) {
    t = {&lin, &nea};
  }
};

template <class R, R (*Twin)(const tg_variant *, const ts_vec4f *, const tg_textures *)>
R eval(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[TG_SLOTS];
  in.gather(x, y, TG_SLOTS, rec);
  const tg_variant tv = to_tg(v);
  const TgViews views(in);
  return Twin(&tv, rec, &views.t);
}

}  // namespace

// The interval twin on pixel (x, y) (glue/conform/bounds.cpp), with the same record and textures
// as eval_f.
ts_vec4iv texture_grad_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  return eval<ts_vec4iv, texture_grad_iv>(v, in, x, y);
}

const ShaderFamily kTextureGradFamily =
    family_of<kLayout>(record_inputs<kLayout, random_pixel, textures>, eval<ts_vec4f, texture_grad_f>,
                       eval<ts_vec4d, texture_grad_d>);
const FamilyRegistrar kRegisterTextureGrad(&kTextureGradFamily);

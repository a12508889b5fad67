// tiershade tests: unit tests of the world_lighting family's C side and of the GL facts it rests on:
//  - the RNM basis (c_ref/offline/rnm_bake.c) against the fact sheet's constants;
//  - the baker: cosine weights, clamping, a light behind the face, the handedness
//    of GetBumpNormals, bad input;
//  - the shader twin (c_ref/twins/world_lighting.c): RNM weights and the zero-sum case,
//    ssbump, the four lightmap decodes (largest and smallest RGBE exponents),
//    Fresnel at N.V = 0 and 1, the mask sources;
//  - the offline encoders (c_ref/offline/lightmap_encoding.c): RGBE, fp16, "4.12", LDR;
//  - the lightmap page layout (c_ref/offline/lightmap_page.c) and probe choice (envmap_probes.c);
//  - GL: LINEAR cube maps are bit-exact on desktop GL (seamless off), and GLES cube
//    maps are seamless on this Mesa (why conformance samples the envmap NEAREST).
// Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
// Tolerances are written next to each check with their reason.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "conform/conform.h"
#include "offline/envmap_probes.h"
#include "families/world_lighting.h"
#include "offline/lightmap_encoding.h"
#include "offline/lightmap_page.h"
#include "offline/rnm_bake.h"
#include "cli/select_args.h"
#include "unit_check.h"

namespace {

std::string num(double v) {
  char b[64];
  snprintf(b, sizeof b, "%.9g", v);
  return b;
}

double dot(ts_vec3d a, ts_vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// ---- basis and baker ---------------------------------------------------------
void check_basis() {
  // The fact sheet's float constants, to the 8 digits it prints (1e-7 = its last digit).
  const double want[3][3] = {
      {0.81649661, 0, 0.57735026}, {-0.40824830, 0.70710677, 0.57735026}, {-0.40824830, -0.70710677, 0.57735026}};
  double worst = 0, ortho = 0;
  for (int k = 0; k < 3; ++k) {
    const ts_vec3d b = rnm_basis(k);
    worst = std::fmax(worst, std::fabs(b.x - want[k][0]) + std::fabs(b.y - want[k][1]) + std::fabs(b.z - want[k][2]));
    for (int j = 0; j < 3; ++j) ortho = std::fmax(ortho, std::fabs(dot(b, rnm_basis(j)) - (j == k ? 1.0 : 0.0)));
  }
  check(worst < 3e-7, "basis matches the fact sheet", "max deviation " + num(worst));
  // Orthonormal to double rounding (1e-15: a few ulps of 1).
  check(ortho < 1e-15, "basis is orthonormal", "max |b_j.b_k - delta| " + num(ortho));
  check(std::fabs(std::acos(rnm_basis(1).z) * 180 / M_PI - 54.7356) < 1e-3,
        "each basis vector is 54.7 deg off the normal");
}

void check_bake() {
  char err[256];
  ts_vec3d bump[3];
  const ts_vec3d N = ts_v3d(0, 0, 1);
  int rc = rnm_bump_basis(ts_v3d(1, 0, 0), ts_v3d(0, 1, 0), N, N, bump, err, sizeof err);
  check(rc == 0, "bump basis of an axis-aligned face", err);
  double dev = 0;
  for (int k = 0; k < 3; ++k) {
    const ts_vec3d b = rnm_basis(k);
    dev = std::fmax(dev, std::fabs(bump[k].x - b.x) + std::fabs(bump[k].y - b.y) + std::fabs(bump[k].z - b.z));
  }
  check(dev < 1e-15, "axis-aligned right-handed frame: world bump vectors = tangent basis", num(dev));
  ts_vec3d left[3];
  rnm_bump_basis(ts_v3d(1, 0, 0), ts_v3d(0, -1, 0), N, N, left, err, sizeof err);
  check(std::fabs(left[1].y + bump[1].y) < 1e-15 && std::fabs(left[0].x - bump[0].x) < 1e-15,
        "left-handed S x T mirrors the bump vectors' axis1 component");
  check(rnm_bump_basis(ts_v3d(0, 0, 2), ts_v3d(0, 1, 0), N, N, left, err, sizeof err) == -1 &&
            std::string(err).find("parallel") != std::string::npos,
        "S parallel to the normal is an error", err);

  // A unit directional light along b0: bumped = (1, 0, 0) (orthonormal basis), flat = 1/sqrt3.
  rnm_light sun{};
  sun.directional = 1;
  sun.dir = ts_v3d(-rnm_basis(0).x, -rnm_basis(0).y, -rnm_basis(0).z);
  sun.color = ts_v3d(1, 2, 3);
  ts_vec3d out[4];
  rc = rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &sun, 1, out, err, sizeof err);
  // 1e-12: a handful of double roundings in unit-size sums.
  check(rc == 0 && std::fabs(out[1].x - 1) < 1e-12 && std::fabs(out[1].z - 3) < 1e-12 && std::fabs(out[2].x) < 1e-12 &&
            std::fabs(out[3].x) < 1e-12 && std::fabs(out[0].y - 2 / std::sqrt(3.0)) < 1e-12,
        "light along b0 feeds b0 only; flat gets cos 54.7 deg",
        num(out[0].y) + " " + num(out[1].x) + " " + num(out[2].x) + " " + num(out[3].x));
  // Grazing from +x (just above the face): b0 lit, b1 and b2 (x < 0) clamped to 0, never negative.
  sun.dir = ts_v3d(-1, 0, -0.05);
  rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &sun, 1, out, err, sizeof err);
  check(out[1].x > 0 && out[2].x == 0 && out[3].x == 0 && out[0].x > 0, "negative basis dots are clamped to 0");
  // From below the face: nothing at all, although b0 faces the light partly (it is tilted).
  sun.dir = ts_v3d(-1, 0, 0.3);
  rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &sun, 1, out, err, sizeof err);
  check(out[0].x == 0 && out[1].x == 0 && out[2].x == 0 && out[3].x == 0 && -dot(bump[0], sun.dir) > 0,
        "a light behind the face blanks all three bumped values");
  // Point light with falloff 1/(1 + 0 d + 1 d^2) at distance 2 overhead: flat = I / 5.
  rnm_light pt{};
  pt.pos = ts_v3d(0, 0, 2);
  pt.color = ts_v3d(5, 5, 5);
  pt.atten[0] = 1;
  pt.atten[2] = 1;
  rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &pt, 1, out, err, sizeof err);
  check(std::fabs(out[0].x - 1) < 1e-12 && std::fabs(out[1].x - 1 / std::sqrt(3.0)) < 1e-12,
        "point light falloff and cosine", num(out[0].x) + " " + num(out[1].x));
  // The same light as a spot pointing straight down (vrad's cone, rnm_bake.h): on the axis
  // dot2 = 1, the same as the point light; outside the outer cone nothing; between the cones
  // dot2 * ((dot2 - cos_outer) / (cos_inner - cos_outer))^exponent times the point light's value.
  rnm_light sp = pt;
  sp.spot = 1;
  sp.spot_dir = ts_v3d(0, 0, -3);  // not unit: normalised
  sp.cos_inner = std::cos(0.2);
  sp.cos_outer = std::cos(0.6);
  sp.exponent = 2;
  ts_vec3d ref[4];
  rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &sp, 1, out, err, sizeof err);
  check(std::fabs(out[0].x - 1) < 1e-12 && std::fabs(out[1].x - 1 / std::sqrt(3.0)) < 1e-12,
        "spot on its axis = the point light", num(out[0].x));
  const ts_vec3d between = ts_v3d(2 * std::tan(0.4), 0, 0);  // 0.4 rad off the axis
  rnm_bake_texel(between, N, bump, &sp, 1, out, err, sizeof err);
  rnm_bake_texel(between, N, bump, &pt, 1, ref, err, sizeof err);
  const double c = std::cos(0.4), want = c * std::pow((c - sp.cos_outer) / (sp.cos_inner - sp.cos_outer), 2.0);
  // 1e-12 relative: the cosine of the angle is recomputed from a unit vector.
  check(ref[0].x > 0 && std::fabs(out[0].x / ref[0].x - want) < 1e-12, "spot between its cones: dot2 * ramp^exponent",
        num(out[0].x / ref[0].x) + " vs " + num(want));
  rnm_bake_texel(ts_v3d(2 * std::tan(0.7), 0, 0), N, bump, &sp, 1, out, err, sizeof err);
  check(out[0].x == 0 && out[1].x == 0 && out[2].x == 0 && out[3].x == 0, "spot: nothing outside its outer cone");
  sp.spot_dir = ts_v3d(0, 0, 0);
  check(rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &sp, 1, out, err, sizeof err) == -1 &&
            std::string(err).find("light 0 (spot)") != std::string::npos,
        "a spot with a zero axis is an error naming the light", err);
  sp.spot_dir = ts_v3d(0, 0, -1);
  sp.cos_inner = sp.cos_outer;
  check(rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &sp, 1, out, err, sizeof err) == -1,
        "a spot with no cone ramp is an error", err);
  pt.atten[0] = pt.atten[2] = 0;
  check(rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &pt, 1, out, err, sizeof err) == -1 &&
            std::string(err).find("light 0") != std::string::npos,
        "zero falloff coefficients are an error naming the light", err);
  pt.atten[0] = 1;
  pt.color.x = std::numeric_limits<double>::quiet_NaN();
  check(rnm_bake_texel(ts_v3d(0, 0, 0), N, bump, &pt, 1, out, err, sizeof err) == -1, "NaN light colour is an error",
        err);
}

// ---- the shader twin --------------------------------------------------------------
struct Tex {
  std::vector<float> px;
  ts_tex2d t{};
  Tex(int w, int h, bool linear) : px(static_cast<size_t>(w) * h * 4, 1.f) {
    t.w = w;
    t.h = h;
    t.texels = px.data();
    t.wrap_s = t.wrap_t = TS_WRAP_CLAMP;
    t.filter = linear ? TS_FILTER_LINEAR : TS_FILTER_NEAREST;
  }
  void set(int x, int y, float r, float g, float b, float a) {
    float *p = &px[(static_cast<size_t>(y) * t.w + x) * 4];
    p[0] = r;
    p[1] = g;
    p[2] = b;
    p[3] = a;
  }
  void fill(float r, float g, float b, float a) {
    for (int y = 0; y < t.h; ++y)
      for (int x = 0; x < t.w; ++x) set(x, y, r, g, b, a);
  }
};

// A 1x1 normal map, a 4x1 NEAREST lightmap (flat, L1, L2, L3 at texels 0..3), white base.
struct Scene1 {
  Tex base{1, 1, false}, nm{1, 1, false}, lm{4, 1, false}, mask{1, 1, false};
  std::vector<float> cube_px = std::vector<float>(6 * 4, 1.f);
  ts_texcube cube{};
  wl_textures tx{};
  ts_vec4f rec[WL_SLOTS];
  Scene1() {
    cube.size = 1;
    for (int f = 0; f < 6; ++f) cube.faces[f] = &cube_px[f * 4];
    cube.filter = TS_FILTER_NEAREST;
    tx.base = &base.t;
    tx.normalmap = &nm.t;
    tx.lightmap = &lm.t;
    tx.envmap_mask = &mask.t;
    tx.envmap = &cube;
    wl_defaults(rec);
    rec[WL_SLOT_UV] = ts_v4f(0.5f, 0.5f, 0.125f, 0.5f);  // lightmap texel 0
    rec[WL_SLOT_LM_OFFSET] = ts_v4f(0.25f, 0, 0, 0);  // next lightmap = next texel
  }
  ts_vec4f shade(int tier, int bump, int enc, int envmap = 0, int mask_src = 0) {
    wl_variant v{tier, bump, enc, envmap, mask_src};
    return world_lighting_f(&v, rec, &tx);
  }
};

void check_twin() {
  Scene1 s;
  s.lm.set(0, 0, 9, 9, 9, 1);
  s.lm.set(1, 0, 1, 0, 0, 1);
  s.lm.set(2, 0, 0, 1, 0, 1);
  s.lm.set(3, 0, 0, 0, 1, 1);
  // n = b0: d = (1, 0, 0) + 1e-30: the b0 lightmap alone (the others weigh < 1e-15).
  const ts_vec3d b0 = rnm_basis(0);
  s.nm.set(0, 0, static_cast<float>(0.5 * b0.x + 0.5), 0.5f, static_cast<float>(0.5 * b0.z + 0.5), 1);
  ts_vec4f c = s.shade(TS_TIER_ID_SM3, WL_BUMP_RNM, WL_LM_FLOAT);
  // 1e-6: the 8-bit-free float texel of b0 and the float basis constants agree to ~1e-7.
  check(std::fabs(c.x - 1) < 1e-6 && c.y < 1e-6 && c.z < 1e-6, "RNM: n = b0 selects lightmap 1",
        num(c.x) + " " + num(c.y) + " " + num(c.z));
  // Flat normal: equal weights, the mean of the three.
  s.nm.set(0, 0, 0.5f, 0.5f, 1.f, 1);
  c = s.shade(TS_TIER_ID_SM3, WL_BUMP_RNM, WL_LM_FLOAT);
  check(std::fabs(c.x - 1 / 3.) < 1e-6 && std::fabs(c.y - 1 / 3.) < 1e-6 && std::fabs(c.z - 1 / 3.) < 1e-6,
        "RNM: the flat normal averages the three lightmaps", num(c.x) + " " + num(c.y) + " " + num(c.z));
  // Zero-length texel and a normal pointing into the surface: sum(d_k) = 0 would be 0/0.
  for (int t = 0; t < 2; ++t) {
    s.nm.set(0, 0, 0.5f, 0.5f, t ? 0.f : 0.5f, 1);
    for (int tier = 0; tier < 3; ++tier) {
      c = s.shade(tier, WL_BUMP_RNM, WL_LM_FLOAT);
      check(std::isfinite(c.x) && std::fabs(c.x - 1 / 3.) < 1e-6 && std::fabs(c.z - 1 / 3.) < 1e-6,
            std::string("RNM: zero weights give the mean, not NaN (") + (t ? "n = -z" : "zero-length") + ", tier " +
                std::to_string(tier) + ")",
            num(c.x));
    }
  }
  // ssbump: the texel is the weights, no normalisation.
  s.nm.set(0, 0, 0.25f, 0.5f, 2.f, 1);
  c = s.shade(TS_TIER_ID_SM3, WL_BUMP_SSBUMP, WL_LM_FLOAT);
  check(c.x == 0.25f && c.y == 0.5f && c.z == 2.f, "ssbump: weights straight from the texel",
        num(c.x) + " " + num(c.y) + " " + num(c.z));
  s.nm.set(0, 0, 0, 0, 0, 1);
  c = s.shade(TS_TIER_ID_PS20, WL_BUMP_SSBUMP, WL_LM_FLOAT, 1, 0);
  // Zero weights and a zero normal: diffuse 0; R = 0 samples the centre of +Z (cube = 1)
  // and N.V = 0 gives F = 1 with R0 = 1: exactly the cube value.
  check(c.x == 1 && c.y == 1 && c.z == 1, "ssbump zero texel: no diffuse, finite envmap term",
        num(c.x) + " " + num(c.y));
  // Flat lightmap: texel 0 times c12 and the tone-map scale.
  s.rec[WL_SLOT_TINT_SCALE] = ts_v4f(0.5f, 1, 2, 2);
  c = s.shade(TS_TIER_ID_PS2B, WL_BUMP_NONE, WL_LM_FLOAT);
  check(c.x == 9 && c.y == 18 && c.z == 36, "flat lightmap x tint x tone-map scale", num(c.x) + " " + num(c.z));
  s.rec[WL_SLOT_TINT_SCALE] = ts_v4f(1, 1, 1, 1);

  // The decodes, read back through the flat path (white base, unit scales).
  auto flat = [&](int enc, float r, float g, float b, float a, int tier = TS_TIER_ID_SM3) {
    s.lm.set(0, 0, r, g, b, a);
    return s.shade(tier, WL_BUMP_NONE, enc);
  };
  c = flat(WL_LM_412, 1, 0.5f, 0, 0);
  check(c.x == 16 && c.y == 8 && c.z == 0, "4.12 decode: t x 16, top of range 16", num(c.x));
  c = flat(WL_LM_LDR, 0.5f, 1, 0, 0);
  // 2e-6 relative: llvmpipe's pow (exp2/log2 polynomials) is a few ulps from the exact (2t)^2.2.
  check(std::fabs(c.x - 1) < 2e-6 && std::fabs(c.y - std::pow(2.0, 2.2)) < 2e-6 * 4.6 && c.z == 0,
        "LDR decode: (2t)^2.2, 0.5 -> 1, 1 -> 4.59", num(c.x) + " " + num(c.y));
  ts_rgbe e{255, 128, 1, 0};
  float tx[4];
  ts_rgbe_texel(e, tx);
  c = flat(WL_LM_RGBE, tx[0], tx[1], tx[2], tx[3]);
  double want[3];
  ts_rgbe_decode(e, want);
  // 1e-6 relative: the shader forms the exponent as 255 a - 128 from a float a = k/255,
  // which is k within an ulp, and exp2's polynomial is within 2 ulps of 2^k.
  check(
      std::fabs(c.x / want[0] - 1) < 1e-6 && std::fabs(c.y / want[1] - 1) < 1e-6 && std::fabs(c.z / want[2] - 1) < 1e-6,
      "RGBE decode in the shader = TexLightToLinear", num(c.x) + " vs " + num(want[0]));
  e = ts_rgbe{255, 255, 255, 127};
  ts_rgbe_texel(e, tx);
  c = flat(WL_LM_RGBE, tx[0], tx[1], tx[2], tx[3]);
  check(c.x == 65504.f, "RGBE largest exponent (2^127) saturates the output at 65504", num(c.x));
  e = ts_rgbe{255, 255, 255, -128};
  ts_rgbe_texel(e, tx);
  c = flat(WL_LM_RGBE, tx[0], tx[1], tx[2], tx[3]);
  // 2^-128 is below FLT_MIN: llvmpipe's exp2 clamps its argument at -126.99999 and the
  // product flushes to zero; either way the result is 0 or a normal float below 2^-126.
  check(std::isfinite(c.x) && c.x >= 0 && c.x < 1.2e-38f, "RGBE smallest exponent: finite, ~0", num(c.x));

  // ps20 decodes LDR as (2t)^2: exact at 2t = 1, 0.25 against 0.2176 at 2t = 0.5.
  c = flat(WL_LM_LDR, 0.5f, 0.25f, 0, 0, TS_TIER_ID_PS20);
  check(c.x == 1.f && c.y == 0.25f && c.z == 0, "ps20 LDR decode: (2t)^2", num(c.x) + " " + num(c.y));

  // Envmap: cube = 1 everywhere; flat normal, eye along N: R = N, N.V = 1, F = R0.
  s.lm.fill(0, 0, 0, 0);
  s.rec[WL_SLOT_EYE] = ts_v4f(0, 0, 2, 0);
  s.rec[WL_SLOT_ENV_PARAMS] = ts_v4f(0, 1, 0.75f, 0.25f);
  c = s.shade(TS_TIER_ID_SM3, WL_BUMP_NONE, WL_LM_FLOAT, 1, 0);
  check(c.x == 0.25f, "Fresnel at N.V = 1 is R0", num(c.x));
  s.rec[WL_SLOT_EYE] = ts_v4f(2, 0, 0, 0);
  c = s.shade(TS_TIER_ID_SM3, WL_BUMP_NONE, WL_LM_FLOAT, 1, 0);
  check(c.x == 1.f, "Fresnel at N.V = 0 is 1", num(c.x));
  s.rec[WL_SLOT_EYE] = ts_v4f(2, 0, -1, 0);
  c = s.shade(TS_TIER_ID_PS20, WL_BUMP_NONE, WL_LM_FLOAT, 1, 0);
  check(c.x == 1.f, "Fresnel with N.V < 0 (back-facing) is clamped to 1", num(c.x));
  s.rec[WL_SLOT_EYE] = ts_v4f(1, 0, 1, 0);  // N.V = cos 45 deg: F = (1 - 0.7071)^5 0.75 + 0.25
  const double f45 = std::pow(1 - std::sqrt(0.5), 5) * 0.75 + 0.25;
  for (int tier = 0; tier < 3; ++tier) {
    c = s.shade(tier, WL_BUMP_NONE, WL_LM_FLOAT, 1, 0);
    check(std::fabs(c.x - f45) < 1e-6, "Fresnel at 45 deg, tier " + std::to_string(tier), num(c.x) + " vs " + num(f45));
  }
  // Mask sources: mask texture rgb, normal-map alpha, 1 - base alpha.
  s.rec[WL_SLOT_ENV_PARAMS] = ts_v4f(0, 1, 0, 1);
  s.mask.set(0, 0, 0.5f, 0.25f, 0, 1);
  s.nm.set(0, 0, 0.5f, 0.5f, 1, 0.125f);
  s.base.set(0, 0, 1, 1, 1, 0.75f);
  c = s.shade(TS_TIER_ID_PS2B, WL_BUMP_NONE, WL_LM_FLOAT, 1, WL_MASK_TEXTURE);
  check(c.x == 0.5f && c.y == 0.25f && c.z == 0, "mask from the mask texture", num(c.x));
  c = s.shade(TS_TIER_ID_PS2B, WL_BUMP_RNM, WL_LM_FLOAT, 1, WL_MASK_NORMAL_ALPHA);
  check(c.x == 0.125f, "mask from the normal-map alpha", num(c.x));
  c = s.shade(TS_TIER_ID_PS2B, WL_BUMP_NONE, WL_LM_FLOAT, 1, WL_MASK_INV_BASE_ALPHA);
  check(c.x == 0.25f, "mask from the inverted base alpha", num(c.x));
  // Contrast 1 squares, saturation 0 gives the luma (0.299, 0.587, 0.114 weights).
  s.cube_px.assign(6 * 4, 0.f);
  for (int f = 0; f < 6; ++f) s.cube_px[f * 4] = 0.5f;
  s.base.set(0, 0, 1, 1, 1, 1);
  s.rec[WL_SLOT_ENV_PARAMS] = ts_v4f(1, 0, 0, 1);
  s.rec[WL_SLOT_EYE] = ts_v4f(0, 0, 1, 0);
  c = s.shade(TS_TIER_ID_SM3, WL_BUMP_NONE, WL_LM_FLOAT, 1, 0);
  check(std::fabs(c.x - 0.25 * 0.299) < 1e-7 && std::fabs(c.y - 0.25 * 0.299) < 1e-7,
        "contrast 1 squares, saturation 0 takes the luma", num(c.x) + " " + num(c.y));
}

// ---- encoders ------------------------------------------------------------------------
void check_encodings() {
  ts_rgbe e;
  double d[3];
  const float one[3] = {1, 0.5f, 0};
  ts_rgbe_encode(one, &e);
  ts_rgbe_decode(e, d);
  check(e.r == 255 && e.g == 127 && e.exponent == 0 && d[0] == 1.0, "RGBE: 1.0 -> (255, e = 0) -> 1.0",
        std::to_string(e.r) + " " + std::to_string(e.g) + " e " + std::to_string(e.exponent));
  const float t[3] = {200.7f / 255.f, 3.f / 255.f, 0};
  ts_rgbe_encode(t, &e);
  check(e.r == 200 && e.exponent == 0 && e.g == 3, "RGBE: mantissas are truncated, max channel in [128, 255]",
        std::to_string(e.r) + " e " + std::to_string(e.exponent));
  // Relative error of the largest channel below 2^-7 (a mantissa >= 128, truncated).
  Rng r(7);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const float v[3] = {std::exp(r.uniform(-20, 20)), 0, 0};
    ts_rgbe_encode(v, &e);
    ts_rgbe_decode(e, d);
    worst = std::fmax(worst, (v[0] - d[0]) / v[0]);
  }
  check(worst < 1.0 / 128 && worst > 0, "RGBE: relative error of the largest channel < 1/128 (truncation)", num(worst));
  const float huge[3] = {3e38f, 1, std::numeric_limits<float>::infinity()};  // 3e38 x 255 / 2^127 = 449 > 255
  ts_rgbe_encode(huge, &e);
  check(e.exponent == 127 && e.r == 255 && e.b == 255, "RGBE: exponent clamped at 127, mantissas saturate",
        std::to_string(e.exponent));
  // The smallest normal float: 255 x 2^-126 = 2^-118.0 -> e = -126, mantissa 255. (Below it,
  // float denormals are read as 0 under the math layer's DAZ: e = -128 is reached only by
  // stored data, which the shader hard cases cover.)
  const float tiny[3] = {std::numeric_limits<float>::min(), 0, 0};
  ts_rgbe_encode(tiny, &e);
  ts_rgbe_decode(e, d);
  check(e.exponent == -126 && e.r == 255 && d[0] == static_cast<double>(std::numeric_limits<float>::min()),
        "RGBE: the smallest normal float round-trips (e = -126)", std::to_string(e.exponent));
  const float nan3[3] = {0, std::numeric_limits<float>::quiet_NaN(), 0};
  check(ts_rgbe_encode(nan3, &e) == -1, "RGBE: NaN is refused");
  float tx[4];
  ts_rgbe_texel(ts_rgbe{1, 2, 3, -128}, tx);
  check(tx[3] == 0.f, "RGBE texel: e = -128 is alpha 0");
  ts_rgbe_texel(ts_rgbe{1, 2, 3, 127}, tx);
  check(tx[3] == 1.f, "RGBE texel: e = 127 is alpha 1");

  check(ts_half_quantize(1.f) == 1.f && ts_half_quantize(65504.f) == 65504.f && ts_half_quantize(1e6f) == 65504.f &&
            ts_half_quantize(-1e6f) == -65504.f,
        "fp16: exact values stay, overflow saturates at 65504");
  check(ts_half_quantize(1.f / 3.f) == 0.333251953125f, "fp16: 1/3 -> 0.333251953125", num(ts_half_quantize(1.f / 3)));
  check(ts_half_quantize(2049.f) == 2048.f && ts_half_quantize(2051.f) == 2052.f, "fp16: ties round to even");
  check(ts_half_quantize(std::ldexp(1.f, -24)) == std::ldexp(1.f, -24) && ts_half_quantize(std::ldexp(1.f, -26)) == 0.f,
        "fp16: smallest denormal 2^-24 kept, 2^-26 rounds to 0");
  check(std::isnan(ts_half_quantize(std::numeric_limits<float>::quiet_NaN())), "fp16: NaN stays NaN");
  check(ts_u16_412_quantize(16.f) == 1.f && ts_u16_412_quantize(100.f) == 1.f && ts_u16_412_quantize(-1.f) == 0.f,
        "4.12: range [0, 16], clamped");
  worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const float v = r.uniform(0, 16);
    worst = std::fmax(worst, std::fabs(16.0 * ts_u16_412_quantize(v) - v));
  }
  // Half a step of 16/65535, plus float rounding of the stored value (16 x 2^-24).
  check(worst <= 8.0 / 65535 + 1e-6, "4.12: absolute error <= half a step (16/65535/2)", num(worst));
  check(ts_ldr_quantize(1.f) == 128.f / 255.f && ts_ldr_quantize(10.f) == 1.f && ts_ldr_quantize(0.f) == 0.f,
        "LDR: 1.0 -> code 128 (0.5, overbright 2), clamped above 2^2.2", num(ts_ldr_quantize(1.f) * 255));
}

// ---- page layout and probes ------------------------------------------------------------------
void check_page() {
  char err[256];
  lm_face_size faces[3] = {{4, 3, 1}, {2, 2, 0}, {8, 8, 1}};
  lm_face_place p[3];
  const int W = 64, H = 32;
  int rc = lm_page_pack(W, H, faces, 3, p, err, sizeof err);
  check(rc == 0, "page: three faces packed", err);
  check(p[0].count == 4 && p[0].block_w == 6 && p[0].offset[0] == 6.f / W && p[0].offset[1] == 0 && p[1].count == 1 &&
            p[1].x == 24,
        "page: bumped faces get 4 blocks side by side, offset = block width / page width");
  // uv + k * offset lands on the centre of luxel (i, j) of block k.
  bool ok = true;
  for (int k = 0; k < 4; ++k) {
    float uv[2];
    lm_page_uv(&p[2], W, H, 1.0, 0.0, uv);
    const float u = uv[0] + k * p[2].offset[0];
    int tx, ty;
    lm_page_texel(&p[2], k, 7, 0, &tx, &ty);
    if (std::fabs(u * W - (tx + 0.5f)) > 1e-4f || std::fabs(uv[1] * H - (ty + 0.5f)) > 1e-4f) ok = false;
  }
  check(ok, "page: uv + k offset hits luxel (i, j) of lightmap k");
  std::vector<float> page(static_cast<size_t>(W) * H * 4, 0.f);
  int tx, ty;
  lm_page_texel(&p[0], 2, 0, 0, &tx, &ty);
  page[(static_cast<size_t>(ty) * W + tx) * 4] = 7.f;
  lm_page_fill_borders(&p[0], W, page.data());
  check(page[(static_cast<size_t>(ty - 1) * W + tx - 1) * 4] == 7.f &&
            page[(static_cast<size_t>(ty) * W + tx - 1) * 4] == 7.f,
        "page: borders copy the edge luxels");
  // A BSP face's RGBE blocks (flat, b0, b1, b2; 8x8 luxels each) decoded into the page.
  std::vector<unsigned char> bsp(4 * 64 * 4);
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 64; ++l) {
      unsigned char *c = &bsp[(static_cast<size_t>(k) * 64 + l) * 4];
      c[0] = static_cast<unsigned char>(128 + l);
      c[1] = static_cast<unsigned char>(k);
      c[2] = 0;
      c[3] = static_cast<unsigned char>(static_cast<signed char>(k - 2));
    }
  std::fill(page.begin(), page.end(), 0.f);
  lm_page_put_bsp_face(&p[2], W, bsp.data(), page.data());
  lm_page_texel(&p[2], 3, 5, 2, &tx, &ty);  // block 3 (b2), luxel (5, 2): l = 21, e = 1
  const float *q = &page[(static_cast<size_t>(ty) * W + tx) * 4];
  check(q[0] == (128 + 21) * 2.f / 255.f && q[1] == 3 * 2.f / 255.f && q[3] == 1.f,
        "page: a BSP face's RGBE blocks decode to c 2^e / 255 at uv + k offset", num(q[0]) + " " + num(q[1]));
  lm_page_texel(&p[2], 0, 0, 0, &tx, &ty);
  check(page[(static_cast<size_t>(ty - 1) * W + tx - 1) * 4] == 128 * 0.25f / 255.f, "page: BSP face borders filled");
  lm_face_size big = {40, 4, 1};
  rc = lm_page_pack(W, H, &big, 1, p, err, sizeof err);
  check(rc == -1 && std::string(err).find("face 0") != std::string::npos, "page: a face too wide is an error naming it",
        err);
  lm_face_size bad = {1, 4, 0};
  check(lm_page_pack(W, H, &bad, 1, p, err, sizeof err) == -1, "page: 1 luxel wide is refused", err);

  const ts_vec3d probes[3] = {ts_v3d(0, 0, 0), ts_v3d(10, 0, 0), ts_v3d(-10, 0, 0)};
  check(env_pick_probe(ts_v3d(7, 1, 0), probes, 3, -1, err, sizeof err) == 1, "probe: nearest");
  check(env_pick_probe(ts_v3d(5, 0, 0), probes, 3, -1, err, sizeof err) == 0, "probe: tie goes to the lowest index");
  check(env_pick_probe(ts_v3d(7, 1, 0), probes, 3, 2, err, sizeof err) == 2, "probe: explicit assignment overrides");
  check(env_pick_probe(ts_v3d(7, 1, 0), probes, 3, 3, err, sizeof err) == -1 &&
            std::string(err).find("probe 3") != std::string::npos,
        "probe: explicit index out of range is an error", err);
  check(env_pick_probe(ts_v3d(0, 0, 0), probes, 0, -1, err, sizeof err) == -1, "probe: no probe is an error", err);
}

// ---- GL: cube maps ---------------------------------------------------------------------------
// Draws the conformance program of v over `in` and counts the pixels that differ from the twin.
long mismatches_drawn(GlRenderer &r, Api api, const Variant &v, const FamilyInputs &in, std::string *err) {
  const GLuint prog = build_conform_program(r, api, v, err);
  if (!prog) return -1;
  const GlFns &g = r.gl();
  g.UseProgram(prog);
  g.Uniform2f(g.GetUniformLocation(prog, "ts_record_size"), static_cast<float>(in.w),
              static_cast<float>(in.h * in.slots));
  g.Uniform1f(g.GetUniformLocation(prog, "ts_grid_height"), static_cast<float>(in.h));
  std::vector<std::pair<std::string, GLuint>> texs = {{"ts_record", r.upload_texture(in.record_texture())}};
  for (const TextureDesc &t : in.textures) texs.push_back({t.sampler, r.upload_texture(t)});
  ImageF img;
  const bool ok = r.draw(prog, texs, in.w, in.h, &img, err);
  for (auto &t : texs) r.delete_texture(t.second);
  r.delete_program(prog);
  if (!ok) return -1;
  long bad = 0;
  for (int y = 0; y < in.h; ++y)
    for (int x = 0; x < in.w; ++x) {
      const ts_vec4f c = kWorldLightingFamily.eval_f(v, in, x, y);
      if (std::memcmp(&c, &img.rgba[(static_cast<size_t>(y) * in.w + x) * 4], sizeof c) != 0) ++bad;
    }
  return bad;
}

void check_gl_cubes() {
  Selection sel;
  std::string err;
  if (!load_shader_decls(&sel.decls, &err)) {
    check(false, "load shader declarations", err);
    return;
  }
  Variant v;
  if (!find_variant(sel.decls, "world_lighting", "sm3:BUMPMAP=1,LIGHTMAP_ENCODING=0,ENVMAP=1,ENVMAPMASK=0", &v, &err)) {
    check(false, "find the sm3 envmap variant", err);
    return;
  }
  FamilyInputs in;
  kWorldLightingFamily.make_inputs(InputSet::Random, 32, 32, 99, &in);
  for (TextureDesc &t : in.textures)
    if (t.kind == TexKind::Cube) t.linear = true;
  const BackendApi cfgs[] = {
      {Backend::OSMesa, Api::GL33}, {Backend::EGL, Api::GL33}, {Backend::EGL, Api::GLES3}, {Backend::EGL, Api::GLES2}};
  for (const BackendApi &c : cfgs) {
    auto ctx = GlContext::create(c.backend, c.api, &err);
    const std::string tag = std::string(backend_name(c.backend)) + "/" + api_name(c.api);
    if (!ctx) {
      check(false, "context " + tag, err);
      continue;
    }
    GlRenderer r(*ctx);
    if (c.api == Api::GL33) {
      ConformRun run;
      run.renderer = &r;
      run.backend = c.backend;
      run.api = c.api;
      const ConformResult res = conform_variant(run, kWorldLightingFamily, v, in, InputSet::Random);
      check(res.passed(), "LINEAR cube map, seamless off: 0 ULP on " + tag,
            res.error + " " + std::to_string(res.mismatches) + " mismatched");
      continue;
    }
    // GLES: drawn here rather than through conform_variant, which may adapt the textures.
    // Not a tolerance: a statement about Mesa. If it fails, GLES cube maps are no longer
    // seamless here and docs/world_lighting.md ("Cube maps on GLES") is out of date.
    const long bad = mismatches_drawn(r, c.api, v, in, &err);
    check(bad > 0, "GLES cube maps are seamless on this Mesa: LINEAR differs from the non-seamless twin on " + tag,
          err + " " + std::to_string(bad) + " mismatched");
    for (TextureDesc &t : in.textures)
      if (t.kind == TexKind::Cube) t.linear = false;
    const long bad_nearest = mismatches_drawn(r, c.api, v, in, &err);
    check(bad_nearest == 0, "GLES: NEAREST cube maps are bit-exact (seamless or not) on " + tag,
          err + " " + std::to_string(bad_nearest) + " mismatched");
    for (TextureDesc &t : in.textures)
      if (t.kind == TexKind::Cube) t.linear = true;
  }
}

}  // namespace

int main() {
  ts_math_init();
  check_basis();
  check_bake();
  check_twin();
  check_encodings();
  check_page();
  check_gl_cubes();
  return finish();
}

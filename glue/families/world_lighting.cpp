// tiershade families: the world_lighting family (lightmaps, radiosity normal mapping,
// cube-map specular): its input records (random and hard cases), its test textures,
// and the bridge to its C twin (c_ref/twins/world_lighting.c). The texture builders are
// shared with the demo and the benchmark through world_lighting.h.
#include "families/world_lighting.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "families/record_family.h"
#include "twins/world_lighting_batch.h"

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// The texture bound to `sampler`. Inputs without it are a programming error of the caller
// (every builder of world_lighting inputs sets all five): stop with a message, never sample garbage.
const TextureDesc &find_tex(const FamilyInputs &in, const char *sampler) {
  for (const TextureDesc &t : in.textures)
    if (t.sampler == sampler) return t;
  fprintf(stderr, "world_lighting: the inputs have no texture for sampler '%s'\n", sampler);
  abort();
}

struct TexViews {
  ts_tex2d base{}, normalmap{}, lightmap{}, mask{};
  ts_texcube envmap{};
  wl_textures t{};
  explicit TexViews(const FamilyInputs &in) {
    base = tex2d_of(find_tex(in, "u_base"));
    normalmap = tex2d_of(find_tex(in, "u_normalmap"));
    lightmap = tex2d_of(find_tex(in, "u_lightmap"));
    mask = tex2d_of(find_tex(in, "u_envmap_mask"));
    envmap = texcube_of(find_tex(in, "u_envmap"));
    t.base = &base;
    t.normalmap = &normalmap;
    t.lightmap = &lightmap;
    t.envmap_mask = &mask;
    t.envmap = &envmap;
  }
};

// Pixel (x, y)'s twin arguments: its record, the variant and the texture views (built per call).
struct PixelCall {
  ts_vec4f rec[WL_SLOTS];
  wl_variant w;
  TexViews tv;
  PixelCall(const Variant &v, const FamilyInputs &in, int x, int y) : w(wl_variant_of(v)), tv(in) {
    in.gather(x, y, WL_SLOTS, rec);
  }
};

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  const PixelCall c(v, in, x, y);
  return world_lighting_f(&c.w, c.rec, &c.tv.t);
}
ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  const PixelCall c(v, in, x, y);
  return world_lighting_d(&c.w, c.rec, &c.tv.t);
}

// The batch twin on the record texture's row (stride 1); shared slots have stride 0.
void eval_row_f(const Variant &v, const FamilyInputs &in, int x0, int y, int count, ts_vec4f *out) {
  wl_batch_input b;
  point_batch_at_row(in, x0, y, WL_SLOTS, &b);
  const wl_variant w = wl_variant_of(v);
  const TexViews tv(in);
  world_lighting_f_batch(&w, &b, &tv.t, out, count);
}

ts_vec4f v4(ts_vec3f v, float w) { return ts_v4f(v.x, v.y, v.z, w); }

// --- test textures: a regular zone that random records sample, and 2x2 blocks of
// special texels that hard records aim at (a 2x2 block sampled at its centre gives
// the block's value with LINEAR filtering too).
constexpr int kTexSize = 16;  // base, normal map, mask: 16x16, regular rows 0..7
constexpr int kPageW = 64, kPageH = 32;  // lightmap page: regular rows 0..15
constexpr int kCubeSize = 8;

void put_block(TextureDesc *t, int bx, int by, const float v[4]) {
  for (int y = by; y < by + 2; ++y)
    for (int x = bx; x < bx + 2; ++x)
      for (int c = 0; c < 4; ++c) t->rgba[(static_cast<size_t>(y) * t->w + x) * 4 + c] = v[c];
}

// Special lightmap blocks (x = 2 i, y = 16).
const float kLmSpecial[][4] = {
    {65504.f, 65504.f, 65504.f, 1.f},  // 0 largest half float
    {kInf, 1.f, 0.5f, 0.5f},  // 1 overflowed sample
    {1e30f, 2e30f, 3e30f, 0.5f},  // 2 huge float
    {1.f, 1.f, 1.f, 1.f},  // 3 RGBE: largest exponent (a = 255/255 -> e = 127); 4.12: 16
    {1.f, 1.f, 1.f, 0.f},  // 4 RGBE: smallest exponent (a = 0 -> e = -128)
    {0.f, 0.f, 0.f, 0.f},  // 5 black
    {kNaN, 0.5f, kNaN, 0.5f},  // 6 NaN
    {1e-40f, 2e-39f, 1e-45f, 0.5f},  // 7 denormals
    {0.5f / 255.f, 1.f / 255.f, 254.f / 255.f, 129.f / 255.f},  // 8 RGBE-like small mantissas
};
const int kNumLmSpecial = sizeof kLmSpecial / sizeof kLmSpecial[0];

// Special normal-map blocks (x = 2 i, y = 8).
const float kNmSpecial[][4] = {
    {0.5f, 0.5f, 0.5f, 0.5f},  // 0 zero-length normal (2 t - 1 = 0): every RNM weight 0
    {0.5f, 0.5f, 0.f, 1.f},  // 1 n = (0, 0, -1): every RNM weight 0
    {kNaN, 0.5f, 1.f, kNaN},  // 2 NaN texel (and NaN mask)
    {1e30f, -1e30f, 1e30f, 1e30f},  // 3 huge texel
    {0.5f, 0.5f, 1.f, 1.f},  // 4 n = (0, 0, 1), ssbump weights (0.5, 0.5, 1)
    {0.f, 0.f, 0.f, 0.f},  // 5 ssbump: all weights 0 (and RNM n = (-1, -1, -1))
    {0.5f * 0.816496580927726f + 0.5f, 0.5f, 0.5f * 0.577350269189626f + 0.5f, 0.f},  // 6 n = b0
};
const int kNumNmSpecial = sizeof kNmSpecial / sizeof kNmSpecial[0];

}  // namespace

wl_variant wl_variant_of(const Variant &v) {
  wl_variant w;
  w.tier = tier_id(v.tier);
  w.bumpmap = v.value("BUMPMAP");
  w.encoding = v.value("LIGHTMAP_ENCODING");
  w.envmap = v.value("ENVMAP");
  w.envmapmask = v.value("ENVMAPMASK");
  return w;
}

void wl_test_textures(Rng &r, std::vector<TextureDesc> *out) {
  TextureDesc base = blank_texture("u_base", kTexSize, kTexSize, true, true);
  for (size_t i = 0; i < base.rgba.size(); ++i) base.rgba[i] = i % 4 == 3 ? r.uniform(0, 1) : r.uniform(0.05f, 1.f);
  TextureDesc nm = blank_texture("u_normalmap", kTexSize, kTexSize, true, true);
  for (int y = 0; y < kTexSize / 2; ++y)
    for (int x = 0; x < kTexSize; ++x) {
      // Mostly outward normals (z > -0.2), stored 0.5 n + 0.5 like an 8-bit normal map.
      ts_vec3f n = r.unit_vector();
      if (n.z < -0.2f) n.z = -n.z;
      float *p = &nm.rgba[(static_cast<size_t>(y) * kTexSize + x) * 4];
      p[0] = 0.5f * n.x + 0.5f;
      p[1] = 0.5f * n.y + 0.5f;
      p[2] = 0.5f * n.z + 0.5f;
      p[3] = r.uniform(0, 1);
    }
  for (int i = 0; i < kNumNmSpecial; ++i) put_block(&nm, 2 * i, kTexSize / 2, kNmSpecial[i]);
  TextureDesc lm = blank_texture("u_lightmap", kPageW, kPageH, true, false);
  for (int y = 0; y < kPageH / 2; ++y)
    for (int x = 0; x < kPageW; ++x) {
      float *p = &lm.rgba[(static_cast<size_t>(y) * kPageW + x) * 4];
      for (int c = 0; c < 3; ++c) p[c] = r.uniform(0, 1);
      // Alpha: an RGBE exponent e in [-8, 2], stored (e + 128) / 255 (the other encodings ignore it).
      p[3] = static_cast<float>(128 - 8 + static_cast<int>(r.next() % 11)) / 255.f;
    }
  for (int i = 0; i < kNumLmSpecial; ++i) put_block(&lm, 2 * i, kPageH / 2, kLmSpecial[i]);
  TextureDesc mask = blank_texture("u_envmap_mask", kTexSize, kTexSize, true, true);
  for (float &v : mask.rgba) v = r.uniform(0, 1);
  // The cube: NEAREST, because GLES cube maps are always seamless and seamless LINEAR
  // filtering is not reproducible per pixel (docs/world_lighting.md, "Cube maps on GLES").
  TextureDesc cube = blank_texture("u_envmap", kCubeSize, kCubeSize * 6, false, false);
  cube.kind = TexKind::Cube;
  cube.h = kCubeSize;
  for (size_t i = 0; i < cube.rgba.size(); ++i) cube.rgba[i] = i % 4 == 3 ? 1.f : r.uniform(0.f, 4.f);
  // Overflowing HDR texels in the quadrant s, t < 0.5 of the -Y face (directions with x < 0, z > 0).
  const float specials[4] = {65504.f, kInf, 1e30f, kNaN};
  for (int y = 0; y < kCubeSize / 2; ++y)
    for (int x = 0; x < kCubeSize / 2; ++x) {
      float *p = &cube.rgba[((3 * static_cast<size_t>(kCubeSize) + y) * kCubeSize + x) * 4];
      for (int c = 0; c < 3; ++c) p[c] = specials[(x + y + c) % 4];
    }
  *out = {base, nm, lm, mask, cube};
}

void wl_defaults(ts_vec4f rec[WL_SLOTS]) {
  for (int k = 0; k < WL_SLOTS; ++k) rec[k] = ts_v4f(0, 0, 0, 0);
  rec[WL_SLOT_NORMAL] = ts_v4f(0, 0, 1, 0);
  rec[WL_SLOT_TANGENT] = ts_v4f(1, 0, 0, 0);
  rec[WL_SLOT_BINORMAL] = ts_v4f(0, 1, 0, 0);
  rec[WL_SLOT_EYE] = ts_v4f(0, 0, 1, 0);
  rec[WL_SLOT_TINT_SCALE] = ts_v4f(1, 1, 1, 1);
  rec[WL_SLOT_ENV_TINT] = ts_v4f(1, 1, 1, 1);
  rec[WL_SLOT_ENV_PARAMS] = ts_v4f(0, 1, 0, 1);  // contrast 0, saturation 1, R0 = 1: Source's defaults
  rec[WL_SLOT_FOG_COLOR] = ts_v4f(0, 0, 0, 0);
  rec[WL_SLOT_FOG_PARAMS] = ts_v4f(0, 0, 0, 0);
}

namespace {

void random_pixel(Rng &r, InputSet, ts_vec4f rec[WL_SLOTS]) {
  // Base/normal/mask uv: any u (wraps), v inside the regular rows of a period.
  const float period = static_cast<float>(static_cast<int>(r.next() % 3) - 1);
  rec[WL_SLOT_UV] =
      ts_v4f(r.uniform(-1, 2), period + r.uniform(0.07f, 0.43f), r.uniform(0.f, 0.6f), r.uniform(0.03f, 0.45f));
  rec[WL_SLOT_LM_OFFSET] = ts_v4f(r.uniform(0.f, 0.12f), r.uniform(-0.01f, 0.01f), r.uniform(0.f, 400.f), 0.f);
  // A random, roughly orthonormal frame, scaled like interpolated vectors are.
  const ts_vec3f n = r.unit_vector();
  ts_vec3f t = r.unit_vector();
  t = ts_normalize3f(ts_sub3f(t, ts_scale3f(n, ts_dot3f(n, t))));
  const glm::vec3 g = glm::cross(glm::vec3(n.x, n.y, n.z), glm::vec3(t.x, t.y, t.z));  // bit-equal to n x t written out
  const ts_vec3f b = ts_v3f(g.x, g.y, g.z);
  rec[WL_SLOT_NORMAL] = v4(ts_scale3f(n, r.uniform(0.8f, 1.2f)), 0);
  rec[WL_SLOT_TANGENT] = v4(ts_scale3f(t, r.uniform(0.8f, 1.2f)), 0);
  rec[WL_SLOT_BINORMAL] = v4(ts_scale3f(b, r.uniform(0.8f, 1.2f)), 0);
  rec[WL_SLOT_EYE] = v4(ts_scale3f(r.unit_vector(), r.uniform(0.1f, 50.f)), 0);
  rec[WL_SLOT_TINT_SCALE] =
      ts_v4f(r.uniform(0.5f, 2.f), r.uniform(0.5f, 2.f), r.uniform(0.5f, 2.f), r.uniform(0.25f, 4.f));
  rec[WL_SLOT_ENV_TINT] = ts_v4f(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), r.uniform(0.5f, 16.f));
  // Half of the pixels at Source's defaults (sm3's fast path), half anywhere in range.
  if (r.next() % 2)
    rec[WL_SLOT_ENV_PARAMS] = ts_v4f(0, 1, 0, 1);
  else {
    const float r0 = r.uniform(0, 1);
    rec[WL_SLOT_ENV_PARAMS] = ts_v4f(r.uniform(0, 1), r.uniform(0, 1.5f), 1.f - r0, r0);
  }
  rec[WL_SLOT_FOG_COLOR] = ts_v4f(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), r.uniform(0.3f, 1.f));
  const float start = r.uniform(0, 200), range = r.uniform(50, 400);
  rec[WL_SLOT_FOG_PARAMS] = ts_v4f(1.f / range, start / range, 0, 0);
}

// The conformance textures, drawn after the records (and the hard cases of
// tests/conform/world_lighting.cases, aimed at the special blocks above).
void test_textures(Rng &r, InputSet, FamilyInputs *out) { wl_test_textures(r, &out->textures); }

// The record layout: shaders/world_lighting_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/world_lighting_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"world_lighting",     WL_SLOTS,         WL_PIXEL_SLOTS, kSlotRows,
                                  std::size(kSlotRows), output_range_half};

}  // namespace

void wl_bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_layout_uniforms<kLayout>(gl, program, shared);
}

const ShaderFamily kWorldLightingFamily =
    family_of<kLayout>(record_inputs<kLayout, random_pixel, test_textures>, eval_f, eval_d, eval_row_f);
static const FamilyRegistrar kRegister(&kWorldLightingFamily);

// tiershade families: the model_lighting family: input records (random and hard
// cases), and the bridge to its C twin (c_ref/twins/model_lighting.c).
#include <cmath>
#include <memory>

#include "families/model_lighting.h"
#include "families/slot_table.h"
#include "families/family.h"
#include "families/hard_cases.h"
#include "twins/model_lighting.h"
#include "twins/model_lighting_batch.h"

namespace {

// The C views of the family's textures, in make_inputs' order.
enum { TEX_ALBEDO, TEX_NORMAL, TEX_EXPONENT, TEX_WARP, TEX_ENVMAP, TEX_COUNT };
struct Views {
  ts_tex2d t2[4];
  ts_texcube cube;
  ml_textures tex;
  explicit Views(const FamilyInputs &in) {
    for (int i = 0; i < 4; ++i) t2[i] = tex2d_of(in.textures.at(i));
    cube = texcube_of(in.textures.at(TEX_ENVMAP));
    tex = {&t2[TEX_ALBEDO], &t2[TEX_NORMAL], &t2[TEX_EXPONENT], &t2[TEX_WARP], &cube};
  }
};

void gather(const FamilyInputs &in, int x, int y, ts_vec4f rec[ML_SLOTS]) {
  for (int k = 0; k < ML_SLOTS; ++k) rec[k] = in.slot(x, y, k);
}

// ml_variant_of looks combos up by name: cache it per thread for the frame's variant.
const ml_variant &cached_ml(const Variant &v) {
  thread_local Tier last_tier = Tier::SM3;
  thread_local std::vector<std::pair<std::string, int>> last_values;
  thread_local bool valid = false;
  thread_local ml_variant m;
  if (!valid || last_tier != v.tier || last_values != v.values) {
    m = ml_variant_of(v);
    last_tier = v.tier;
    last_values = v.values;
    valid = true;
  }
  return m;
}

// The texture views, rebuilt only when the frame's textures change (per thread).
const ml_textures &cached_views(const FamilyInputs &in) {
  thread_local const float *key[TEX_COUNT] = {};
  thread_local std::unique_ptr<Views> views;
  bool same = views != nullptr && in.textures.size() == TEX_COUNT;
  for (int i = 0; same && i < TEX_COUNT; ++i) same = key[i] == in.textures[i].rgba.data();
  if (!same) {
    views.reset(new Views(in));
    for (int i = 0; i < TEX_COUNT; ++i) key[i] = in.textures.at(i).rgba.data();
  }
  return views->tex;
}

ts_vec4f eval_f(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[ML_SLOTS];
  gather(in, x, y, rec);
  return model_lighting_f(&cached_ml(v), rec, &cached_views(in));
}

// The batch twin straight on the record texture: slot k of pixels (x0.., y) is a run of
// texels (stride 1); slots past in.slots are the frame's shared ones (stride 0).
void eval_row_f(const Variant &v, const FamilyInputs &in, int x0, int y, int count, ts_vec4f *out) {
  ml_batch_input b;
  point_batch_at_row(in, x0, y, ML_SLOTS, &b);
  model_lighting_f_batch(&cached_ml(v), &b, &cached_views(in), out, count);
}

ts_vec4d eval_d(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[ML_SLOTS];
  gather(in, x, y, rec);
  return model_lighting_d(&cached_ml(v), rec, &cached_views(in));
}

void output_range(const Variant &v, float *lo, float *hi) {
  *lo = 0.f;
  *hi = v.value("OUTPUT_MODE") == 0 ? 65504.f : 1.f;
}

ts_vec4f v4(ts_vec3f v, float w) { return ts_v4f(v.x, v.y, v.z, w); }

// A well-conditioned random light of a random type (point, spot, directional).
void random_light(Rng &r, ts_vec4f l[5]) {
  const int type = static_cast<int>(r.next() % 3);  // 0 point, 1 spot, 2 directional
  const ts_vec3f dir = r.unit_vector();
  l[0] = ts_v4f(r.uniform(0, 4), r.uniform(0, 4), r.uniform(0, 4), type == 2 ? 1.f : 0.f);
  l[1] = v4(dir, type == 1 ? 1.f : 0.f);
  l[2] = ts_v4f(r.uniform(-4, 4), r.uniform(-4, 4), r.uniform(-4, 4), 1.f);
  const float cos_outer = r.uniform(0.3f, 0.95f);
  const float cos_inner = std::fmin(1.f, cos_outer + r.uniform(0.02f, 0.3f));
  l[3] = ts_v4f(r.uniform(0.5f, 8.f), 0.f, cos_outer, 1.0f / (cos_inner - cos_outer));
  l[4] = type == 2 ? ts_v4f(1, 0, 0, 0) : ts_v4f(r.uniform(0.05f, 1.f), r.uniform(0, 0.5f), r.uniform(0, 0.5f), 0);
}

void random_pixel(Rng &r, ts_vec4f rec[ML_SLOTS]) {
  rec[ML_SLOT_NORMAL] = v4(ts_scale3f(r.unit_vector(), r.uniform(0.2f, 3.f)), 0.f);
  rec[ML_SLOT_POSITION] = ts_v4f(r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2), 1.f);
  rec[ML_SLOT_UV] = ts_v4f(r.uniform(-1, 2), r.uniform(-1, 2), 0, 0);
  rec[ML_SLOT_VERTEX_ATTEN] = ts_v4f(r.uniform(0, 2), r.uniform(0, 2), r.uniform(0, 2), r.uniform(0, 2));
  // A tangent frame around the interpolated normal (not exactly orthonormal, as interpolated).
  const ts_vec3f n = ts_normalize3f(ts_v3f(rec[ML_SLOT_NORMAL].x, rec[ML_SLOT_NORMAL].y, rec[ML_SLOT_NORMAL].z));
  const ts_vec3f a = std::fabs(n.x) < 0.9f ? ts_v3f(1, 0, 0) : ts_v3f(0, 1, 0);
  const ts_vec3f t = ts_normalize3f(ts_sub3f(a, ts_scale3f(n, ts_dot3f(a, n))));
  const ts_vec3f b = ts_v3f(n.y * t.z - n.z * t.y, n.z * t.x - n.x * t.z, n.x * t.y - n.y * t.x);
  rec[ML_SLOT_TANGENT] = v4(ts_scale3f(t, r.uniform(0.8f, 1.2f)), 0.f);
  rec[ML_SLOT_BITANGENT] = v4(ts_scale3f(b, r.uniform(0.8f, 1.2f)), 0.f);
  rec[ML_SLOT_EYE] = ts_v4f(r.uniform(-6, 6), r.uniform(-6, 6), r.uniform(-6, 6), 1.f);
  rec[ML_SLOT_PHONG] = ts_v4f(r.uniform(1, 150), r.uniform(0, 200), r.uniform(0, 4), (r.next() & 1) ? 1.f : 0.f);
  const float fmin = r.uniform(0, 1), fmid = r.uniform(0, 1), fmax = r.uniform(0, 1);
  rec[ML_SLOT_FRESNEL] = ts_v4f((fmid - fmin) * 2.f, fmid, (fmax - fmid) * 2.f, (r.next() % 4 == 0) ? 1.f : 0.f);
  rec[ML_SLOT_PHONG_TINT] = ts_v4f(r.uniform(0, 2), r.uniform(0, 2), r.uniform(0, 2), (r.next() & 1) ? 1.f : 0.f);
  rec[ML_SLOT_RIM] = ts_v4f(r.uniform(1, 16), r.uniform(0, 4), r.uniform(0, 1), 0.f);
  rec[ML_SLOT_ENVMAP] = ts_v4f(r.uniform(0, 2), r.uniform(0, 1), (r.next() & 1) ? 1.f : 0.f, 0.f);
  rec[ML_SLOT_ENVMAP_TINT] = ts_v4f(r.uniform(0, 2), r.uniform(0, 2), r.uniform(0, 2), 0.f);
  rec[ML_SLOT_SELF_ILLUM] =
      ts_v4f(r.uniform(0, 2), r.uniform(0, 2), r.uniform(0, 2), (r.next() & 1) ? r.uniform(0, 1) : 0.f);
  for (int k = 0; k < 6; ++k) rec[ML_SLOT_AMBIENT + k] = ts_v4f(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), 0);
  rec[ML_SLOT_PARAMS] = ts_v4f(r.uniform(0.25f, 4.f), static_cast<float>(r.next() % 5), 0, 0);
  rec[ML_SLOT_ALBEDO] = ts_v4f(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), 1);
  for (int i = 0; i < ML_MAX_LIGHTS; ++i) random_light(r, &rec[ML_SLOT_LIGHT0 + 5 * i]);
}

void make_inputs(InputSet set, int w, int h, uint32_t seed, FamilyInputs *out) {
  Rng r(seed);
  // The hard cases: tests/conform/model_lighting.cases.
  fill_record_grid(
      "model_lighting", set, w, h, ML_SLOTS, r, [&](ts_vec4f *rec) { random_pixel(r, rec); }, out);
  // Textures: RGBA32F, bilinear (RGBA8 would take llvmpipe's 8-bit fixed-point
  // filtering path: platform notes section 4). Order: enum TEX_*.
  auto tex2d = [&](const char *name, int w, int h, bool repeat) {
    TextureDesc t;
    t.sampler = name;
    t.w = w;
    t.h = h;
    t.linear = true;
    t.repeat = repeat;
    t.rgba.resize(static_cast<size_t>(w) * h * 4);
    return t;
  };
  auto texel = [](TextureDesc &t, int x, int y) { return &t.rgba[(static_cast<size_t>(y) * t.w + x) * 4]; };
  TextureDesc albedo = tex2d("u_albedo", 16, 16, true);
  for (float &v : albedo.rgba) v = r.uniform(0.05f, 1.f);
  TextureDesc nmap = tex2d("u_normal_map", 16, 16, true);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const ts_vec3f d = r.unit_vector();
      float *p = texel(nmap, x, y);
      p[0] = 0.5f + 0.5f * d.x;
      p[1] = 0.5f + 0.5f * d.y;
      p[2] = 0.5f + 0.5f * std::fabs(d.z);
      p[3] = r.uniform(0, 1);
    }
  TextureDesc expmap = tex2d("u_exponent_map", 16, 16, true);
  for (float &v : expmap.rgba) v = r.uniform(0, 1);
  // Hard-case blocks (tests/conform/model_lighting.cases): texels (0..1, 0..1) of the normal map are grey, so
  // they decode to a zero vector; texels (2..3, 0..1) are a flat (0.5, 0.5, 1) normal
  // with exponent-map r = 1 (exponent 150).
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      float *p = texel(nmap, x, y);
      p[0] = p[1] = 0.5f;
      p[2] = x < 2 ? 0.5f : 1.f;
      if (x >= 2) texel(expmap, x, y)[0] = 1.f;
    }
  TextureDesc warp = tex2d("u_light_warp", 32, 1, false);
  for (float &v : warp.rgba) v = r.uniform(0, 1);
  TextureDesc env;
  env.sampler = "u_envmap";
  env.kind = TexKind::Cube;
  env.w = env.h = 8;
  env.linear = true;
  env.rgba.resize(6 * 8 * 8 * 4);
  for (float &v : env.rgba) v = r.uniform(0, 4);
  out->textures = {albedo, nmap, expmap, warp, env};
}

// The record layout: shaders/model_lighting_slots.glsl, the one table (slot_table.h).
#define TS_SLOT TS_SLOT_ROW
constexpr SlotRow kSlotRows[] = {
#include "../../shaders/model_lighting_slots.glsl"
};
#undef TS_SLOT
static_assert(slot_rows_valid(kSlotRows, ML_SLOTS, ML_PIXEL_SLOTS), "shaders/model_lighting_slots.glsl: bad rows");

std::vector<std::string> slot_names() { return slot_names_of(kSlotRows); }

void bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_slot_uniforms(gl, program, shared, kSlotRows, ML_PIXEL_SLOTS);
}

}  // namespace

ml_variant ml_variant_of(const Variant &v) {
  ml_variant m = {};
  m.tier = tier_id(v.tier);
  m.albedo_texture = v.value("ALBEDO_TEXTURE");
  m.half_lambert = v.value("HALF_LAMBERT");
  m.output_mode = v.value("OUTPUT_MODE");
  m.num_lights = v.value("NUM_LIGHTS");
  m.phong = v.value("PHONG");
  m.exponent_map = v.value("PHONG_EXPONENT_MAP");
  m.rim_light = v.value("RIM_LIGHT");
  m.envmap = v.value("ENVMAP");
  m.light_warp = v.value("LIGHT_WARP");
  return m;
}

const ShaderFamily kModelLightingFamily = {
    "model_lighting", ML_SLOTS,     slot_names(),   make_inputs,   eval_f,
    eval_d,           output_range, ML_PIXEL_SLOTS, bind_uniforms, eval_row_f,
};
const FamilyRegistrar kRegister(&kModelLightingFamily);

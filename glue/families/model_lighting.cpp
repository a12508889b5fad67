// tiershade families: the model_lighting family: input records (random and hard
// cases), and the bridge to its C twin (c_ref/twins/model_lighting.c).
#include <cmath>
#include <iterator>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "families/model_lighting.h"
#include "families/record_family.h"
#include "twins/model_lighting.h"
#include "twins/model_lighting_batch.h"

namespace {

// The record layout: shaders/model_lighting_slots.glsl, the one table (slot_table.h).
#define TS_SLOT_FILE "../../shaders/model_lighting_slots.glsl"
#include "families/slot_rows.inc"
constexpr RecordLayout kLayout = {"model_lighting",           ML_SLOTS, ML_PIXEL_SLOTS, kSlotRows, std::size(kSlotRows),
                                  output_range_by_output_mode};

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
  thread_local const float *key[ML_TEX_COUNT] = {};
  thread_local std::unique_ptr<MlTextureViews> views;
  bool same = views != nullptr && in.textures.size() == ML_TEX_COUNT;
  for (int i = 0; same && i < ML_TEX_COUNT; ++i) same = key[i] == in.textures[i].rgba.data();
  if (!same) {
    views.reset(new MlTextureViews(in));
    for (int i = 0; i < ML_TEX_COUNT; ++i) key[i] = in.textures.at(i).rgba.data();
  }
  return views->tex;
}

// The batch twin straight on the record texture: slot k of pixels (x0.., y) is a run of
// texels (stride 1); slots past in.slots are the frame's shared ones (stride 0).
void eval_row_f(const Variant &v, const FamilyInputs &in, int x0, int y, int count, ts_vec4f *out) {
  ml_batch_input b;
  point_batch_at_row(in, x0, y, ML_SLOTS, &b);
  model_lighting_f_batch(&cached_ml(v), &b, &cached_views(in), out, count);
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

void random_pixel(Rng &r, InputSet, ts_vec4f rec[ML_SLOTS]) {
  rec[ML_SLOT_NORMAL] = v4(ts_scale3f(r.unit_vector(), r.uniform(0.2f, 3.f)), 0.f);
  rec[ML_SLOT_POSITION] = ts_v4f(r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2), 1.f);
  rec[ML_SLOT_UV] = ts_v4f(r.uniform(-1, 2), r.uniform(-1, 2), 0, 0);
  rec[ML_SLOT_VERTEX_ATTEN] = ts_v4f(r.uniform(0, 2), r.uniform(0, 2), r.uniform(0, 2), r.uniform(0, 2));
  // A tangent frame around the interpolated normal (not exactly orthonormal, as interpolated).
  const ts_vec3f n = ts_normalize3f(ts_v3f(rec[ML_SLOT_NORMAL].x, rec[ML_SLOT_NORMAL].y, rec[ML_SLOT_NORMAL].z));
  const ts_vec3f a = std::fabs(n.x) < 0.9f ? ts_v3f(1, 0, 0) : ts_v3f(0, 1, 0);
  const ts_vec3f t = ts_normalize3f(ts_sub3f(a, ts_scale3f(n, ts_dot3f(a, n))));
  const glm::vec3 g = glm::cross(glm::vec3(n.x, n.y, n.z), glm::vec3(t.x, t.y, t.z));  // bit-equal to n x t written out
  const ts_vec3f b = ts_v3f(g.x, g.y, g.z);
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

// Textures: RGBA32F, bilinear (RGBA8 would take llvmpipe's 8-bit fixed-point filtering path:
// platform notes section 4), drawn after the records (and the hard cases of
// tests/conform/model_lighting.cases). Order: enum ml_texture_index.
void random_textures(Rng &r, InputSet, FamilyInputs *out) {
  auto texel = [](TextureDesc &t, int x, int y) { return &t.rgba[(static_cast<size_t>(y) * t.w + x) * 4]; };
  TextureDesc albedo = blank_texture("u_albedo", 16, 16, true, true);
  for (float &v : albedo.rgba) v = r.uniform(0.05f, 1.f);
  TextureDesc nmap = blank_texture("u_normal_map", 16, 16, true, true);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const ts_vec3f d = r.unit_vector();
      float *p = texel(nmap, x, y);
      p[0] = 0.5f + 0.5f * d.x;
      p[1] = 0.5f + 0.5f * d.y;
      p[2] = 0.5f + 0.5f * std::fabs(d.z);
      p[3] = r.uniform(0, 1);
    }
  TextureDesc expmap = blank_texture("u_exponent_map", 16, 16, true, true);
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
  TextureDesc warp = blank_texture("u_light_warp", 32, 1, true, false);
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

}  // namespace

MlTextureViews::MlTextureViews(const FamilyInputs &in) {
  for (int i = 0; i < 4; ++i) t2[i] = tex2d_of(in.textures.at(i));
  cube = texcube_of(in.textures.at(ML_TEX_ENVMAP));
  tex = {&t2[ML_TEX_ALBEDO], &t2[ML_TEX_NORMAL], &t2[ML_TEX_EXPONENT], &t2[ML_TEX_WARP], &cube, nullptr, 0};
}

void ml_pack_lights(const ts_vec4f *lights, int n, ts_vec4f *out) {
  for (int i = 0; i < n; ++i) {
    const ts_vec4f *l = lights + 5 * i;  // color, dir, pos, spot, atten
    // The flags as the shader tests them (> 0.5): (directional ? 1 : -1) * (spot ? 2 : 1).
    const float flags = (l[0].w > 0.5f ? 1.f : -1.f) * (l[1].w > 0.5f ? 2.f : 1.f);
    out[4 * i + 0] = ts_v4f(l[0].x, l[0].y, l[0].z, l[4].x);
    out[4 * i + 1] = ts_v4f(l[1].x, l[1].y, l[1].z, flags);
    out[4 * i + 2] = ts_v4f(l[2].x, l[2].y, l[2].z, l[4].y);
    out[4 * i + 3] = ts_v4f(l[3].x, l[4].z, l[3].z, l[3].w);
  }
}

namespace {

// The production uniforms of the slot table, and, where the fragment program packs its lights
// (ps20, ps2b: u_light_pack), the record's lights packed for it (ml_pack_lights).
void ml_bind_uniforms(const GlFns &gl, GLuint program, const std::vector<ts_vec4f> &shared) {
  bind_layout_uniforms<kLayout>(gl, program, shared);
  const GLint loc = gl.GetUniformLocation(program, "u_light_pack");
  if (loc < 0) return;
  (void)shared.at(ML_SLOT_LIGHT0 + 5 * ML_MAX_LIGHTS - 1);  // std::out_of_range for a short record
  ts_vec4f pack[4 * ML_MAX_LIGHTS];
  ml_pack_lights(&shared[ML_SLOT_LIGHT0], ML_MAX_LIGHTS, pack);
  // As bind_slot_uniforms: elements past the program's array (ps20 declares 2 lights) are ignored.
  gl.Uniform4fv(loc, 4 * ML_MAX_LIGHTS, &pack[0].x);
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

const ShaderFamily kModelLightingFamily = [] {
  ShaderFamily f = family_of<kLayout>(record_inputs<kLayout, random_pixel, random_textures>,
                                      eval_twin<kLayout, cached_ml, cached_views, model_lighting_f>,
                                      eval_twin<kLayout, cached_ml, cached_views, model_lighting_d>, eval_row_f);
  f.bind_uniforms = ml_bind_uniforms;
  return f;
}();
const FamilyRegistrar kRegister(&kModelLightingFamily);

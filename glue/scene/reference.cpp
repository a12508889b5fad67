// tiershade scene: the double-precision reference of a scene frame (reference.h): every light local on
// model draws, the float32 page on world draws.
#include "scene/reference.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "base/parallel_rows.h"
#include "families/family.h"
#include "families/model_lighting.h"
#include "families/world_lighting.h"
#include "twins/model_lighting.h"
#include "twins/world_lighting.h"

bool scene_reference_linear(const Scene &s, const PreparedScene &p, const std::vector<int> &draw,
                            const std::vector<float> &slots, std::vector<double> *rgb, std::string *err, int threads) {
  const size_t n = static_cast<size_t>(p.w) * p.h;
  if (draw.size() != n || slots.size() != n * 24) {
    *err = s.path + ": reference: the G-buffer is not " + std::to_string(p.w) + "x" + std::to_string(p.h);
    return false;
  }
  // The scene's lights packed once, in groups of ML_MAX_LIGHTS.
  std::vector<std::array<ts_vec4f, 5>> packed;
  for (const SceneLight &l : s.lights) {
    float pk[5][4];
    char msg[200];
    if (!ts_light_pack(&l.light, pk, msg, sizeof msg)) {
      *err = s.path + ": " + l.name + ": " + msg;
      return false;
    }
    std::array<ts_vec4f, 5> a;
    for (int k = 0; k < 5; ++k) a[k] = ts_v4f(pk[k][0], pk[k][1], pk[k][2], pk[k][3]);
    packed.push_back(a);
  }
  // Per draw: its variant at sm3, linear output, and its texture views.
  // World draws: their variant at sm3 reading the float32 page (LIGHTMAP_ENCODING 0, unquantised).
  struct Ctx {
    ml_variant v;
    wl_variant wv;
    ts_tex2d t2[4];
    ts_texcube cube;
    ts_tex2d page;  // world: its page of the float32 pages
    ml_textures tex;
    wl_textures wt;
  };
  TextureDesc page32;
  ts_tex2d page32_view{};
  if (!p.lightmap_page.empty()) {
    page32 = blank_texture("u_lightmap", p.lightmap_w, p.lightmap_h, true, false);
    page32.rgba = p.lightmap_page;
    page32_view = tex2d_of(page32);
  }
  std::vector<Ctx> ctx(p.draws.size());
  for (size_t i = 0; i < p.draws.size(); ++i) {
    const PreparedDraw &d = p.draws[i];
    Ctx &c = ctx[i];
    for (int k = 0; k < 4; ++k) c.t2[k] = tex2d_of(p.texture(d, k));
    c.cube = texcube_of(p.texture(d, 4));
    if (d.world) {
      c.wv = wl_variant_of(*d.variant);
      c.wv.tier = TS_TIER_ID_SM3;
      c.wv.encoding = WL_LM_FLOAT;
      c.page = page32_view;  // the draw's page: its rows of the stacked pages
      c.page.h = p.lightmap_h / std::max(1, p.lightmap_pages);
      c.page.texels += static_cast<size_t>(d.lightmap_page) * c.page.h * p.lightmap_w * 4;
      c.wt = {&c.t2[0], &c.t2[1], &c.page, &c.t2[3], &c.cube, nullptr, 0};
      continue;
    }
    c.v = ml_variant_of(*d.variant);
    c.v.tier = TS_TIER_ID_SM3;
    c.v.output_mode = 0;
    c.tex = {&c.t2[0], &c.t2[1], &c.t2[2], &c.t2[3], &c.cube, nullptr, 0};
  }
  const int nl = static_cast<int>(packed.size());
  rgb->assign(n * 3, 0.0);
  parallel_rows(p.h, threads, [&](int y) {
    ts_vec4f rec[ML_SLOTS];
    for (int x = 0; x < p.w; ++x) {
      const size_t q = static_cast<size_t>(y) * p.w + x;
      if (draw[q] < 0) continue;
      const PreparedDraw &d = p.draws[static_cast<size_t>(draw[q])];
      const Ctx &c = ctx[static_cast<size_t>(draw[q])];
      if (d.world) {  // the lights are in the page: one evaluation
        ts_vec4f wrec[WL_SLOTS];
        std::copy(d.shared.begin(), d.shared.begin() + WL_SLOTS, wrec);
        std::memcpy(wrec, &slots[q * 24], 24 * sizeof(float));
        const ts_vec4d r = world_lighting_d(&c.wv, wrec, &c.wt);
        (*rgb)[q * 3 + 0] = r.x;
        (*rgb)[q * 3 + 1] = r.y;
        (*rgb)[q * 3 + 2] = r.z;
        continue;
      }
      std::copy(d.shared.begin(), d.shared.begin() + ML_SLOTS, rec);
      std::memcpy(rec, &slots[q * 24], 24 * sizeof(float));  // the pixel slots come first
      double sum[3] = {0, 0, 0};
      for (int first = 0; first < std::max(nl, 1); first += static_cast<int>(ML_MAX_LIGHTS)) {
        const int count = std::min(static_cast<int>(ML_MAX_LIGHTS), nl - first);
        for (int f = 0; f < 6; ++f)
          rec[ML_SLOT_AMBIENT + f] =
              first == 0 ? ts_v4f(d.ambient[f][0], d.ambient[f][1], d.ambient[f][2], 0) : ts_v4f(0, 0, 0, 0);
        rec[ML_SLOT_PARAMS] = ts_v4f(p.tone_map_scale, static_cast<float>(std::max(count, 0)), 0, 0);
        for (int i = 0; i < count; ++i)
          for (int k = 0; k < 5; ++k) rec[ML_SLOT_LIGHT0 + 5 * i + k] = packed[first + i][k];
        const ts_vec4d r = model_lighting_d(&c.v, rec, &c.tex);
        sum[0] += r.x;
        sum[1] += r.y;
        sum[2] += r.z;
      }
      for (int k = 0; k < 3; ++k) (*rgb)[q * 3 + k] = sum[k];
    }
  });
  return true;
}

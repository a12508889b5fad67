// tiershade scene: derives the variants a scene needs (glue/scene/selection.h): per primitive the
// combo values its material, the scene's lights and probes and the tier call for, each with
// the reason, then the unique variants. Combo meanings: shaders/model_lighting.variants and
// shaders/world_lighting.variants; Source key meanings: docs/scenes.md.
#include "scene/selection.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace {

const ShaderDecl *find_decl(const std::vector<ShaderDecl> &decls, const std::string &name) {
  for (const auto &d : decls)
    if (d.name == name) return &d;
  return nullptr;
}

// Is an image one value everywhere (within 1/4096 per channel)? Then sampling it is a constant.
bool image_constant(const SceneImage &im, float *value) {
  if (im.rgba.empty()) return false;
  const float *p0 = im.rgba.data();
  for (size_t i = 0; i < im.rgba.size(); i += 4)
    for (int c = 0; c < 4; ++c)
      if (std::fabs(im.rgba[i + c] - p0[c]) > 1.f / 4096.f) return false;
  *value = p0[0];
  return true;
}

const char *yes(bool b) { return b ? "1" : "0"; }

struct Wanted {
  std::vector<std::pair<std::string, int>> values;
  std::vector<std::string> why;
  void set(const std::string &k, int v, const std::string &reason) {
    values.emplace_back(k, v);
    why.push_back(k + "=" + std::to_string(v) + ": " + reason);
  }
};

// The variant of the tier whose combo values equal `w` (combos not in w must be 0).
const Variant *match(const std::vector<Variant> &all, const ShaderDecl *d, Tier tier, const Wanted &w) {
  for (const Variant &v : all) {
    if (v.shader != d || v.tier != tier) continue;
    bool ok = true;
    for (const auto &kv : v.values) {
      int want = 0;
      for (const auto &ww : w.values)
        if (ww.first == kv.first) want = ww.second;
      if (kv.second != want) ok = false;
    }
    if (ok) return &v;
  }
  return nullptr;
}

void model_choice(const Scene &s, const ScenePrimitive &p, const SceneMaterial &m, Tier tier, bool float_path,
                  Wanted *w, SceneDrawChoice *c) {
  const bool sm2b = tier != Tier::PS20;
  // Self-illumination is computed in the shader's Phong path only (model_lighting.fs): a
  // $selfillum material without $phong takes that path with the specular term off.
  const bool phong_for_self_illum = sm2b && !m.phong && m.self_illum;
  const bool phong = sm2b && (m.phong || phong_for_self_illum);
  const bool has_probe = !s.probes.empty();
  const bool textured = m.base_texture.image >= 0;
  if (phong)
    w->set("ALBEDO_TEXTURE", 1,
           textured ? "base colour texture" : "Phong needs a texture: a 1x1 one of the base colour");
  else
    w->set("ALBEDO_TEXTURE", textured ? 1 : 0,
           textured ? "base colour texture" : "no base colour texture: constant colour");
  if (phong)
    w->set("HALF_LAMBERT", 1, "Phong forces half-Lambert (as Source's skin shader)");
  else
    w->set("HALF_LAMBERT", m.half_lambert ? 1 : 0, m.half_lambert ? "$halflambert" : "$halflambert 0: Lambert");
  int out_mode = 0;
  std::string out_why;
  if (float_path) {
    out_why = "float HDR path: linear radiance to the fp16 target, tone mapped later";
  } else if (tier == Tier::PS20) {
    out_why = "integer HDR path on ps20: linear out, the sRGB target encodes";
  } else {
    out_mode = 2;
    out_why = "integer HDR path: tone-map scale and exact sRGB in the shader";
  }
  w->set("OUTPUT_MODE", out_mode, out_why);
  if (sm2b) {
    w->set("PHONG", phong ? 1 : 0,
           m.phong
               ? "$phong"
               : (phong_for_self_illum ? "$selfillum lives in the Phong path: Phong with $phongboost 0" : "no $phong"));
    if (phong) {
      w->set(
          "PHONG_EXPONENT_MAP", m.phong_exponent_texture.image >= 0 ? 1 : 0,
          m.phong_exponent_texture.image >= 0 ? "$phongexponenttexture" : "constant $phongexponent: no exponent fetch");
      w->set("RIM_LIGHT", m.rim_light ? 1 : 0, m.rim_light ? "$rimlight" : "no $rimlight");
      const bool env = m.envmap && has_probe;
      w->set(
          "ENVMAP", env ? 1 : 0,
          env ? "$envmap with a probe" : (m.envmap ? "$envmap but the scene has no probe: no cube map" : "no $envmap"));
      w->set("LIGHT_WARP", m.light_warp_texture.image >= 0 ? 1 : 0,
             m.light_warp_texture.image >= 0 ? "$lightwarptexture" : "no $lightwarptexture");
      if (env) c->probe = 0;  // resolved to the nearest probe by the renderer (scene_render.cpp)
    }
  } else if (m.phong) {
    c->why.push_back("$phong dropped: ps20 has no Phong (talk: Phong is an Episode One ps_2_b feature)");
  } else if (m.self_illum) {
    c->why.push_back("$selfillum dropped: ps20 has no Phong path, where self-illumination is computed");
  }
  const int n = static_cast<int>(s.lights.size());
  const int local = std::min(n, max_local_lights(tier));
  c->lights_local = local;
  c->lights_folded = n - local;
  const std::string fold = n > local ? ", " + std::to_string(n - local) + " folded into the ambient cube" : "";
  if (tier == Tier::SM3)
    c->why.push_back("light count " + std::to_string(local) + " as a uniform (sm3 loops)" + fold);
  else
    w->set("NUM_LIGHTS", local,
           std::to_string(n) + " scene lights, tier limit " + std::to_string(max_local_lights(tier)) + fold);
  (void)p;
}

void world_choice(const Scene &s, const SceneMaterial &m, Wanted *w, SceneDrawChoice *c) {
  const bool bump = m.normal_texture.image >= 0;
  w->set("BUMPMAP", bump ? (m.ssbump ? 2 : 1) : 0,
         bump ? (m.ssbump ? "$ssbump: self-shadowed bump weights" : "$bumpmap: radiosity normal mapping")
              : "no $bumpmap: the flat lightmap alone, no RNM");
  static const char *kEnc[] = {"float", "412", "ldr", "rgbe"};
  int enc = 3;
  for (int i = 0; i < 4; ++i)
    if (s.lightmaps.encoding == kEnc[i]) enc = i;
  if (s.lightmaps.encoding == "float32") enc = 0;  // the float path, fed the unquantised page
  // "rgbe": stored RGBE, decoded at load to fp16 and sampled LINEAR (Source's run-time 16-bit format, fact
  // sheet section 2): the float path; "rgbe_shader": RGBE texels decoded in the shader, NEAREST.
  if (s.lightmaps.encoding == "rgbe") enc = 0;
  if (s.lightmaps.encoding == "rgbe_shader") enc = 3;
  w->set("LIGHTMAP_ENCODING", enc, "the scene's lightmap encoding \"" + s.lightmaps.encoding + "\"");
  const bool env = m.envmap && !s.probes.empty();
  w->set("ENVMAP", env ? 1 : 0,
         env ? "$envmap with a probe" : (m.envmap ? "$envmap but the scene has no probe: no cube map" : "no $envmap"));
  int mask = 0;
  std::string why = "no envmap mask";
  if (env) {
    switch (m.envmap_mask) {
      case SceneEnvMask::None:
        break;
      case SceneEnvMask::Texture: {
        float v = 1.f;
        const int im = m.envmap_mask_texture.image;
        if (im >= 0 && im < static_cast<int>(s.images.size()) && image_constant(s.images[im], &v)) {
          c->mask_constant = true;
          c->mask_value = v;
          why = "$envmapmask is constant (" + std::to_string(v) + "): folded into the tint, no mask fetch";
        } else {
          mask = 1;
          why = "$envmapmask texture";
        }
        break;
      }
      case SceneEnvMask::NormalAlpha:
        if (bump) {
          mask = 2;
          why = "$normalmapalphaenvmapmask";
        } else {
          why = "$normalmapalphaenvmapmask without a normal map: unmasked";
        }
        break;
      case SceneEnvMask::InvBaseAlpha:
        mask = 3;
        why = "$basealphaenvmapmask";
        break;
    }
    if (mask > 1 && enc != 0) {
      c->why.push_back("alpha envmap masks need the float lightmap encoding (world_lighting.variants): unmasked");
      mask = 0;
    }
    c->probe = 0;
  }
  w->set("ENVMAPMASK", mask, why);
}

}  // namespace

bool select_scene_variants(const Scene &s, Tier tier, const std::string &hdr_path_in, SceneSelection *out,
                           std::string *err, bool all_features) {
  SceneSelection sel;
  if (!load_shader_decls(&sel.decls, err)) return false;
  sel.hdr_path = hdr_path_in.empty() ? s.hdr.path : hdr_path_in;
  if (sel.hdr_path != "integer" && sel.hdr_path != "float") {
    *err = "unknown HDR path '" + sel.hdr_path + "' (integer, float)";
    return false;
  }
  const bool float_path = sel.hdr_path == "float";
  const ShaderDecl *model = find_decl(sel.decls, "model_lighting");
  const ShaderDecl *world = find_decl(sel.decls, "world_lighting");
  if (!model || !world) {
    *err = "shader library lacks model_lighting or world_lighting";
    return false;
  }
  // The sky's skybox (glue/scene/skybox_pass.h): only in a scene with a sky.
  const ShaderDecl *skybox = s.sky.image >= 0 ? find_decl(sel.decls, "skybox") : nullptr;
  if (s.sky.image >= 0 && !skybox) {
    *err = "shader library lacks skybox";
    return false;
  }
  // Every variant of the families for the tier; those used are pointed at.
  for (const ShaderDecl *d : {model, world, skybox}) {
    if (!d) continue;
    std::string enum_err;  // (enumerate_variants reports through a non-empty message)
    std::vector<Variant> v = enumerate_variants(*d, {tier}, &enum_err);
    if (!enum_err.empty()) {
      *err = enum_err;
      return false;
    }
    sel.all_storage.insert(sel.all_storage.end(), v.begin(), v.end());
  }
  bool used_model = false, used_world = false;
  std::map<const Variant *, int> index;
  std::vector<const Variant *> order;
  for (size_t i = 0; i < s.primitives.size(); ++i) {
    const ScenePrimitive &p = s.primitives[i];
    const SceneMaterial &m = s.materials.at(p.material);
    SceneDrawChoice c;
    c.primitive = static_cast<int>(i);
    Wanted w;
    const ShaderDecl *d = m.shader == SceneShader::World ? world : model;
    if (m.shader == SceneShader::World) {
      used_world = true;
      world_choice(s, m, &w, &c);
    } else {
      used_model = true;
      model_choice(s, p, m, tier, float_path, &w, &c);
    }
    c.family = d->name;
    if (all_features) {
      // Every feature on: only the HDR-path, encoding and light-count choices stay derived.
      for (auto &kv : w.values) {
        const std::string &k = kv.first;
        if (k == "ALBEDO_TEXTURE" || k == "PHONG" || k == "PHONG_EXPONENT_MAP" || k == "RIM_LIGHT" || k == "ENVMAP" ||
            k == "LIGHT_WARP" || k == "ENVMAPMASK")
          kv.second = 1;
        if (k == "HALF_LAMBERT" && tier != Tier::PS20) kv.second = 1;  // Phong needs it
        if (k == "BUMPMAP") kv.second = 1;
        if (k == "NUM_LIGHTS") kv.second = max_local_lights(tier);
      }
      c.why.assign(1, "all features compiled in (the baseline without selection)");
      w.why.clear();
      c.mask_constant = false;
    }
    const Variant *v = match(sel.all_storage, d, tier, w);
    if (!v) {
      std::string vals;
      for (const auto &kv : w.values) vals += (vals.empty() ? "" : ",") + kv.first + "=" + std::to_string(kv.second);
      *err = p.where + " (material " + m.where + "): no " + d->name + " variant " + tier_name(tier) + ":" + vals +
          " (excluded by the skip rules of " + d->file + ")";
      return false;
    }
    c.variant = v;
    c.why.insert(c.why.begin(), w.why.begin(), w.why.end());
    if (!index.count(v)) {
      index[v] = static_cast<int>(order.size());
      order.push_back(v);
    }
    sel.draws.push_back(std::move(c));
  }
  const Variant *sky = nullptr;  // the skybox has one variant per tier
  for (const Variant &v : sel.all_storage)
    if (skybox && v.shader == skybox && !sky) sky = &v;
  if (sky) {
    index[sky] = static_cast<int>(order.size());
    order.push_back(sky);
  }
  for (const Variant &v : sel.all_storage)
    if ((v.shader == model && used_model) || (v.shader == world && used_world) || v.shader == skybox)
      sel.all_variants.push_back(&v);
  sel.all_combos = static_cast<int>(sel.all_variants.size());
  // Unique variants, in first-use order; the Variant objects are copied into sel.variants.
  sel.variants.reserve(order.size());
  sel.variant_why.resize(order.size());
  for (const Variant *v : order) sel.variants.push_back(*v);
  for (auto &c : sel.draws) {
    const int k = index[c.variant];
    const ScenePrimitive &p = s.primitives[c.primitive];
    std::string line = p.where + " (" + s.materials[p.material].name + ")";
    for (const auto &r : c.why) line += "; " + r;
    sel.variant_why[k].push_back(line);
    c.variant = &sel.variants[k];
  }
  if (sky) {
    sel.sky = &sel.variants[index[sky]];
    sel.variant_why[index[sky]].push_back("the scene's sky (extras.tiershade.sky): the HDR skybox where no geometry covers a pixel");
  }
  (void)yes;
  *out = std::move(sel);
  return true;
}

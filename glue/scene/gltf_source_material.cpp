// tiershade scene: glTF materials to SceneMaterial: the pbr base colour and normal map, and
// the Source shader and $-keys of `extras.source` (docs/scenes.md lists them), each checked
// for its type, range and shader, and the combos the variant files forbid.
#include "scene/gltf_util.h"

namespace scene_gltf {
namespace {

enum : int { MODEL = 1, WORLD = 2, BOTH = 3 };

// One $-key: the shaders that take it and where it goes in the material. Exactly one pointer is
// set, and it says the key's JSON kind; numbers are checked against [lo, hi].
struct Slot {
  const char *key;
  int shaders;
  double lo = 0, hi = 0;
  bool *flag = nullptr;                // true/false (or 0/1)
  float *number = nullptr;             // a number
  float *vec3 = nullptr;               // three numbers
  int *integer = nullptr;              // an integer
  SceneTextureRef *texture = nullptr;  // {"index": i}
};
Slot key_bool(const char *key, int shaders, bool *f) {
  Slot s{key, shaders};
  s.flag = f;
  return s;
}
Slot key_number(const char *key, int shaders, double lo, double hi, float *f) {
  Slot s{key, shaders, lo, hi};
  s.number = f;
  return s;
}
Slot key_vec3(const char *key, int shaders, double lo, double hi, float *f) {
  Slot s{key, shaders, lo, hi};
  s.vec3 = f;
  return s;
}
Slot key_int(const char *key, int shaders, int lo, int hi, int *f) {
  Slot s{key, shaders, static_cast<double>(lo), static_cast<double>(hi)};
  s.integer = f;
  return s;
}
Slot key_texture(const char *key, int shaders, SceneTextureRef *f) {
  Slot s{key, shaders};
  s.texture = f;
  return s;
}

bool texture_ref(const tinygltf::Model &m, int index, const std::string &place, SceneTextureRef *out, Err &e) {
  if (index < 0 || static_cast<size_t>(index) >= m.textures.size())
    return e.fail(
        place,
        "texture " + std::to_string(index) + " does not exist (" + std::to_string(m.textures.size()) + " textures)");
  const tinygltf::Texture &t = m.textures[index];
  const std::string tp = "textures[" + std::to_string(index) + "]";
  if (t.source < 0 || static_cast<size_t>(t.source) >= m.images.size())
    return e.fail(tp, "source image " + std::to_string(t.source) + " does not exist");
  SceneTextureRef r;
  r.image = t.source;
  if (t.sampler >= 0) {
    if (static_cast<size_t>(t.sampler) >= m.samplers.size())
      return e.fail(tp, "sampler " + std::to_string(t.sampler) + " does not exist");
    const tinygltf::Sampler &sm = m.samplers[t.sampler];
    r.linear = sm.magFilter != TINYGLTF_TEXTURE_FILTER_NEAREST;
    r.repeat = sm.wrapS == TINYGLTF_TEXTURE_WRAP_REPEAT && sm.wrapT == TINYGLTF_TEXTURE_WRAP_REPEAT;
    if (sm.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST ||
        sm.minFilter == TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST)
      r.mip = 1;
    else if (sm.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR ||
             sm.minFilter == TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR)
      r.mip = 2;
  }
  *out = r;
  return true;
}

const char *shader_name(int s) { return s == MODEL ? "VertexLitGeneric" : "LightmappedGeneric"; }

bool read_source(const tinygltf::Model &m, const tinygltf::Value &src, const std::string &place, SceneMaterial *mat,
                 Err &e) {
  if (!src.IsObject()) return e.fail(place, "expected an object, got " + value_kind(src));
  int shader = MODEL;
  if (src.Has("shader")) {
    std::string name;
    if (!read_string(src.Get("shader"), place + ".shader", &name, e)) return false;
    if (name == "VertexLitGeneric")
      shader = MODEL;
    else if (name == "LightmappedGeneric")
      shader = WORLD;
    else
      return e.fail(place + ".shader", quoted(name) + " is not \"VertexLitGeneric\" or \"LightmappedGeneric\"");
  }
  mat->shader = shader == MODEL ? SceneShader::Model : SceneShader::World;
  bool mask_alpha_normal = false, mask_alpha_base = false;
  const Slot slots[] = {
      key_bool("$halflambert", MODEL, &mat->half_lambert),
      key_bool("$phong", MODEL, &mat->phong),
      key_number("$phongexponent", MODEL, 0.01, 10000, &mat->phong_exponent),
      key_texture("$phongexponenttexture", MODEL, &mat->phong_exponent_texture),
      key_number("$phongexponentfactor", MODEL, 0, 10000, &mat->phong_exponent_factor),
      key_number("$phongboost", MODEL, 0, 1000, &mat->phong_boost),
      key_vec3("$phongfresnelranges", MODEL, 0, 100, mat->phong_fresnel_ranges),
      key_vec3("$phongtint", MODEL, 0, 1000, mat->phong_tint),
      key_bool("$phongalbedotint", MODEL, &mat->phong_albedo_tint),
      key_bool("$basemapalphaphongmask", MODEL, &mat->base_alpha_phong_mask),
      key_bool("$invertphongmask", MODEL, &mat->invert_phong_mask),
      key_bool("$rimlight", MODEL, &mat->rim_light),
      key_number("$rimlightexponent", MODEL, 0.01, 10000, &mat->rim_exponent),
      key_number("$rimlightboost", MODEL, 0, 1000, &mat->rim_boost),
      key_number("$rimmask", MODEL, 0, 1, &mat->rim_mask),
      key_texture("$lightwarptexture", MODEL, &mat->light_warp_texture),
      key_number("$envmapfresnel", MODEL, 0, 1, &mat->envmap_fresnel),
      key_bool("$selfillum", MODEL, &mat->self_illum),
      key_vec3("$selfillumtint", MODEL, 0, 100000, mat->self_illum_tint),
      key_bool("$envmap", BOTH, &mat->envmap),
      key_number("$envmapscale", BOTH, 0, 1000, &mat->envmap_scale),
      key_vec3("$envmaptint", BOTH, 0, 1000, mat->envmap_tint),
      key_int("probe", BOTH, 0, 1023, &mat->probe),
      key_bool("$ssbump", WORLD, &mat->ssbump),
      key_texture("$envmapmask", WORLD, &mat->envmap_mask_texture),
      key_bool("$normalmapalphaenvmapmask", WORLD, &mask_alpha_normal),
      key_bool("$basealphaenvmapmask", WORLD, &mask_alpha_base),
      key_number("$envmapcontrast", WORLD, 0, 1, &mat->envmap_contrast),
      key_number("$envmapsaturation", WORLD, 0, 1, &mat->envmap_saturation),
      key_number("$fresnelreflection", WORLD, 0, 1, &mat->fresnel_reflection),
  };
  bool explicit_half_lambert = false;
  for (const std::string &k : src.Keys()) {
    if (k == "shader") continue;
    const Slot *s = nullptr;
    for (const Slot &c : slots)
      if (k == c.key) s = &c;
    if (!s) return e.fail(place, "unknown key " + quoted(k));
    if (!(s->shaders & shader))
      return e.fail(place, quoted(k) + " is a " + shader_name(s->shaders) + " key, not " + shader_name(shader));
    const std::string kp = place + "." + k;
    const tinygltf::Value &v = src.Get(k);
    double d[3];
    if (s->flag) {
      if (!read_bool(v, kp, s->flag, e)) return false;
    } else if (s->number) {
      if (!read_number(v, kp, s->lo, s->hi, d, e)) return false;
      *s->number = static_cast<float>(d[0]);
    } else if (s->vec3) {
      if (!read_vec(v, kp, 3, s->lo, s->hi, d, e)) return false;
      for (int i = 0; i < 3; ++i) s->vec3[i] = static_cast<float>(d[i]);
    } else if (s->integer) {
      if (!read_int(v, kp, static_cast<int>(s->lo), static_cast<int>(s->hi), s->integer, e)) return false;
    } else {
      int idx = -1;
      if (!check_keys(v, kp, {"index"}, e)) return false;
      if (!v.Has("index")) return e.fail(kp, "missing \"index\"");
      if (!read_int(v.Get("index"), kp + ".index", -1000000, 1000000, &idx, e)) return false;
      if (!texture_ref(m, idx, kp + ".index", s->texture, e)) return false;
    }
    if (k == "$halflambert") explicit_half_lambert = true;
  }
  // The combos the variant files allow (shaders/*.variants skip rules).
  if (shader == MODEL) {
    const struct {
      const char *key;
      bool on;
    } needs_phong[] = {{"$phongexponenttexture", mat->phong_exponent_texture.image >= 0},
                       {"$rimlight", mat->rim_light},
                       {"$envmap", mat->envmap},
                       {"$lightwarptexture", mat->light_warp_texture.image >= 0}};
    for (const auto &n : needs_phong)
      if (n.on && !mat->phong) return e.fail(place, quoted(n.key) + " needs \"$phong\": 1 (ps2b/sm3 Phong feature)");
    if (mat->phong) {
      if (explicit_half_lambert && !mat->half_lambert)
        return e.fail(place + ".$halflambert", "0 conflicts with \"$phong\" (Phong forces half-Lambert)");
      mat->half_lambert = true;
    }
  } else {
    if (mat->ssbump && mat->normal_texture.image < 0)
      return e.fail(place, "\"$ssbump\" needs a normalTexture (the ssbump map)");
    const int masks = (mat->envmap_mask_texture.image >= 0) + mask_alpha_normal + mask_alpha_base;
    if (masks > 1)
      return e.fail(place,
                    "\"$envmapmask\", \"$normalmapalphaenvmapmask\" and \"$basealphaenvmapmask\" exclude each other");
    if (masks && !mat->envmap) return e.fail(place, "an envmap mask needs \"$envmap\": 1");
    if (mask_alpha_normal && mat->normal_texture.image < 0)
      return e.fail(place, "\"$normalmapalphaenvmapmask\" needs a normalTexture");
    mat->envmap_mask = mat->envmap_mask_texture.image >= 0 ? SceneEnvMask::Texture
        : mask_alpha_normal                                ? SceneEnvMask::NormalAlpha
        : mask_alpha_base                                  ? SceneEnvMask::InvBaseAlpha
                                                           : SceneEnvMask::None;
  }
  if (mat->probe >= 0 && !mat->envmap)
    return e.fail(place + ".probe", "names the envmap's probe: needs \"$envmap\": 1");
  return true;
}

// emissiveFactor (3 numbers in [0, 1]) x KHR_materials_emissive_strength's emissiveStrength (>= 0)
// and emissiveTexture (TEXCOORD_0).
bool read_emission(const tinygltf::Model &m, const tinygltf::Material &g, SceneMaterial *mat, Err &e) {
  const std::string fp = mat->where + ".emissiveFactor";
  if (g.emissiveFactor.size() != 3) return e.fail(fp, "expected 3 numbers");
  double strength = 1;
  const auto ext = g.extensions.find("KHR_materials_emissive_strength");
  if (ext != g.extensions.end()) {
    const std::string sp = mat->where + ".extensions.KHR_materials_emissive_strength";
    if (!check_keys(ext->second, sp, {"emissiveStrength"}, e)) return false;
    if (ext->second.Has("emissiveStrength") &&
        !read_number(ext->second.Get("emissiveStrength"), sp + ".emissiveStrength", 0, 1e6, &strength, e))
      return false;
  }
  for (int k = 0; k < 3; ++k) {
    const double c = g.emissiveFactor[k];
    if (!(c >= 0 && c <= 1)) return e.fail(fp, "values must be in [0, 1]");
    mat->emission[k] = static_cast<float>(c * strength);
  }
  if (g.emissiveTexture.index >= 0) {
    const std::string tp = mat->where + ".emissiveTexture";
    if (g.emissiveTexture.texCoord != 0) return e.fail(tp + ".texCoord", "only TEXCOORD_0 is supported");
    if (!texture_ref(m, g.emissiveTexture.index, tp + ".index", &mat->emissive_texture, e)) return false;
  }
  return true;
}

}  // namespace

bool convert_materials(const tinygltf::Model &m, Scene *s, Err &e) {
  for (size_t i = 0; i < m.materials.size(); ++i) {
    const tinygltf::Material &g = m.materials[i];
    SceneMaterial mat;
    mat.name = g.name;
    mat.where = named("materials[" + std::to_string(i) + "]", g.name);
    const auto &pbr = g.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() != 4)
      return e.fail(mat.where + ".pbrMetallicRoughness.baseColorFactor", "expected 4 numbers");
    for (int k = 0; k < 4; ++k) {
      const double c = pbr.baseColorFactor[k];
      if (!(c >= 0 && c <= 1))
        return e.fail(mat.where + ".pbrMetallicRoughness.baseColorFactor", "values must be in [0, 1]");
      mat.base_color[k] = static_cast<float>(c);
    }
    if (pbr.baseColorTexture.index >= 0) {
      const std::string tp = mat.where + ".pbrMetallicRoughness.baseColorTexture";
      if (pbr.baseColorTexture.texCoord != 0) return e.fail(tp + ".texCoord", "only TEXCOORD_0 is supported");
      if (!texture_ref(m, pbr.baseColorTexture.index, tp + ".index", &mat.base_texture, e)) return false;
    }
    if (g.normalTexture.index >= 0) {
      const std::string tp = mat.where + ".normalTexture";
      if (g.normalTexture.texCoord != 0) return e.fail(tp + ".texCoord", "only TEXCOORD_0 is supported");
      if (!texture_ref(m, g.normalTexture.index, tp + ".index", &mat.normal_texture, e)) return false;
    }
    if (!read_emission(m, g, &mat, e)) return false;
    if (g.extras.IsObject() && g.extras.Has("source") &&
        !read_source(m, g.extras.Get("source"), mat.where + ".extras.source", &mat, e))
      return false;
    s->materials.push_back(mat);
  }
  return true;
}

}  // namespace scene_gltf

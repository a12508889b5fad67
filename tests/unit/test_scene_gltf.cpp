// tiershade tests: unit tests for the glTF scene loader (glue/scene/gltf_load*.cpp, glue/scene/scene.h).
//
// Usage: build/tests/test_scene_gltf   (from the repo root: it reads scenes/)
//   Prints "PASS name" or "FAIL name: detail" per check; exits 1 if any failed.
//
// Covered: the three shipped scenes (counts, a transformed vertex, normals and
// tangents, image row order, light conversion, Source keys, extras); a minimal
// scene as .gltf with an external .bin, with a data URI, and as .glb; and a
// table of broken scenes written to a private mkdtemp() directory, each of
// which must fail with the file name and the place in the message and leave
// the output scene untouched.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "base/image.h"
#include "io/exr.h"
#include "scene/scene.h"
#include "unit_check.h"

namespace {

bool near(double a, double b, double eps = 1e-4) { return std::fabs(a - b) <= eps; }
bool contains(const std::string &h, const std::string &n) { return h.find(n) != std::string::npos; }

const SceneMaterial *material(const Scene &s, const std::string &name) {
  for (const SceneMaterial &m : s.materials)
    if (m.name == name) return &m;
  return nullptr;
}
const SceneLight *light(const Scene &s, const std::string &name) {
  for (const SceneLight &l : s.lights)
    if (l.name == name) return &l;
  return nullptr;
}
const ScenePrimitive *prim_of(const Scene &s, const std::string &instance) {
  for (const ScenePrimitive &p : s.primitives)
    if (p.instance >= 0 && s.instances[p.instance].name == instance) return &p;
  return nullptr;
}

// Every normal and tangent unit length, tangent w = +-1, indices in range.
bool well_formed(const Scene &s, std::string *why) {
  for (const ScenePrimitive &p : s.primitives) {
    const size_t n = p.position.size() / 3;
    if (p.normal.size() != n * 3 || p.uv.size() != n * 2 || (!p.tangent.empty() && p.tangent.size() != n * 4)) {
      *why = p.where + ": array sizes";
      return false;
    }
    for (size_t i = 0; i < n; ++i) {
      const float *nn = &p.normal[i * 3];
      if (!near(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2], 1, 1e-4)) {
        *why = p.where + ": normal " + std::to_string(i) + " not unit";
        return false;
      }
      if (!p.tangent.empty()) {
        const float *t = &p.tangent[i * 4];
        if (!near(t[0] * t[0] + t[1] * t[1] + t[2] * t[2], 1, 1e-4) || std::fabs(t[3]) != 1.f) {
          *why = p.where + ": tangent " + std::to_string(i);
          return false;
        }
      }
    }
    if (p.indices.empty() || p.indices.size() % 3) {
      *why = p.where + ": index count";
      return false;
    }
    for (uint32_t ix : p.indices)
      if (ix >= n) {
        *why = p.where + ": index out of range";
        return false;
      }
    if (p.material < 0 || p.material >= static_cast<int>(s.materials.size())) {
      *why = p.where + ": material";
      return false;
    }
  }
  return true;
}

void test_model_lighting() {
  Scene s;
  std::string err;
  const bool ok = load_scene("scenes/model_lighting.gltf", &s, &err);
  check(ok, "model_lighting loads", err);
  if (!ok) return;
  check(s.materials.size() == 5 && s.primitives.size() == 5 && s.instances.size() == 5,
        "model_lighting: 5 materials, primitives, instances",
        std::to_string(s.materials.size()) + " " + std::to_string(s.primitives.size()));
  int types[3] = {0, 0, 0};
  for (const SceneLight &l : s.lights) types[l.light.type]++;
  check(s.lights.size() == 6 && types[0] == 2 && types[1] == 2 && types[2] == 2,
        "model_lighting: 2 point, 2 spot, 2 directional lights");
  std::string why;
  check(well_formed(s, &why), "model_lighting: unit normals/tangents, indices in range", why);
  for (const SceneMaterial &m : s.materials)
    check(m.shader == SceneShader::Model, "model_lighting: " + m.name + " is VertexLitGeneric");
  const ScenePrimitive *p = prim_of(s, "plain_sphere");  // north pole of a r=0.6 sphere at x=-3
  check(p && near(p->position[0], -3) && near(p->position[1], 0.6) && near(p->position[2], 0),
        "model_lighting: first vertex of plain_sphere in world space",
        p ? std::to_string(p->position[0]) + "," + std::to_string(p->position[1]) : "no primitive");
  check(p && p->uv.size() == p->position.size() / 3 * 2 && !p->tangent.empty(),
        "model_lighting: uvs and tangents read");
  const ScenePrimitive *t = prim_of(s, "metal_torus");
  bool inside = t != nullptr;
  for (size_t i = 0; t && i < t->position.size(); i += 3) {  // scale 1.1: |p - centre| <= 1.1 * 0.77
    const double dx = t->position[i] - 1.5, dy = t->position[i + 1], dz = t->position[i + 2] + 0.5;
    inside = inside && std::sqrt(dx * dx + dy * dy + dz * dz) <= 1.1 * 0.77 + 1e-4;
  }
  check(inside && t && near(s.instances[t->instance].world[12], 1.5) && near(s.instances[t->instance].world[0], 1.1),
        "model_lighting: torus under a scaled parent node");
  const SceneMaterial *plain = material(s, "lambert_plain"), *skin = material(s, "skin"),
                      *metal = material(s, "metal_envmap"), *glow = material(s, "selfillum_stripes");
  check(plain && !plain->half_lambert && plain->base_texture.image < 0 && near(plain->base_color[0], 0.7),
        "model_lighting: lambert_plain ($halflambert 0, untextured)");
  check(skin && skin->phong && skin->rim_light && skin->half_lambert && skin->phong_exponent_texture.image >= 0 &&
            near(skin->phong_fresnel_ranges[0], 0.3f) && near(skin->rim_boost, 2) && skin->normal_texture.image >= 0,
        "model_lighting: skin Phong keys");
  check(metal && metal->envmap && metal->light_warp_texture.image >= 0 && near(metal->envmap_tint[0], 0.6f) &&
            near(metal->phong_exponent, 40),
        "model_lighting: metal envmap and light warp");
  check(glow && glow->self_illum && near(glow->self_illum_tint[1], 0.6f), "model_lighting: self-illumination");
  const SceneMaterial *checker = material(s, "halflambert_checker");
  if (checker && checker->base_texture.image >= 0) {
    const SceneImage &im = s.images[checker->base_texture.image];
    // file row 0 starts with (70, 90, 130), the file's last row with (200, 190, 170)
    check(im.w == 128 && im.h == 128 && near(im.rgba[0], 200 / 255.0) &&
              near(im.rgba[(size_t)(im.h - 1) * im.w * 4 + 2], 130 / 255.0) && im.rgba[3] == 1.f,
          "model_lighting: checker.png rows bottom-up, code/255");
  } else {
    check(false, "model_lighting: checker texture");
  }
  const SceneLight *spot = light(s, "top_spot"), *sun = light(s, "sun"), *key = light(s, "key_point");
  if (spot && sun && key) {
    const ts_light &l = spot->light;
    const double d = std::sqrt(17.0);
    check(l.type == TS_LIGHT_SPOT && near(l.color[0], 15) && near(l.color[2], 14.25) && near(l.pos[1], 4) &&
              near(l.pos[2], 1) && near(l.dir[1], -4 / d) && near(l.dir[2], -1 / d) &&
              near(l.cos_outer, std::cos(0.5)) && near(l.cos_inner, std::cos(0.3)) && near(l.spot_exponent, 2) &&
              near(l.atten[2], 1) && l.atten[0] == 0,
          "model_lighting: spot light converted");
    const double n = 1.5;  // |(1, -1, -0.5)|
    check(sun->light.type == TS_LIGHT_DIRECTIONAL && near(sun->light.dir[0], 1 / n) &&
              near(sun->light.dir[1], -1 / n) && sun->light.atten[0] == 1 && sun->light.atten[2] == 0 &&
              near(sun->light.color[0], 0.6),
          "model_lighting: directional light (direction = node -Z, atten 1,0,0)");
    check(key->light.type == TS_LIGHT_POINT && near(key->light.pos[0], -2.5) && near(key->light.color[1], 9),
          "model_lighting: point light colour x intensity");
    float packed[5][4];
    bool all = true;
    for (const SceneLight &sl : s.lights) all = all && ts_light_pack(&sl.light, packed, nullptr, 0);
    check(all, "model_lighting: every light packs");
  } else {
    check(false, "model_lighting: lights by name");
  }
  const SceneCamera &c = s.cameras[s.camera];
  const double cl = std::sqrt(37.0);
  check(s.cameras.size() == 1 && near(c.eye[2], 6) && near(c.forward[1], -1 / cl) && near(c.forward[2], -6 / cl) &&
            near(c.up[1], 6 / cl) && near(c.yfov, 0.7),
        "model_lighting: camera from its node");
  check(s.probes.size() == 1 && s.probes[0].image >= 0 && s.images[s.probes[0].image].w > 0 && s.probes[0].size == 64 &&
            contains(s.images[s.probes[0].image].path, "grace.hdr"),
        "model_lighting: probe image grace.hdr");
  check(s.ambient.size() == 2 && s.ambient[0].from_probe == 0 && s.ambient[1].from_probe == -1 &&
            near(s.ambient[1].cube[0][0], 0.2f) && near(s.ambient[1].position[0], 4),
        "model_lighting: ambient samples");
  check(s.hdr.path == "integer" && s.hdr.luts.empty() && s.path == "scenes/model_lighting.gltf",
        "model_lighting: hdr settings");
}

void test_world_lighting() {
  Scene s;
  std::string err;
  const bool ok = load_scene("scenes/world_lighting.gltf", &s, &err);
  check(ok, "world_lighting loads", err);
  if (!ok) return;
  // The back wall is four quads around its window; the sky's sun is the fourth light
  // (extras.tiershade.sky.sun, its spread in radians).
  check(s.materials.size() == 8 && s.primitives.size() == 25 && s.lights.size() == 4 && s.probes.size() == 2,
        "world_lighting: 8 materials, 24 quads and the ceiling lamp's disc, 4 lights, 2 probes");
  check(s.sky.image >= 0 && s.lightmaps.quality.sky_samples == 16 && s.lights.back().light.type == TS_LIGHT_DIRECTIONAL &&
            std::fabs(s.lights.back().spread - 4 * M_PI / 180) < 1e-12,
        "world_lighting: the sky and its soft sun");
  std::string why;
  check(well_formed(s, &why), "world_lighting: well formed", why);
  bool quads = true, world = true;
  const SceneMaterial *lamp_m = material(s, "ceiling_lamp");
  const ScenePrimitive *lamp = prim_of(s, "ceiling_lamp");
  for (const ScenePrimitive &p : s.primitives)
    quads = quads && (&p == lamp || (p.position.size() == 12 && p.indices.size() == 6));
  // The ceiling lamp (an emitter of any shape: glue/bake/area_lights.h): a 24-triangle disc with its own
  // lightmap UVs, facing down, emissiveFactor x emissiveStrength 100.
  check(lamp && lamp_m && lamp->indices.size() == 72 && lamp->uv1.size() == 50 && near(lamp->normal[1], -1) &&
            near(lamp_m->emission[0], 100) && near(lamp_m->emission[2], 78),
        "world_lighting: the ceiling lamp, a TEXCOORD_1 disc emitting 100 x [1, 0.92, 0.78]");
  for (const SceneMaterial &m : s.materials) world = world && m.shader == SceneShader::World;
  check(quads, "world_lighting: every primitive but the lamp a 4-vertex quad");
  check(world, "world_lighting: every material LightmappedGeneric");
  const ScenePrimitive *fl = prim_of(s, "floor");
  check(fl && near(fl->normal[1], 1) && near(fl->position[1], 0) && fl->tangent.size() == 16,
        "world_lighting: floor faces up, has tangents");
  const SceneMaterial *crate = material(s, "crate_masked"), *glossy = material(s, "glossy_tile_basealpha"),
                      *floor = material(s, "floor_tiles"), *stone = material(s, "wall_stone_ssbump"),
                      *ceil = material(s, "ceiling_plaster"), *cm = material(s, "plinth_const_mask");
  check(crate && crate->envmap && crate->envmap_mask == SceneEnvMask::Texture && crate->probe == 1 &&
            crate->envmap_mask_texture.image >= 0,
        "world_lighting: crate envmap mask texture, probe 1");
  check(glossy && glossy->envmap_mask == SceneEnvMask::InvBaseAlpha && near(glossy->envmap_contrast, 0.3f),
        "world_lighting: $basealphaenvmapmask");
  check(floor && floor->envmap_mask == SceneEnvMask::NormalAlpha && floor->normal_texture.image >= 0 &&
            near(floor->fresnel_reflection, 0.3f),
        "world_lighting: floor RNM with normal-alpha mask");
  check(stone && stone->ssbump && stone->normal_texture.image >= 0, "world_lighting: ssbump wall");
  check(ceil && ceil->normal_texture.image < 0 && !ceil->envmap, "world_lighting: flat ceiling");
  bool constant = false;
  if (cm && cm->envmap_mask_texture.image >= 0) {
    const SceneImage &im = s.images[cm->envmap_mask_texture.image];
    constant = im.w == 4 && im.h == 4;
    for (size_t i = 0; i < im.rgba.size(); ++i) constant = constant && im.rgba[i] == (i % 4 == 3 ? 1.f : 128 / 255.f);
  }
  check(constant, "world_lighting: constant-valued mask texture");
  check(s.probes[0].image == -1 && s.probes[1].image == -1 && s.probes[1].size == 32,
        "world_lighting: probes from the world");
  check(near(s.lightmaps.quality.luxels_per_unit, 8) && s.lightmaps.encoding == "rgbe" && s.lightmaps.page_w == 512 &&
            s.lightmaps.page_h == 256,
        "world_lighting: lightmap settings");
  const SceneCamera &c = s.cameras[s.camera];
  check(c.eye[0] > 0 && c.forward[0] < 0 && c.forward[2] < 0, "world_lighting: camera looks into the far corner");
}

void test_hdr_atrium() {
  Scene s;
  std::string err;
  const bool ok = load_scene("scenes/hdr_atrium.gltf", &s, &err);
  check(ok, "hdr_atrium loads", err);
  if (!ok) return;
  std::string why;
  check(well_formed(s, &why), "hdr_atrium: well formed", why);
  check(s.hdr.path == "float" && s.hdr.auto_exposure && near(s.hdr.bloom_amount, 0.3f) && s.hdr.luts.size() == 2 &&
            contains(s.hdr.luts[0].path, "luts/day_for_night.cube") && near(s.hdr.luts[0].weight, 0.3f) &&
            near(s.hdr.luts[1].weight, 0.2f),
        "hdr_atrium: float path, auto exposure, bloom, two LUTs");
  const SceneLight *sun = light(s, "sun_lamp");
  check(sun && near(sun->light.color[0], 200) && near(sun->light.color[1], 184, 1e-3),
        "hdr_atrium: 200-intensity lamp");
  const SceneMaterial *panel = material(s, "light_panel");
  check(panel && panel->self_illum && near(panel->self_illum_tint[0], 24), "hdr_atrium: bright self-illuminated panel");
  check(s.probes.size() == 1 && near(s.probes[0].scale, 4) && s.probes[0].image >= 0 &&
            contains(s.images[s.probes[0].image].path, "uffizi.hdr"),
        "hdr_atrium: uffizi probe with scale");
}

// ---- broken scenes ---------------------------------------------------------
std::string g_dir;

void write_file(const std::string &name, const std::string &data) {
  FILE *f = fopen((g_dir + "/" + name).c_str(), "wb");
  if (f) {
    fwrite(data.data(), 1, data.size(), f);
    fclose(f);
  }
}

// One triangle: 3 float positions (36 bytes), 3 uint16 indices (6), 2 padding.
std::string tri_bin() {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint16_t ix[4] = {0, 1, 2, 0};
  std::string b(reinterpret_cast<const char *>(p), 36);
  b.append(reinterpret_cast<const char *>(ix), 8);
  return b;
}

std::string base64(const std::string &in) {
  static const char *t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string o;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= static_cast<unsigned char>(in[i + 2]);
    o += t[v >> 18 & 63];
    o += t[v >> 12 & 63];
    o += i + 1 < in.size() ? t[v >> 6 & 63] : '=';
    o += i + 2 < in.size() ? t[v & 63] : '=';
  }
  return o;
}

const std::string kBase =
    "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,1]}],"
    "\"nodes\":[{\"mesh\":0,\"translation\":[1,2,3]},{\"camera\":0,\"translation\":[0,0,3]}],"
    "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0}]}],"
    "\"materials\":[{\"name\":\"mat\",\"extras\":{\"source\":{\"shader\":\"VertexLitGeneric\"}}}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
    "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}],"
    "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":"
    "6}],"
    "\"buffers\":[{\"uri\":\"tri.bin\",\"byteLength\":44}]}";

std::string edit(std::string s, const std::string &from, const std::string &to) {
  const size_t p = s.find(from);
  if (p == std::string::npos) {
    check(false, "test setup: edit", "no '" + from + "' in the base scene");
    return s;
  }
  return s.replace(p, from.size(), to);
}

void test_good_minimal() {
  write_file("tri.bin", tri_bin());
  write_file("ok.gltf", kBase);
  Scene s;
  std::string err;
  bool ok = load_scene(g_dir + "/ok.gltf", &s, &err);
  check(ok && s.primitives.size() == 1 && near(s.primitives[0].position[3], 2) && near(s.primitives[0].normal[2], 1) &&
            s.primitives[0].indices.size() == 3,
        "minimal .gltf: translated triangle with a flat normal", err);
  // No material: a default VertexLitGeneric one is appended.
  write_file("nomat.gltf", edit(kBase, ",\"material\":0", ""));
  ok = load_scene(g_dir + "/nomat.gltf", &s, &err);
  check(ok && s.materials.size() == 2 && s.primitives[0].material == 1 && s.materials[1].shader == SceneShader::Model,
        "minimal: primitive without material gets a default material", err);
  // Data URI buffer.
  write_file(
      "datauri.gltf",
      edit(kBase, "\"uri\":\"tri.bin\"", "\"uri\":\"data:application/octet-stream;base64," + base64(tri_bin()) + "\""));
  ok = load_scene(g_dir + "/datauri.gltf", &s, &err);
  check(ok && s.primitives.size() == 1 && near(s.primitives[0].position[5], 3), "minimal: data URI buffer", err);
  // .glb with a BIN chunk.
  std::string json = edit(kBase, "\"uri\":\"tri.bin\",", "");
  while (json.size() % 4) json += ' ';
  const std::string bin = tri_bin();
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char *>(&v), 4); };
  const std::string glb = "glTF" + u32(2) + u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size())) +
      u32(static_cast<uint32_t>(json.size())) + "JSON" + json + u32(static_cast<uint32_t>(bin.size())) +
      std::string("BIN\0", 4) + bin;
  write_file("ok.glb", glb);
  ok = load_scene(g_dir + "/ok.glb", &s, &err);
  check(ok && s.primitives.size() == 1 && s.cameras.size() == 1, "minimal: .glb with a BIN chunk", err);
}

struct Bad {
  const char *name;
  std::string file, text;  // text empty: the file is not written (or written by the case)
  const char *place;  // substring the message must contain (besides the file name)
};

void test_bad_scenes() {
  const std::string tex =
      "\"images\":[{\"uri\":\"gone.png\"}],\"textures\":[{\"source\":0}],\"materials\":[{\"name\":\"mat\","
      "\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},";
  auto src = [](const std::string &keys) {
    return edit(kBase, "{\"shader\":\"VertexLitGeneric\"}", "{\"shader\":\"VertexLitGeneric\"," + keys + "}");
  };
  auto extras = [](const std::string &ts) {
    return edit(kBase, "\"asset\":", "\"extras\":{\"tiershade\":" + ts + "},\"asset\":");
  };
  // Lightmap pages (extras.tiershade.lightmaps.image): a good 32 x 16 one, one with a NaN, one
  // with a negative texel, one too small to be a page.
  auto page = [](const std::string &name, int w, int h, int bad_x, int bad_y, float bad) {
    ImageF img;
    img.w = w;
    img.h = h;
    img.rgba.assign(static_cast<size_t>(w) * h * 4, 0.25f);
    if (bad_x >= 0) img.rgba[(static_cast<size_t>(bad_y) * w + bad_x) * 4 + 1] = bad;
    std::string e;
    if (!write_exr(g_dir + "/" + name, img, &e)) check(false, "test setup: write " + name, e);
  };
  page("page.exr", 32, 16, -1, -1, 0);
  page("page_nan.exr", 32, 16, 3, 2, std::nanf(""));
  page("page_neg.exr", 32, 16, 5, 7, -1.f);
  page("page_tiny.exr", 8, 8, -1, -1, 0);
  write_file("short.bin", tri_bin().substr(0, 40));
  write_file("bad.glb", std::string("glTX\2\0\0\0\x18\0\0\0\0\0\0\0JSON\0\0\0\0", 24));
  const std::vector<Bad> cases = {
      {"broken JSON", "broken.gltf", edit(kBase, "\"scene\":0,", "\"scene\":0,,"), "JSON: parse error at line 1"},
      {"truncated JSON", "truncated.gltf", kBase.substr(0, kBase.size() / 2), "JSON: parse error"},
      {"missing .bin", "nobin.gltf", edit(kBase, "tri.bin", "nope.bin"), "buffers[0]: file not found: "},
      {"missing image", "noimage.gltf", edit(kBase, "\"materials\":[{\"name\":\"mat\",", tex),
       "images[0]: file not found:"},
      {"buffer file shorter than byteLength", "short.gltf", edit(kBase, "tri.bin", "short.bin"), "buffers[0]: file"},
      {"bufferView beyond the buffer", "view.gltf",
       edit(kBase, "\"byteOffset\":36,\"byteLength\":6", "\"byteOffset\":40,\"byteLength\":6"), "bufferViews[1]"},
      {"accessor type wrong", "acctype.gltf",
       edit(kBase, "\"count\":3,\"type\":\"VEC3\"", "\"count\":3,\"type\":\"VEC2\""),
       "meshes[0].primitives[0].attributes.POSITION: accessor 0 has type VEC2, expected VEC3"},
      {"index component type wrong", "idxtype.gltf", edit(kBase, "\"componentType\":5123", "\"componentType\":5126"),
       "meshes[0].primitives[0].indices: accessor 1 has componentType 5126"},
      {"index out of range", "idxrange.gltf",
       edit(kBase, "\"count\":3,\"type\":\"VEC3\"", "\"count\":2,\"type\":\"VEC3\""),
       "meshes[0].primitives[0].indices: index 2"},
      {"unknown material key", "unkkey.gltf", src("\"$phongexp\":5"),
       "materials[0] (\"mat\").extras.source: unknown key \"$phongexp\""},
      {"wrong key type", "keytype.gltf", src("\"$phongboost\":\"big\""),
       "materials[0] (\"mat\").extras.source.$phongboost"},
      {"key on the wrong shader", "wrongshader.gltf", src("\"$ssbump\":1"),
       "extras.source: \"$ssbump\" is a LightmappedGeneric key"},
      {"texture index out of range", "texrange.gltf", src("\"$phong\":1,\"$lightwarptexture\":{\"index\":3}"),
       "extras.source.$lightwarptexture.index: texture 3 does not exist"},
      {"Phong feature without $phong", "nophong.gltf", src("\"$rimlight\":1"), "\"$rimlight\" needs \"$phong\""},
      {"unknown tiershade key", "unkextras.gltf", extras("{\"cameras\":0}"),
       "extras.tiershade: unknown key \"cameras\""},
      {"unknown probe key", "unkprobe.gltf", extras("{\"probes\":[{\"position\":[0,0,0],\"sise\":8}]}"),
       "extras.tiershade.probes[0]: unknown key \"sise\""},
      {"probe size out of range", "probesize.gltf", extras("{\"probes\":[{\"position\":[0,0,0],\"size\":1024}]}"),
       "extras.tiershade.probes[0].size"},
      {"ambient from a missing probe", "ambient.gltf",
       extras("{\"ambient\":[{\"position\":[0,0,0],\"from_probe\":0}]}"), "extras.tiershade.ambient[0].from_probe"},
      {"camera index out of range", "camidx.gltf", extras("{\"camera\":1}"), "extras.tiershade.camera"},
      {"non-finite number", "inf.gltf", edit(kBase, "\"yfov\":0.8", "\"yfov\":1e999"), "line 1, column"},
      {"no camera", "nocam.gltf", edit(kBase, "\"nodes\":[0,1]", "\"nodes\":[0]"), "no camera"},
      {"orthographic camera without extent", "ortho.gltf",
       edit(kBase, "{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}",
            "{\"type\":\"orthographic\",\"orthographic\":{\"xmag\":0,\"ymag\":1,\"znear\":0.1,\"zfar\":10}}"),
       "cameras[0].orthographic.xmag: must be > 0"},
      {"LUT file missing", "nolut.gltf", extras("{\"hdr\":{\"luts\":[{\"file\":\"luts/none.cube\",\"weight\":0.5}]}}"),
       "extras.tiershade.hdr.luts[0].file: file not found"},
      {"too many LUTs", "luts5.gltf",
       extras("{\"hdr\":{\"luts\":[{\"file\":\"tri.bin\"},{\"file\":\"tri.bin\"},{\"file\":\"tri.bin\"},"
              "{\"file\":\"tri.bin\"},{\"file\":\"tri.bin\"}]}}"),
       "extras.tiershade.hdr.luts: 5 LUTs"},
      {"lightmap page missing", "lmmiss.gltf", extras("{\"lightmaps\":{\"image\":\"none.exr\"}}"),
       "extras.tiershade.lightmaps.image: file not found"},
      {"lightmap page not an image", "lmbin.gltf", extras("{\"lightmaps\":{\"image\":\"tri.bin\"}}"),
       "extras.tiershade.lightmaps.image: " /* + path */},
      {"lightmap page size differs from page", "lmsize.gltf",
       extras("{\"lightmaps\":{\"page\":[512,256],\"image\":\"page.exr\"}}"),
       "32 x 16 texels, but \"page\" is 512 x 256"},
      {"lightmap page with a NaN", "lmnan.gltf", extras("{\"lightmaps\":{\"image\":\"page_nan.exr\"}}"),
       "page_nan.exr: texel (3, 2) channel G is NaN"},
      {"lightmap page with a negative texel", "lmneg.gltf", extras("{\"lightmaps\":{\"image\":\"page_neg.exr\"}}"),
       "page_neg.exr: texel (5, 7) channel G is -1"},
      {"lightmap page too small", "lmtiny.gltf", extras("{\"lightmaps\":{\"image\":\"page_tiny.exr\"}}"),
       "8 x 8 texels, a page is 16..8192"},
      {"lightmap image not a string", "lmtype.gltf", extras("{\"lightmaps\":{\"image\":3}}"),
       "extras.tiershade.lightmaps.image"},
      {"non-triangle mode", "lines.gltf", edit(kBase, "\"material\":0", "\"material\":0,\"mode\":1"),
       "meshes[0].primitives[0]: mode 1"},
      {"node cycle", "cycle.gltf", edit(kBase, "{\"mesh\":0,", "{\"children\":[0],\"mesh\":0,"),
       "nodes[0]: appears twice"},
      {"bad spot cone", "spot.gltf",
       edit(edit(kBase, "\"asset\":",
                 "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"spot\",\"spot\":"
                 "{\"innerConeAngle\":0.5,\"outerConeAngle\":0.4}}]}},\"asset\":"),
            "{\"camera\":0,", "{\"camera\":0,\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}},"),
       "extensions.KHR_lights_punctual.lights[0].spot"},
      {"unknown light extras key", "lightkey.gltf",
       edit(edit(kBase, "\"asset\":",
                 "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\","
                 "\"extras\":{\"source\":{\"quadratic\":1,\"cubic\":2}}}]}},\"asset\":"),
            "{\"camera\":0,", "{\"camera\":0,\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}},"),
       "lights[0].extras.source: unknown key \"cubic\""},
      {"light with zero attenuation", "atten.gltf",
       edit(edit(kBase, "\"asset\":",
                 "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\","
                 "\"extras\":{\"source\":{\"quadratic\":0}}}]}},\"asset\":"),
            "{\"camera\":0,", "{\"camera\":0,\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}},"),
       "nodes[1] light extensions.KHR_lights_punctual.lights[0]"},
      {".glb with bad magic", "bad.glb", "", "GLB header: bad magic"},
      {"missing scene file", "absent.gltf", "", "cannot open"},
  };
  for (const Bad &b : cases) {
    if (!b.text.empty()) write_file(b.file, b.text);
    const std::string path = g_dir + "/" + b.file;
    Scene s;
    s.path = "untouched";
    std::string err;
    const bool ok = load_scene(path, &s, &err);
    check(!ok && contains(err, path + ": ") && contains(err, b.place) && s.path == "untouched" && s.primitives.empty(),
          std::string("bad scene: ") + b.name, ok ? "loaded" : err);
  }
  // A good page: its size becomes the page size, its alpha 1, its path kept.
  write_file("lmok.gltf", extras("{\"lightmaps\":{\"image\":\"page.exr\"}}"));
  Scene s;
  std::string err;
  const bool ok = load_scene(g_dir + "/lmok.gltf", &s, &err);
  check(ok && s.lightmaps.page_w == 32 && s.lightmaps.page_h == 16 && s.lightmaps.image_rgba.size() == 32 * 16 * 4 &&
            s.lightmaps.image_rgba[1] == 0.25f && s.lightmaps.image_rgba[3] == 1.f &&
            contains(s.lightmaps.image, "page.exr"),
        "lightmaps.image: a 32 x 16 page read, its size the page size", err);
}

}  // namespace

int main() {
  test_model_lighting();
  test_world_lighting();
  test_hdr_atrium();
  char tmpl[] = "/tmp/test_scene_gltf.XXXXXX";
  if (!mkdtemp(tmpl)) {
    check(false, "mkdtemp");
  } else {
    g_dir = tmpl;
    test_good_minimal();
    test_bad_scenes();
    const std::string rm = "rm -rf '" + g_dir + "'";
    if (system(rm.c_str()) != 0) check(false, "remove " + g_dir);
  }
  return finish();
}

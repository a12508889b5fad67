// tiershade tests: the world-lighting features of the scene renderer, on scenes/world_lighting.gltf
// (the demo's and benchmark's lightmapped room):
//   - range fog (extras.tiershade.fog): read from the scene, refused with its place when bad, and
//     set as the world draws' fog uniforms (1 / range, start / range, colour, max density);
//   - views (glue/scene/views.h): "lightmaps" gives every world draw ENVMAP 0 and a white base,
//     "flat_lightmaps" also BUMPMAP 0 (scale 1), "final" the scene's own variants;
//   - the "float32" lightmap encoding: LIGHTMAP_ENCODING 0 with the page exactly as baked, where
//     "float" quantises it to half floats;
//   - bounces and emission: lightmaps.bounces / gather_rays and the glTF emissive terms read and
//     refused with their place; bounces and an emitting face only add light to the page;
//   - the double reference of world draws (scene_reference_linear): 0 on the background, equal to
//     the C fallback's float32-page sm3 frame within float rounding, and it includes the fog.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene/deferred.h"
#include "scene/frame.h"
#include "scene/prepare.h"
#include "scene/reference.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/views.h"
#include "families/world_lighting.h"
#include "unit_check.h"

namespace {

const char *kRoom = "scenes/world_lighting.gltf";

std::string read_text(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// *sel must outlive *p (the prepared draws point into it).
bool prepared(const Scene &s, Tier tier, int w, int h, SceneSelection *sel, PreparedScene *p, std::string *err) {
  return select_scene_variants(s, tier, "", sel, err) && prepare_scene(s, *sel, w, h, Api::GL33, 1.f, p, err);
}

void test_fog(const Scene &room, const std::string &path) {
  const SceneFog &f = room.fog;
  check(f.enabled && f.color[0] == 0.05f && f.color[2] == 0.06f && f.start == 3 && f.end == 15 &&
            f.max_density == 0.5f,
        "fog: read from extras.tiershade.fog");
  std::string err;
  SceneSelection sel;
  PreparedScene p;
  if (!prepared(room, Tier::SM3, 16, 8, &sel, &p, &err)) return check(false, "fog: prepare", err);
  bool slots = !p.draws.empty();
  for (const PreparedDraw &d : p.draws) {
    const ts_vec4f c = d.shared[WL_SLOT_FOG_COLOR], q = d.shared[WL_SLOT_FOG_PARAMS];
    slots = slots && d.world && c.x == 0.05f && c.w == 0.5f && q.x == static_cast<float>(1.0 / 12) &&
        q.y == static_cast<float>(3.0 / 12);
  }
  check(slots, "fog: every world draw's fog uniforms (colour, density, 1/range, start/range)");
  // Bad fog objects, each refused with its place.
  const std::string text = read_text(kRoom);
  const size_t at = text.find("\"fog\": {"), end = text.find('}', at);
  if (at == std::string::npos || end == std::string::npos) return check(false, "fog: the scene has a fog object");
  const size_t len = end + 1 - at;
  const struct {
    const char *fog, *expect;
  } bad[] = {
      {"\"fog\": {\"color\": [0.05, 0.05, 0.06], \"start\": 5.0, \"end\": 2.0}", "extras.tiershade.fog.end"},
      {"\"fog\": {\"start\": 3.0, \"end\": 15.0}", "missing \"color\""},
      {"\"fog\": {\"color\": [1, 1, 1], \"start\": 3.0, \"end\": 15.0, \"max_density\": 2}",
       "extras.tiershade.fog.max_density"},
      {"\"fog\": {\"color\": [1, 1, 1], \"start\": 3.0, \"end\": 15.0, \"density\": 1}", "density"},
      {"\"fog\": {\"color\": [-1, 1, 1], \"start\": 3.0, \"end\": 15.0}", "extras.tiershade.fog.color"},
  };
  for (const auto &b : bad) {
    std::string m = text;
    m.replace(at, len, b.fog);
    std::ofstream(path) << m;
    Scene s;
    err.clear();
    const bool ok = load_scene(path, &s, &err);
    unlink(path.c_str());
    check(!ok && err.find(path) == 0 && err.find(b.expect) != std::string::npos,
          std::string("fog: refused with its place: ") + b.fog, ok ? "accepted" : err);
  }
}

// The room's text with `from` replaced by `to` (the first occurrence), loaded from `path`.
bool load_edited(const std::string &path, const std::string &from, const std::string &to, Scene *s, std::string *err) {
  std::string text = read_text(kRoom);
  const size_t at = text.find(from);
  if (at == std::string::npos) {
    *err = "the room has no " + from;
    return false;
  }
  text.replace(at, from.size(), to);
  std::ofstream(path) << text;
  const bool ok = load_scene(path, s, err);
  unlink(path.c_str());
  return ok;
}

// Bounce settings and emission read from the scene; bounces add light to the page.
void test_bounces(const Scene &room, const std::string &path) {
  const std::string lux = "\"luxels_per_unit\": 8,";
  Scene s;
  std::string err;
  check(load_edited(path, lux, lux + " \"bounces\": 3, \"gather_rays\": 9, \"supersample\": 3,", &s, &err) &&
            s.lightmaps.quality.bounces == 3 && s.lightmaps.quality.gather_rays == 9 &&
            s.lightmaps.quality.supersample == 3 && room.lightmaps.quality.bounces == 0 &&
            room.lightmaps.quality.gather_rays == 64 && room.lightmaps.quality.supersample == 2,
        "bounces: lightmaps.bounces, gather_rays, supersample read (defaults 0, 64, 2)", err);
  for (const char *bad : {" \"bounces\": 101,", " \"gather_rays\": 0,", " \"supersample\": 9,"}) {
    err.clear();
    const bool ok = load_edited(path, lux, lux + bad, &s, &err);
    check(!ok && err.find("extras.tiershade.lightmaps.") != std::string::npos,
          std::string("bounces: refused with its place:") + bad, ok ? "accepted" : err);
  }
  const std::string mat = "\"name\": \"ceiling_plaster\",";
  err.clear();
  const bool emits = load_edited(path, mat,
                                 mat + " \"emissiveFactor\": [1, 0.5, 0.25], \"extensions\": "
                                       "{\"KHR_materials_emissive_strength\": {\"emissiveStrength\": 4}},",
                                 &s, &err);
  int ceiling = -1;
  for (size_t i = 0; i < s.materials.size(); ++i)
    if (s.materials[i].name == "ceiling_plaster") ceiling = static_cast<int>(i);
  check(emits && ceiling >= 0 && s.materials[ceiling].emission[0] == 4.f && s.materials[ceiling].emission[2] == 1.f,
        "emission: emissiveFactor x emissiveStrength", err);
  err.clear();
  Scene bad;
  const bool ok = load_edited(path, mat,
                              mat + " \"emissiveFactor\": [1, 1, 1], \"extensions\": "
                                    "{\"KHR_materials_emissive_strength\": {\"emissiveStrength\": -1}},",
                              &bad, &err);
  check(!ok && err.find("KHR_materials_emissive_strength.emissiveStrength") != std::string::npos,
        "emission: a negative strength is refused with its place", ok ? "accepted" : err);
  // The page: direct only, with two bounces, and with two bounces and the ceiling emitting.
  SceneSelection s0, s2, se;
  PreparedScene p0, p2, pe;
  Scene b2 = room, be = s;
  b2.lightmaps.quality.bounces = be.lightmaps.quality.bounces = 2;
  b2.lightmaps.quality.gather_rays = be.lightmaps.quality.gather_rays = 16;
  if (!prepared(room, Tier::SM3, 16, 8, &s0, &p0, &err) || !prepared(b2, Tier::SM3, 16, 8, &s2, &p2, &err) ||
      !prepared(be, Tier::SM3, 16, 8, &se, &pe, &err))
    return check(false, "bounces: prepare", err);
  bool never_less = true;
  double sum0 = 0, sum2 = 0, sume = 0;
  for (size_t i = 0; i < p0.lightmap_page.size(); ++i) {
    if (i % 4 == 3) continue;
    never_less = never_less && p2.lightmap_page[i] >= p0.lightmap_page[i] && pe.lightmap_page[i] >= p2.lightmap_page[i];
    sum0 += p0.lightmap_page[i];
    sum2 += p2.lightmap_page[i];
    sume += pe.lightmap_page[i];
  }
  check(never_less && sum2 > 1.05 * sum0 && sume > 1.05 * sum2,
        "bounces: light only adds (direct <= 2 bounces <= 2 bounces + an emitting ceiling)",
        std::to_string(sum0) + " " + std::to_string(sum2) + " " + std::to_string(sume));
}

void test_views(const Scene &room) {
  std::string err;
  SceneSelection fin, lm, flat;
  if (!select_scene_variants(room, Tier::SM3, "", &fin, &err) ||
      !select_scene_variants(scene_view(room, SceneView::Lightmaps), Tier::SM3, "", &lm, &err) ||
      !select_scene_variants(scene_view(room, SceneView::FlatLightmaps), Tier::SM3, "", &flat, &err))
    return check(false, "views: selection", err);
  bool env_fin = false, lm_ok = true, flat_ok = true, bump_kept = true;
  for (size_t i = 0; i < fin.draws.size(); ++i) {
    env_fin = env_fin || fin.draws[i].variant->value("ENVMAP") == 1;
    lm_ok = lm_ok && lm.draws[i].variant->value("ENVMAP") == 0;
    bump_kept = bump_kept && lm.draws[i].variant->value("BUMPMAP") == fin.draws[i].variant->value("BUMPMAP");
    flat_ok = flat_ok && flat.draws[i].variant->value("BUMPMAP") == 0 && flat.draws[i].variant->value("ENVMAP") == 0;
  }
  check(env_fin, "views: the final room has envmapped draws");
  check(lm_ok && bump_kept, "views: lightmaps: ENVMAP 0 everywhere, the bump modes kept");
  check(flat_ok, "views: flat_lightmaps: BUMPMAP 0 and ENVMAP 0 everywhere");
  SceneSelection sel;
  PreparedScene p;
  if (!prepared(scene_view(room, SceneView::FlatLightmaps), Tier::SM3, 16, 8, &sel, &p, &err))
    return check(false, "views: prepare flat", err);
  bool white = true, scale1 = true;
  for (const PreparedDraw &d : p.draws) {
    const TextureDesc &b = p.texture(d, 0);
    white = white && b.w == 1 && b.h == 1 && b.rgba[0] == 1.f && b.rgba[1] == 1.f && b.rgba[2] == 1.f;
    scale1 = scale1 && d.shared[WL_SLOT_TINT_SCALE].x == 1.f;
  }
  check(white && scale1, "views: flat_lightmaps: a white 1x1 base, lightmap scale 1");
  SceneView v;
  check(scene_view_from_name("lightmaps", &v) && v == SceneView::Lightmaps && !scene_view_from_name("lit", &v) &&
            std::string(scene_view_name(SceneView::FlatLightmaps)) == "flat_lightmaps",
        "views: names");
}

void test_float32(const Scene &room) {
  std::string err;
  Scene s32 = room, s16 = room;
  s32.lightmaps.encoding = "float32";
  s16.lightmaps.encoding = "float";
  SceneSelection a, b;
  PreparedScene p32, p16;
  if (!prepared(s32, Tier::SM3, 16, 8, &a, &p32, &err) || !prepared(s16, Tier::SM3, 16, 8, &b, &p16, &err))
    return check(false, "float32: prepare", err);
  const TextureDesc &t32 = p32.texture(p32.draws[0], 2), &t16 = p16.texture(p16.draws[0], 2);
  bool exact = t32.rgba.size() == p32.lightmap_page.size(), quantised = false;
  for (size_t i = 0; exact && i < t32.rgba.size(); ++i)
    if (i % 4 != 3) {
      exact = exact && t32.rgba[i] == p32.lightmap_page[i];
      quantised = quantised || t16.rgba[i] != p32.lightmap_page[i];
    }
  check(a.draws[0].variant->value("LIGHTMAP_ENCODING") == 0 && exact && t32.linear,
        "float32: LIGHTMAP_ENCODING 0, the page as baked, LINEAR");
  check(quantised, "float32: \"float\" quantises the same page (half floats)");
}

void test_reference(const Scene &room) {
  const int w = 96, h = 48;
  std::string err;
  Scene s = room;
  s.lightmaps.encoding = "float32";
  SceneGBufferCpu g;
  std::vector<double> ref;
  if (!scene_gbuffer_cpu(s, Tier::SM3, w, h, false, &g, &err) ||
      !scene_reference_linear(s, g.p, g.draw, g.slots, &ref, &err, 2))
    return check(false, "reference: world draws", err);
  const std::vector<int> &draw = g.draw;
  SceneRenderConfig cfg;  // the C fallback's frame of the same scene
  cfg.backend = Backend::CPU;
  cfg.w = w;
  cfg.h = h;
  cfg.mipmaps = false;  // the reference's records carry no derivatives: level 0, as scene_gbuffer_cpu
  SceneRenderResult res;
  if (!render_scene(s, g.sel, cfg, &res, &err)) return check(false, "reference: the C frame", err);
  const ImageF &f = res.lit;
  long covered = 0;
  bool bg = true;
  double m = 0;
  for (size_t q = 0; q < draw.size(); ++q) {
    if (draw[q] < 0) {
      bg = bg && ref[q * 3] == 0 && ref[q * 3 + 1] == 0 && ref[q * 3 + 2] == 0;
      continue;
    }
    ++covered;
    for (int c = 0; c < 3; ++c)
      m = std::max(m, std::fabs(ref[q * 3 + c] - f.rgba[q * 4 + c]) / std::max(1e-3, std::fabs(ref[q * 3 + c])));
  }
  check(covered > w * h / 2 && bg, "reference: the room covers the frame; 0 on any background",
        std::to_string(covered) + " pixels covered");
  // Tolerance: the float32 twin and the double twin run the same shading; the float frame's error is
  // its rounding (a few dozen float operations, 2^-24 each) plus llvmpipe's pow/exp2/log2
  // approximations in the float path (docs/c_math_layer.md: relative error ~1e-6 to 1e-5).
  check(m < 1e-4, "reference: world draws = the float32-page sm3 frame within float rounding",
        "max relative difference " + std::to_string(m));
  // The fog is part of the reference: without it the reference changes.
  Scene nofog = s;
  nofog.fog.enabled = false;
  SceneGBufferCpu g2;
  std::vector<double> ref2;
  if (!scene_gbuffer_cpu(nofog, Tier::SM3, w, h, false, &g2, &err) ||
      !scene_reference_linear(nofog, g2.p, g2.draw, g2.slots, &ref2, &err, 2))
    return check(false, "reference: without fog", err);
  double d = 0;
  for (size_t i = 0; i < ref.size(); ++i) d = std::max(d, std::fabs(ref[i] - ref2[i]));
  check(d > 1e-3, "reference: includes the range fog", "max difference " + std::to_string(d));
}

}  // namespace

int main() {
  ts_math_init();
  Scene room;
  std::string err;
  if (!load_scene(kRoom, &room, &err)) {
    check(false, "load the room", err);
  } else {
    // The bad-fog scenes sit beside the room, so that its buffer and textures resolve.
    test_fog(room, "scenes/.test_scene_world_" + std::to_string(getpid()) + ".gltf");
    test_bounces(room, "scenes/.test_scene_world_" + std::to_string(getpid()) + ".gltf");
    test_views(room);
    test_float32(room);
    test_reference(room);
  }
  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed ? 1 : 0;
}

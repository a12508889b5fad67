// tiershade tests: the light choice is per model, as Source's is (fact sheet section 4: each model
// gets the few lights most important at its position, the others folded into its ambient cube;
// docs/light_folding.md). A scene built in memory: two small models 200 units apart, four point
// lights around each. On every tier each model's draw keeps only lights of its own group (the
// tier's limit: 2 on ps20, 4 on ps2b/sm3) and folds the other group into its ambient cube; the
// two draws' kept lights differ. A per-scene choice (one set for every draw) fails this test.
// And a row of 12 instances of one shared mesh (object-space geometry, a translation each:
// glue/scene/scene.h) under 24 lights of different strengths scattered along it: every draw keeps
// exactly the tier's limit of lights with the largest incident luminance at its own instance's
// centre (ranked here from ts_light_incident, independently of ts_fold_lights' loop), in index
// order; sharing the geometry does not share the choice.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
#include <algorithm>
#include <cmath>
#include <memory>
#include <cstdio>
#include <string>

#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "twins/model_lighting.h"
#include "unit_check.h"

namespace {

// A small triangle model centred at (cx, 0, 0) facing +Z, from node instance `inst`.
void add_model(Scene *s, double cx, int inst) {
  SceneInstance in;
  in.name = "model_" + std::to_string(inst);
  for (int i = 0; i < 16; ++i) in.world[i] = (i % 5 == 0) ? 1 : 0;
  in.world[12] = cx;
  in.center[0] = cx;
  in.center[1] = in.center[2] = 0;
  s->instances.push_back(in);
  ScenePrimitive p;
  p.material = 0;
  p.instance = inst;
  const float x = static_cast<float>(cx);
  p.position = {x - 0.5f, -0.5f, 0.f, x + 0.5f, -0.5f, 0.f, x, 0.5f, 0.f};
  p.normal = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  p.uv = {0, 0, 1, 0, 0.5f, 1};
  p.indices = {0, 1, 2};
  p.where = "meshes[" + std::to_string(inst) + "].primitives[0]";
  s->primitives.push_back(p);
}

// A point light at (x, y, z), colour c, 1/d^2 falloff.
void add_light(Scene *s, float x, float y, float z, float c, const std::string &name) {
  SceneLight l;
  l.name = name;
  l.light = ts_light{};
  l.light.type = TS_LIGHT_POINT;
  l.light.color[0] = l.light.color[1] = l.light.color[2] = c;
  l.light.pos[0] = x;
  l.light.pos[1] = y;
  l.light.pos[2] = z;
  l.light.atten[0] = 0;
  l.light.atten[1] = 0;
  l.light.atten[2] = 1;
  s->lights.push_back(l);
}

Scene two_models() {
  Scene s;
  s.path = "<two models>";
  SceneMaterial m;
  m.name = "plain";
  m.where = "materials[0]";
  s.materials.push_back(m);
  add_model(&s, -100, 0);
  add_model(&s, 100, 1);
  // Four lights near each model, of different strengths (so that the tier's limit keeps the
  // brightest of its own group); lights 0-3 around the left model, 4-7 around the right one.
  for (int g = 0; g < 2; ++g) {
    const float cx = g == 0 ? -100.f : 100.f;
    for (int i = 0; i < 4; ++i)
      add_light(&s, cx + (i % 2 ? 1.5f : -1.5f), i < 2 ? 1.5f : -1.5f, 2.f, 4.f + i, "lamp_" + std::to_string(g * 4 + i));
  }
  SceneCamera cam;
  cam.name = "view";
  cam.eye[0] = 0, cam.eye[1] = 0, cam.eye[2] = 300;
  cam.forward[0] = 0, cam.forward[1] = 0, cam.forward[2] = -1;
  cam.up[0] = 0, cam.up[1] = 1, cam.up[2] = 0;
  cam.zfar = 1000;
  s.cameras.push_back(cam);
  SceneAmbientSample a{};
  a.position[0] = a.position[1] = a.position[2] = 0;
  s.ambient.push_back(a);  // a black ambient cube: what is in a draw's cube was folded into it
  return s;
}

// The x positions of the lights a prepared model draw shades per pixel (the packed slots: [2] = pos).
std::vector<float> kept_x(const PreparedDraw &d) {
  std::vector<float> xs;
  const int nk = static_cast<int>(d.shared[ML_SLOT_PARAMS].y);
  for (int i = 0; i < nk; ++i) xs.push_back(d.shared[ML_SLOT_LIGHT0 + 5 * i + 2].x);
  return xs;
}

void test_tier(const Scene &s, Tier tier) {
  const std::string t = tier_name(tier);
  SceneSelection sel;
  PreparedScene p;
  std::string err;
  if (!select_scene_variants(s, tier, "", &sel, &err) || !prepare_scene(s, sel, 64, 32, Api::GL33, 1.f, &p, &err))
    return check(false, "lights per model " + t + ": prepared", err);
  if (p.draws.size() != 2) return check(false, "lights per model " + t + ": two draws", std::to_string(p.draws.size()));
  const int limit = max_local_lights(tier);
  std::vector<float> k[2];
  for (int di = 0; di < 2; ++di) {
    const PreparedDraw &d = p.draws[static_cast<size_t>(di)];
    k[di] = kept_x(d);
    const float cx = di == 0 ? -100.f : 100.f;
    bool own = static_cast<int>(k[di].size()) == limit;
    std::string detail = "kept x:";
    for (float x : k[di]) {
      own = own && std::fabs(x - cx) < 2.f;
      detail += " " + std::to_string(x);
    }
    check(own, "lights per model " + t + ": draw " + std::to_string(di) + " keeps " + std::to_string(limit) +
              " lights of its own group", detail);
    // The folded lights (its own group's weakest beyond the limit, and the far group) are in its
    // ambient cube: the cube faces toward +Z (the lights are at z = +2) are lit, not black.
    const ts_vec4f pz = d.shared[ML_SLOT_AMBIENT + 4];
    check(pz.x > 0 && pz.y > 0 && pz.z > 0, "lights per model " + t + ": draw " + std::to_string(di) +
              ": the folded lights are in its ambient cube (+Z face)", std::to_string(pz.x));
  }
  check(k[0] != k[1], "lights per model " + t + ": the two models keep different lights");
}

// 12 instances of one shared triangle mesh along x (spacing 6), 24 point lights of strengths
// 1..24 at pseudo-random places along the row.
Scene shared_row() {
  Scene s = two_models();
  s.primitives.clear();
  s.instances.clear();
  s.lights.clear();
  auto geo = std::make_shared<SceneGeometry>();
  geo->position = {-0.5f, -0.5f, 0.f, 0.5f, -0.5f, 0.f, 0.f, 0.5f, 0.f};
  geo->normal = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  geo->uv = {0, 0, 1, 0, 0.5f, 1};
  geo->indices = {0, 1, 2};
  for (int i = 0; i < 12; ++i) {
    SceneInstance in;
    in.name = "row_" + std::to_string(i);
    for (int k = 0; k < 16; ++k) in.world[k] = (k % 5 == 0) ? 1 : 0;
    in.world[12] = -33 + 6 * i;
    in.center[0] = in.world[12];
    in.center[1] = in.center[2] = 0;
    s.instances.push_back(in);
    ScenePrimitive p;
    p.material = 0;
    p.instance = i;
    p.shared = geo;
    p.model[12] = static_cast<float>(in.world[12]);
    p.where = "meshes[0].primitives[0] (node row_" + std::to_string(i) + ")";
    s.primitives.push_back(p);
  }
  uint32_t r = 12345;
  auto next = [&r] {
    r = r * 1664525u + 1013904223u;
    return static_cast<float>(r >> 8) / 16777216.f;
  };
  for (int l = 0; l < 24; ++l)
    add_light(&s, -36 + 72 * next(), -2 + 4 * next(), 1 + 3 * next(), 1.f + l, "lamp_" + std::to_string(l));
  return s;
}

void test_shared_row(const Scene &s, Tier tier) {
  const std::string t = tier_name(tier);
  SceneSelection sel;
  PreparedScene p;
  std::string err;
  if (!select_scene_variants(s, tier, "", &sel, &err) || !prepare_scene(s, sel, 64, 32, Api::GL33, 1.f, &p, &err))
    return check(false, "lights per shared instance " + t + ": prepared", err);
  const size_t limit = static_cast<size_t>(max_local_lights(tier));
  int right = 0;
  std::string detail;
  std::vector<std::vector<float>> all;
  for (const PreparedDraw &d : p.draws) {
    const ScenePrimitive &pr = s.primitives[static_cast<size_t>(d.choice->primitive)];
    const double *c = s.instances.at(static_cast<size_t>(pr.instance)).center;
    const float cf[3] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
    std::vector<std::pair<double, int>> lum;  // (-luminance, index): sorted, the brightest first
    for (size_t l = 0; l < s.lights.size(); ++l) {
      double rgb[3], dir[3];
      ts_light_incident(&s.lights[l].light, cf, rgb, dir);
      lum.push_back({-(0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]), static_cast<int>(l)});
    }
    std::sort(lum.begin(), lum.end());
    std::vector<int> want;
    for (size_t k = 0; k < limit; ++k) want.push_back(lum[k].second);
    std::sort(want.begin(), want.end());
    std::vector<float> want_x;
    for (int l : want) want_x.push_back(s.lights[static_cast<size_t>(l)].light.pos[0]);
    const std::vector<float> got = kept_x(d);
    if (got == want_x) ++right;
    else detail += " draw at x " + std::to_string(c[0]);
    all.push_back(got);
  }
  check(p.draws.size() == 12 && right == 12,
        "lights per shared instance " + t + ": each of 12 draws keeps the " + std::to_string(limit) +
            " lights brightest at its centre",
        std::to_string(right) + " right;" + detail);
  std::sort(all.begin(), all.end());
  const size_t distinct = static_cast<size_t>(std::unique(all.begin(), all.end()) - all.begin());
  check(distinct >= 4, "lights per shared instance " + t + ": the instances keep different lights",
        std::to_string(distinct) + " distinct sets");
}

}  // namespace

int main() {
  const Scene s = two_models();
  for (Tier t : {Tier::PS20, Tier::PS2B, Tier::SM3}) test_tier(s, t);
  const Scene row = shared_row();
  for (Tier t : {Tier::PS20, Tier::PS2B, Tier::SM3}) test_shared_row(row, t);
  return finish();
}

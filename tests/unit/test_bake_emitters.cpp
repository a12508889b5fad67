// tiershade tests: emitters of any shape as area lights (glue/bake/area_lights.h) against closed forms,
// on the 4 x 4 floor (8 luxels per unit: 33 x 33) under a disc of radius 0.5 at height 1.5 made of 64
// triangles, facing down, of radiance Le:
//   - Arvo's spherical-triangle map: every direction inside the triangle, the sub-triangle to a
//     vertex and the opposite arc's midpoint taking its share of the area, and the mean cosine of the
//     directions times the solid angle equal to Lambert's form factor (the edge sum);
//   - the disc as a model primitive: every luxel's flat value is Le times the point-to-polygon form
//     factor (Lambert's formula: F = |sum_i theta_i u_i . n| / (2 pi), computed here on its own) to
//     1e-9, and the centre luxel's Le R^2 / (R^2 + h^2) (the disc's) within the 64-gon's deficit
//     (its area is 0.16 % below the disc's: 0.3 % allowed);
//   - an occluder over x >= 0 at height 0.75: the centre luxel sees exactly half the disc (by
//     symmetry; 3 % allowed for 256 stratified shadow rays across the edge), the luxel at x = -1 the
//     whole disc (its rays all pass at x < 0: exact), the luxel at x = +1 nothing;
//   - the same bytes for 1 and 2 threads;
//   - the disc as a TEXCOORD_1 chart (a lightmapped world mesh): the same values at the centre;
//   - the bounces: with the emission sampled, a bounce adds nothing to a floor that sees no
//     reflector (no emission twice); with area lights off, the first bounce's gather rays find the
//     model and its light agrees with the sampled one (mean over the 9 x 9 central luxels, 1024 rays
//     each: about 1 % noise, 4 % allowed);
//   - the irradiance volume's ray sees the model's front (Le) and passes its back;
//   - the scene path: world_lighting's room with an emissive model quad added lights the ceiling above.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bake/area_lights.h"
#include "bake/irradiance_volume.h"
#include "bake/ray_scene.h"
#include "bake/world_bake.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "unit_check.h"

namespace {

const double kR = 0.5, kH = 1.5, kLe = 2.0;
const int kSeg = 64;

// The disc's fan: 3 floats per vertex (the centre first), its normals (down), its triangles.
void disc(std::vector<float> *pos, std::vector<float> *nrm, std::vector<uint32_t> *idx, std::vector<float> *uv1) {
  *pos = {0.f, static_cast<float>(kH), 0.f};
  *nrm = {0.f, -1.f, 0.f};
  *uv1 = {0.5f, 0.5f};
  for (int k = 0; k < kSeg; ++k) {
    const double ph = 2 * M_PI * k / kSeg;
    pos->insert(pos->end(), {static_cast<float>(kR * std::cos(ph)), static_cast<float>(kH),
                             static_cast<float>(kR * std::sin(ph))});
    nrm->insert(nrm->end(), {0.f, -1.f, 0.f});
    uv1->insert(uv1->end(), {static_cast<float>(0.5 + 0.5 * std::cos(ph)), static_cast<float>(0.5 + 0.5 * std::sin(ph))});
  }
  idx->clear();
  for (int k = 0; k < kSeg; ++k)
    idx->insert(idx->end(), {0u, static_cast<uint32_t>(1 + k), static_cast<uint32_t>(1 + (k + 1) % kSeg)});
}

// Lambert's point-to-polygon form factor (the polygon wholly above the receiver's plane).
double lambert(const std::vector<glm::dvec3> &poly, const glm::dvec3 &p, const glm::dvec3 &n) {
  double sum = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a = glm::normalize(poly[i] - p), b = glm::normalize(poly[(i + 1) % poly.size()] - p);
    const glm::dvec3 c = glm::cross(a, b);
    sum += std::acos(std::fmax(-1.0, std::fmin(1.0, glm::dot(a, b)))) * glm::dot(n, glm::normalize(c));
  }
  return std::fabs(sum) / (2 * M_PI);
}

std::vector<glm::dvec3> rim() {
  std::vector<glm::dvec3> r;
  for (int k = 0; k < kSeg; ++k) {
    const double ph = 2 * M_PI * k / kSeg;
    r.emplace_back(kR * std::cos(ph), kH, kR * std::sin(ph));
  }
  return r;
}

void spherical_triangles() {
  const glm::dvec3 a = glm::normalize(glm::dvec3(0.2, 1, 0.1)), b = glm::normalize(glm::dvec3(1, 0.6, -0.3)),
                   c = glm::normalize(glm::dvec3(-0.4, 0.8, 0.9));
  const SphericalTri t = spherical_tri(a, b, c);
  const glm::dvec3 m = glm::normalize(b + c);  // the midpoint of the arc b-c
  const SphericalTri half = spherical_tri(a, b, m);
  const glm::dvec3 n0 = glm::cross(a, b), n1 = glm::cross(b, c), n2 = glm::cross(c, a);
  const double side = glm::dot(n0, c) > 0 ? 1 : -1;
  const bool bside = glm::dot(glm::cross(a, m), b) >= 0;
  const int N = 256;
  long inside = 0, in_half = 0;
  double cos_sum = 0;
  const glm::dvec3 axis(0, 1, 0);
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      const glm::dvec3 w = spherical_tri_dir(t, (i + 0.5) / N, (j + 0.5) / N);
      inside += side * glm::dot(n0, w) >= -1e-12 && side * glm::dot(n1, w) >= -1e-12 && side * glm::dot(n2, w) >= -1e-12;
      in_half += (glm::dot(glm::cross(a, m), w) >= 0) == bside;  // on b's side of the arc a-m
      cos_sum += glm::dot(axis, w);
    }
  check(inside == N * N, "Arvo's map: every direction inside the spherical triangle",
        std::to_string(N * N - inside) + " outside");
  const double share = static_cast<double>(in_half) / (N * N), want = half.area / t.area;
  check(std::fabs(share - want) < 0.01, "Arvo's map: the sub-triangle to the arc's midpoint takes its share of the area",
        std::to_string(share) + " of the directions, its area " + std::to_string(want));
  const double f = t.area * cos_sum / (N * N) / M_PI, fl = lambert({a, b, c}, glm::dvec3(0.0), axis);
  check(std::fabs(f - fl) < 1e-3 * fl, "Arvo's map: solid angle x the mean cosine = Lambert's form factor",
        std::to_string(f) + " against " + std::to_string(fl));
}

struct Setup {
  std::vector<float> pos, nrm, uv1;
  std::vector<uint32_t> idx;
  RayScene rays;
  WorldBakeInput in;
  WorldBake out;
  bool ok = false;
};

WorldFace floor_face(double reflectivity) {
  WorldFace f{"floor", ts_v3d(-2, 0, 2), ts_v3d(1, 0, 0), ts_v3d(0, 0, -1), 4, 4, -1, ts_v3d(0, 1, 0)};
  f.reflectivity = ts_v3d(reflectivity, reflectivity, reflectivity);
  f.bumped = false;
  return f;
}

// The floor under the disc as a model emitter; `occluder`: the quad x in [0, 3], |z| <= 3 at 0.75.
void bake_model(Setup *s, bool occluder, int samples, int threads, int bounces = 0, int gather = 64,
                double reflectivity = 0) {
  disc(&s->pos, &s->nrm, &s->idx, &s->uv1);
  std::string err;
  const std::vector<float> fl = {-2, 0, 2, 2, 0, 2, 2, 0, -2, -2, 0, -2};
  bool ok = s->rays.add_mesh(fl, {0, 1, 2, 0, 2, 3}, 0, "floor", &err) &&
      s->rays.add_mesh(s->pos, s->idx, model_emitter_id(0), "disc", &err);
  if (occluder) ok = ok && s->rays.add_mesh({0, 0.75f, -3, 3, 0.75f, -3, 3, 0.75f, 3, 0, 0.75f, 3}, {0, 1, 2, 0, 2, 3}, -2, "occluder", &err);
  ok = ok && s->rays.commit(&err);
  if (!ok) return check(false, "ray scene", err);
  s->in.faces = {floor_face(reflectivity)};
  s->in.model_emitters = {model_emitter(s->pos, s->nrm, s->idx, false, ts_v3d(kLe, kLe, kLe), "disc")};
  s->in.probes = {ts_v3d(0, 1, 0)};
  s->in.luxels_per_unit = 8;
  s->in.page_w = 256;
  s->in.page_h = 64;
  s->in.cube_size = 4;
  s->in.rays = &s->rays;
  s->in.area_samples = samples;
  s->in.bounce.threads = threads;
  s->in.bounce.max_bounces = bounces;
  s->in.bounce.gather_rays = gather;
  s->in.bounce.threshold = 0;
  s->ok = bake_world(s->in, &s->out, &err);
  if (!s->ok) check(false, "bake the floor under the disc", err);
}

double flat(const Setup &s, int face, int i, int j) {
  int tx, ty;
  lm_page_texel(&s.out.place[face], 0, i, j, &tx, &ty);
  return s.out.page[(static_cast<size_t>(ty) * s.in.page_w + tx) * 4];
}

// Luxel (i, j)'s point as area_lights takes it (the grid point, 1e-4 off the floor).
glm::dvec3 luxel_p(int i, int j) {
  const double inset = kWorldSampleInset / 4;
  const double a = std::fmin(1 - inset, std::fmax(inset, i / 32.0)), b = std::fmin(1 - inset, std::fmax(inset, j / 32.0));
  return glm::dvec3(-2 + 4 * a, 1e-4, 2 - 4 * b);
}

void model_disc() {
  Setup s;
  bake_model(&s, false, 16, 0);
  if (!s.ok) return;
  double worst = 0;
  for (int j = 0; j < 33; ++j)
    for (int i = 0; i < 33; ++i) {
      const double want = kLe * lambert(rim(), luxel_p(i, j), glm::dvec3(0, 1, 0));
      worst = std::fmax(worst, std::fabs(flat(s, 0, i, j) - want) / want);
    }
  check(worst < 1e-6 && s.out.area.emitters == 1 && s.out.area.meshes == 1,
        "model disc: every luxel is Le x Lambert's form factor of the 64-gon (1e-6: the page is float32)",
        "worst relative " + std::to_string(worst));
  const double h = kH - 1e-4, disc_f = kR * kR / (kR * kR + h * h), c = flat(s, 0, 16, 16) / kLe;
  check(c < disc_f && c > disc_f * (1 - 3e-3), "model disc: the centre luxel is Le R^2 / (R^2 + h^2) within 0.3 %",
        std::to_string(c) + " against the disc's " + std::to_string(disc_f));
}

void occluded() {
  Setup s, s2;
  bake_model(&s, true, 256, 1);
  bake_model(&s2, true, 256, 2);
  if (!s.ok || !s2.ok) return;
  const double full = kLe * lambert(rim(), luxel_p(16, 16), glm::dvec3(0, 1, 0));
  const double c = flat(s, 0, 16, 16);
  check(std::fabs(c / full - 0.5) < 0.03 * 0.5, "occluder over x >= 0: the centre luxel sees half the disc (3 %)",
        std::to_string(c / full) + " of the unoccluded value");
  const double left = kLe * lambert(rim(), luxel_p(8, 16), glm::dvec3(0, 1, 0));
  check(std::fabs(flat(s, 0, 8, 16) - left) < 1e-6 * left && flat(s, 0, 24, 16) == 0,
        "occluder: the luxel at x = -1 sees the whole disc, at x = +1 none of it",
        std::to_string(flat(s, 0, 8, 16) / left) + ", " + std::to_string(flat(s, 0, 24, 16)));
  check(s.out.page == s2.out.page && s.out.area.rays == s2.out.area.rays, "model disc with an occluder: the same bytes on 1 and 2 threads");
}

void chart_disc() {
  Setup s;
  disc(&s.pos, &s.nrm, &s.idx, &s.uv1);
  std::string err;
  WorldFace lamp{};
  if (!world_face_from_chart(s.pos, s.nrm, {}, s.uv1, s.idx, "lamp", -1, 8, "lamp", &lamp, &err))
    return check(false, "chart the disc", err);
  lamp.emission = ts_v3d(kLe, kLe, kLe);
  const std::vector<float> fl = {-2, 0, 2, 2, 0, 2, 2, 0, -2, -2, 0, -2};
  std::vector<uint32_t> seq(s.idx.size());
  std::vector<float> corners;  // the chart's triangles as the bake's own face_rays adds them, in order
  for (size_t k = 0; k < s.idx.size(); ++k) {
    seq[k] = static_cast<uint32_t>(k);
    for (int c = 0; c < 3; ++c) corners.push_back(s.pos[s.idx[k] * 3 + c]);
  }
  if (!s.rays.add_mesh(fl, {0, 1, 2, 0, 2, 3}, 0, "floor", &err) || !s.rays.add_mesh(corners, seq, 1, "lamp", &err) ||
      !s.rays.commit(&err))
    return check(false, "ray scene", err);
  s.in.faces = {floor_face(0), lamp};
  s.in.probes = {ts_v3d(0, 1, 0)};
  s.in.luxels_per_unit = 8;
  s.in.page_w = 256;
  s.in.page_h = 64;
  s.in.cube_size = 4;
  s.in.rays = &s.rays;
  if (!bake_world(s.in, &s.out, &err)) return check(false, "bake the floor under the chart lamp", err);
  const double want = kLe * lambert(rim(), luxel_p(16, 16), glm::dvec3(0, 1, 0));
  check(std::fabs(flat(s, 0, 16, 16) - want) < 1e-6 * want && s.out.area.meshes == 1,
        "TEXCOORD_1 chart lamp: the centre luxel is Le x Lambert's form factor",
        std::to_string(flat(s, 0, 16, 16)) + " against " + std::to_string(want));
}

void bounces() {
  Setup sampled, gathered;
  bake_model(&sampled, false, 16, 0, 1, 64, 0.5);
  bake_model(&gathered, false, 0, 0, 1, 1024, 0.5);
  if (!sampled.ok || !gathered.ok) return;
  check(sampled.out.bounce.passes == 1 && sampled.out.bounce.added.size() == 1 && sampled.out.bounce.added[0] == 0,
        "emission sampled: the bounce adds nothing to a floor that sees no reflector (no emission twice)",
        "largest added " + std::to_string(sampled.out.bounce.added.empty() ? -1 : sampled.out.bounce.added[0]));
  double a = 0, b = 0;
  for (int j = 12; j <= 20; ++j)
    for (int i = 12; i <= 20; ++i) a += flat(sampled, 0, i, j), b += flat(gathered, 0, i, j);
  check(std::fabs(b / a - 1) < 0.04, "area lights off: the first bounce's gather rays find the model (4 %)",
        "gathered / sampled " + std::to_string(b / a));
}

void volume_rays() {
  Setup s;
  bake_model(&s, false, 16, 0);
  if (!s.ok) return;
  VolumeSettings set;
  std::vector<LuxelGrid> grids(1);
  grids[0].w = grids[0].h = 33;
  grids[0].v.assign(33 * 33 * 4, ts_v3d(0, 0, 0));
  const glm::dvec3 none = volume_ray_radiance(glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0), s.in.faces, grids, s.rays, set, nullptr);
  set.model_emitters = &s.in.model_emitters;
  bool back = true;
  const glm::dvec3 up = volume_ray_radiance(glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0), s.in.faces, grids, s.rays, set, &back);
  const glm::dvec3 down = volume_ray_radiance(glm::dvec3(0, 2, 0), glm::dvec3(0, -1, 0), s.in.faces, grids, s.rays, set, nullptr);
  check(up == glm::dvec3(kLe) && !back && none == glm::dvec3(0.0) && down == glm::dvec3(0.0),
        "irradiance volume: a ray sees the emissive model's front (Le), passes its back to the floor",
        std::to_string(up.x) + ", without the emitters " + std::to_string(none.x) + ", from above " + std::to_string(down.x));
}

// The scene path (glue/scene/bake_inputs.cpp, prepare.cpp): world_lighting's room with a small model
// quad (the floor's, 0.4 x 0.3, facing up, 0.3 above the floor at the room's centre) of emission 50:
// it is found as a model emitter (the bake samples two meshes: it and the ceiling lamp) and lights the
// ceiling above it by about Le A / (pi d^2) (a small square 2.7 below: 0.26; 25 % allowed for the
// square's size and the luxel grid); the bake hash's materials change with its emission.
void scene_model() {
  Scene room;
  std::string err;
  if (!load_scene("scenes/world_lighting.gltf", &room, &err)) return check(false, "load world_lighting", err);
  SceneMaterial mm;
  mm.name = "emissive_model";
  mm.where = "materials[test]";
  mm.shader = SceneShader::Model;
  room.materials.push_back(mm);
  ScenePrimitive model = room.primitives[0];  // the floor quad, x [-4, 4], z [-3, 3], facing up
  model.material = static_cast<int>(room.materials.size()) - 1;
  model.instance = -1;
  model.where = "test model";
  for (size_t i = 0; i < model.position.size(); i += 3) {
    model.position[i] *= 0.05f;
    model.position[i + 1] = 0.3f;
    model.position[i + 2] = model.position[i + 2] * 0.05f + 0.5f;
  }
  room.primitives.push_back(model);
  room.lights.clear();  // (the lamps' light would drown the gain)
  auto bake = [&](float le, PreparedScene *ps) {
    room.materials.back().emission[0] = room.materials.back().emission[1] = room.materials.back().emission[2] = le;
    SceneSelection sel;
    return select_scene_variants(room, Tier::SM3, "", &sel, &err) &&
        prepare_scene(room, sel, 16, 16, Api::GL33, 1.f, ps, &err);
  };
  PreparedScene lit, dark;
  if (!bake(50.f, &lit) || !bake(0.f, &dark)) return check(false, "prepare the room with an emissive model", err);
  // The ceiling (face 1): its flat block's largest gain.
  const lm_face_place &pl = lit.lightmap_places.at(1);
  double gain = 0;
  for (int j = 0; j < pl.block_h - 2; ++j)
    for (int i = 0; i < pl.block_w - 2; ++i) {
      int tx, ty;
      lm_page_texel(&pl, 0, i, j, &tx, &ty);
      const size_t t = (static_cast<size_t>(ty) * lit.lightmap_w + tx) * 4;
      gain = std::fmax(gain, lit.lightmap_page[t] - dark.lightmap_page[t]);
    }
  const double want = 50 * 0.4 * 0.3 / (M_PI * 2.7 * 2.7);
  check(lit.bake_summary.area_pass.meshes == 2 && lit.bake_summary.model_emitters == 1 &&
            std::fabs(gain / want - 1) < 0.25 && lit.bake_summary.hash.materials != dark.bake_summary.hash.materials,
        "scene: an emissive model primitive lights the ceiling above it by Le A / (pi d^2) (25 %)",
        "gain " + std::to_string(gain) + " against " + std::to_string(want) + ", " +
            std::to_string(lit.bake_summary.area_pass.meshes) + " meshes");
}

}  // namespace

int main() {
  ts_math_init();
  spherical_triangles();
  model_disc();
  occluded();
  chart_disc();
  bounces();
  volume_rays();
  scene_model();
  return finish();
}

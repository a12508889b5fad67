// tiershade tests: the irradiance volume (glue/bake/irradiance_volume.cpp): its 162 ray directions,
// a closed emitting room gives its emission everywhere, a model is passed through (the default) or
// (models_occlude) stops the rays, a sample inside a solid is invalid and never
// used, a point moving in small steps changes its cube by a bounded amount per step, and the
// inverse-square option reproduces Source's 1/(d^2 + 1) on a hand case.
#include <cmath>
#include <cstring>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake/irradiance_volume.h"
#include "bake/ray_scene.h"
#include "bake/world_faces.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "twins/model_lighting.h"
#include "unit_check.h"

namespace {
// The six faces of the box [lo, hi]; inward: normals into the box (a room), else out of it (a solid).
void add_box(const glm::dvec3 &lo, const glm::dvec3 &hi, bool inward, const glm::dvec3 emission[6],
             std::vector<WorldFace> *faces) {
  static const char *names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      WorldFace f{};
      f.name = names[a * 2 + s];
      glm::dvec3 o = lo;
      o[a] = s ? hi[a] : lo[a];
      glm::dvec3 u(0.0), v(0.0), n(0.0);
      u[b] = 1;
      v[c] = 1;
      n[a] = (s ? -1.0 : 1.0) * (inward ? 1.0 : -1.0);
      f.origin = ts_v3d(o.x, o.y, o.z);
      f.u = ts_v3d(u.x, u.y, u.z);
      f.v = ts_v3d(v.x, v.y, v.z);
      f.su = hi[b] - lo[b];
      f.sv = hi[c] - lo[c];
      f.probe = -1;
      f.normal = ts_v3d(n.x, n.y, n.z);
      f.reflectivity = ts_v3d(0.5, 0.5, 0.5);
      const glm::dvec3 e = emission[a * 2 + s];
      f.emission = ts_v3d(e.x, e.y, e.z);
      faces->push_back(f);
    }
}

bool build_rays(const std::vector<WorldFace> &faces, RayScene *rays, std::string *err) {
  for (size_t i = 0; i < faces.size(); ++i) {
    const WorldFace &f = faces[i];
    const glm::dvec3 o(f.origin.x, f.origin.y, f.origin.z), u = glm::dvec3(f.u.x, f.u.y, f.u.z) * f.su,
                     v = glm::dvec3(f.v.x, f.v.y, f.v.z) * f.sv;
    std::vector<float> p;
    for (const glm::dvec3 &q : {o, o + u, o + u + v, o + v})
      for (int k = 0; k < 3; ++k) p.push_back(static_cast<float>(q[k]));
    if (!rays->add_mesh(p, {0, 1, 2, 0, 2, 3}, static_cast<int>(i), f.name, err)) return false;
  }
  return rays->commit(err);
}

std::string cube_sum_text(const float c[6][3]) {
  char b[200];
  snprintf(b, sizeof b, "+X %.4g %.4g %.4g, +Y %.4g %.4g %.4g, -Y %.4g %.4g %.4g", c[0][0], c[0][1], c[0][2], c[2][0],
           c[2][1], c[2][2], c[3][0], c[3][1], c[3][2]);
  return b;
}

// Dark luxel grids (2 x 2 luxels per face): a face's radiosity is then its emission alone.
std::vector<LuxelGrid> dark_grids(size_t n) {
  std::vector<LuxelGrid> g(n);
  for (LuxelGrid &x : g) {
    x.w = x.h = 2;
    x.v.assign(16, ts_v3d(0, 0, 0));
  }
  return g;
}
}  // namespace

int main() {
  std::string err;
  // 1. The directions: 162 distinct unit vectors, symmetric (their sum is zero).
  {
    const std::vector<glm::dvec3> &d = volume_ray_directions();
    glm::dvec3 sum(0.0);
    double worst_len = 0, closest = 10;
    for (size_t i = 0; i < d.size(); ++i) {
      sum += d[i];
      worst_len = std::fmax(worst_len, std::fabs(glm::length(d[i]) - 1));
      for (size_t j = 0; j < i; ++j) closest = std::fmin(closest, glm::length(d[i] - d[j]));
    }
    check(d.size() == 162 && worst_len < 1e-12 && closest > 0.1 && glm::length(sum) < 1e-9,
          "162 distinct unit ray directions, symmetric",
          std::to_string(d.size()) + " dirs, closest pair " + std::to_string(closest));
  }
  // 2. A closed room whose walls all emit L (reflectivity 0.5, dark lightmaps): every ray sees L, so
  //    every sample is valid and its cube is L (mean: exact ratio; lsq: its quadrature is normalised
  //    on constants; tolerance 1e-6 relative for float rounding).
  const glm::dvec3 L(0.3, 0.6, 0.9);
  for (AmbientFit fit : {AmbientFit::Mean, AmbientFit::Lsq}) {
    std::vector<WorldFace> faces;
    const glm::dvec3 em[6] = {L, L, L, L, L, L};
    add_box(glm::dvec3(0, 0, 0), glm::dvec3(4, 3, 5), true, em, &faces);
    RayScene rays;
    if (!build_rays(faces, &rays, &err)) {
      check(false, "room ray scene", err);
      break;
    }
    VolumeSettings set;
    set.fit = fit;
    IrradianceVolume v;
    const double lo[3] = {0, 0, 0}, hi[3] = {4, 3, 5};
    if (!bake_irradiance_volume(lo, hi, faces, dark_grids(faces.size()), rays, set, &v, &err)) {
      check(false, "room volume bake", err);
      break;
    }
    double worst = 0;
    bool all_valid = true;
    for (size_t s = 0; s < v.cube.size(); ++s) {
      all_valid = all_valid && v.valid[s];
      for (int f = 0; f < 6; ++f)
        for (int c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs(v.cube[s][f][c] - L[c]) / L[c]);
    }
    char d[160];
    snprintf(d, sizeof d, "%d x %d x %d samples, worst relative error %.3g", v.n[0], v.n[1], v.n[2], worst);
    check(all_valid && worst < 1e-6 && v.n[0] == 3 && v.n[1] == 1 && v.n[2] == 4,
          std::string("closed emitting room gives cubes of L everywhere (") + ambient_fit_name(fit) + ")", d);
  }
  // 3. A solid box standing in the room: a sample inside it sees only the box's back faces: invalid,
  //    and never used by the lookup next to it.
  {
    std::vector<WorldFace> faces;
    const glm::dvec3 em[6] = {L, L, L, L, L, L}, dark[6] = {};
    add_box(glm::dvec3(0, 0, 0), glm::dvec3(6, 3, 6), true, em, &faces);
    add_box(glm::dvec3(2, 0.5, 2), glm::dvec3(4, 2.5, 4), false, dark, &faces);  // off the floor: no coplanar faces
    RayScene rays;
    if (!build_rays(faces, &rays, &err)) check(false, "solid-box ray scene", err);
    VolumeSettings set;
    set.spacing[0] = set.spacing[2] = 2;
    set.spacing[1] = 3;
    IrradianceVolume v;
    const double lo[3] = {0, 0, 0}, hi[3] = {6, 3, 6};
    if (!bake_irradiance_volume(lo, hi, faces, dark_grids(faces.size()), rays, set, &v, &err)) {
      check(false, "solid-box volume bake", err);
    } else {
      // 3 x 1 x 3 samples at (1|3|5, 1.5, 1|3|5): the centre one (3, 1.5, 3) is inside the box.
      const size_t centre = v.index(1, 0, 1);
      int valid_others = 0;
      for (size_t s = 0; s < v.valid.size(); ++s)
        if (s != centre) valid_others += v.valid[s];
      check(!v.valid[centre] && v.back_share[centre] == 1.f && valid_others == 8,
            "a sample inside a solid box is invalid (all back-face hits), the others valid",
            "centre back share " + std::to_string(v.back_share[centre]) + ", valid others " + std::to_string(valid_others));
      float cube[6][3];
      std::vector<VolumeContribution> used;
      const double p[3] = {2.9, 1.5, 3.1};
      bool uses_centre = false;
      double wsum = 0;
      const bool ok = volume_cube_at(v, p, VolumeLookup::Trilinear, cube, &used);
      for (const VolumeContribution &u : used) {
        uses_centre = uses_centre || (u.i == 1 && u.j == 0 && u.k == 1);
        wsum += u.weight;
      }
      check(ok && !used.empty() && !uses_centre && std::fabs(wsum - 1) < 1e-12,
            "the lookup next to an invalid sample leaves it out and renormalises", std::to_string(used.size()) + " used");
    }
  }
  // 4. A sphere moving in 1 cm steps through a room with six differently emitting walls: trilinear
  //    interpolation changes its cube per step by at most sum_a |dp_a| / step_a x (the samples' range
  //    of that colour), the bound of a trilinear blend's derivative (each axis: a difference of two
  //    samples over a step, blended with weights summing to 1), plus 1e-6 for float rounding.
  {
    std::vector<WorldFace> faces;
    const glm::dvec3 em[6] = {{2, 0.1, 0.1}, {0.1, 2, 0.1}, {0.1, 0.1, 2}, {1, 1, 0.1}, {0.1, 1, 1}, {1, 0.1, 1}};
    add_box(glm::dvec3(0, 0, 0), glm::dvec3(5, 5, 5), true, em, &faces);
    RayScene rays;
    if (!build_rays(faces, &rays, &err)) check(false, "moving-sphere ray scene", err);
    VolumeSettings set;
    IrradianceVolume v;
    const double lo[3] = {0, 0, 0}, hi[3] = {5, 5, 5};
    if (!bake_irradiance_volume(lo, hi, faces, dark_grids(faces.size()), rays, set, &v, &err)) {
      check(false, "moving-sphere volume bake", err);
    } else {
      double lo_c[3] = {1e30, 1e30, 1e30}, hi_c[3] = {-1e30, -1e30, -1e30};
      for (const auto &c : v.cube)
        for (int f = 0; f < 6; ++f)
          for (int k = 0; k < 3; ++k) {
            lo_c[k] = std::fmin(lo_c[k], c[f][k]);
            hi_c[k] = std::fmax(hi_c[k], c[f][k]);
          }
      const glm::dvec3 a(0.2, 0.3, 0.4), b(4.8, 4.6, 4.7);
      const int steps = static_cast<int>(std::ceil(glm::length(b - a) / 0.01));
      const glm::dvec3 dp = (b - a) / double(steps);
      float prev[6][3];
      double pa[3] = {a.x, a.y, a.z};
      volume_cube_at(v, pa, VolumeLookup::Trilinear, prev, nullptr);
      double worst_ratio = 0, largest = 0;
      for (int s = 1; s <= steps; ++s) {
        const glm::dvec3 p = a + dp * double(s);
        const double pp[3] = {p.x, p.y, p.z};
        float cur[6][3];
        volume_cube_at(v, pp, VolumeLookup::Trilinear, cur, nullptr);
        for (int k = 0; k < 3; ++k) {
          const double bound =
              (std::fabs(dp.x) / v.step[0] + std::fabs(dp.y) / v.step[1] + std::fabs(dp.z) / v.step[2]) * (hi_c[k] - lo_c[k]) + 1e-6;
          for (int f = 0; f < 6; ++f) {
            const double change = std::fabs(static_cast<double>(cur[f][k]) - prev[f][k]);
            worst_ratio = std::fmax(worst_ratio, change / bound);
            largest = std::fmax(largest, change);
          }
        }
        std::memcpy(prev, cur, sizeof prev);
      }
      char d[160];
      snprintf(d, sizeof d, "%d steps, largest change %.3g, worst change / bound %.3f", steps, largest, worst_ratio);
      printf("moving sphere: %s\n", d);
      check(worst_ratio <= 1 && largest > 0, "a sphere moving in 1 cm steps changes its cube within the trilinear bound", d);
    }
  }
  // 5. Inverse-square weights on a hand-made 2 x 2 x 2 volume (samples 1 m apart; one invalid):
  //    weight 1 / (d^2 + 1) with d in inches, renormalised over the 7 valid samples.
  {
    IrradianceVolume v;
    v.n[0] = v.n[1] = v.n[2] = 2;
    v.step[0] = v.step[1] = v.step[2] = 1;
    v.cube.assign(8, {});
    v.valid.assign(8, 1);
    v.back_share.assign(8, 0.f);
    for (int s = 0; s < 8; ++s)
      for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 3; ++k) v.cube[s][f][k] = static_cast<float>(s + 1);
    v.valid[7] = 0;  // (1, 1, 1)
    const double p[3] = {0.1, 0.2, 0.3};
    double want = 0, wsum = 0;
    for (int s = 0; s < 7; ++s) {
      const double dx = (s & 1) - p[0], dy = ((s >> 1) & 1) - p[1], dz = ((s >> 2) & 1) - p[2];
      const double d2 = (dx * dx + dy * dy + dz * dz) / (0.0254 * 0.0254);
      const double w = 1 / (d2 + 1);
      want += w * (s + 1);
      wsum += w;
    }
    want /= wsum;
    float cube[6][3];
    std::vector<VolumeContribution> used;
    volume_cube_at(v, p, VolumeLookup::InverseSquare, cube, &used);
    const double rel = std::fabs(cube[2][1] - want) / want;
    check(used.size() == 7 && rel < 1e-6, "inverse-square lookup is 1/(d^2+1) in inches over the valid samples",
          "got " + std::to_string(cube[2][1]) + " want " + std::to_string(want));
  }
  // 6. The scene hook (glue/scene/scene_volume.cpp via prepare.cpp): world_lighting's room with a
  //    small model added gets a volume cube (non-zero: the room is lit); a hand-typed ambient sample
  //    overrides it; "enabled": false leaves the cube zero; lights beyond the tier fold into the
  //    volume's cube; the room without the model bakes no volume.
  {
    Scene room;
    if (!load_scene("scenes/world_lighting.gltf", &room, &err)) {
      check(false, "load world_lighting", err);
    } else {
      SceneMaterial mm;
      mm.name = "volume_probe_model";
      mm.where = "materials[test]";
      mm.shader = SceneShader::Model;
      room.materials.push_back(mm);
      ScenePrimitive model = room.primitives[0];
      model.material = static_cast<int>(room.materials.size()) - 1;
      model.instance = -1;
      model.where = "test model";
      double c[3];
      for (int k = 0; k < 3; ++k) {
        double lo = 1e30, hi = -1e30;
        for (size_t i = k; i < model.position.size(); i += 3) {
          lo = std::fmin(lo, model.position[i]);
          hi = std::fmax(hi, model.position[i]);
        }
        c[k] = 0.5 * (lo + hi);
      }
      const double at[3] = {0.5, 1.0, 0.3};
      for (size_t i = 0; i < model.position.size(); ++i)
        model.position[i] = static_cast<float>((model.position[i] - c[i % 3]) * 0.05 + at[i % 3]);
      room.primitives.push_back(model);
      PreparedScene last;  // the latest prepared scene (its volume)
      float folded[6][3] = {};  // the latest model's shader cube (slots ML_SLOT_AMBIENT..: lights folded in)
      auto model_cube = [&](const Scene &sc, float out[6][3], Tier tier = Tier::SM3) {
        SceneSelection sel;
        PreparedScene &ps = last;
        ps = PreparedScene();
        if (!select_scene_variants(sc, tier, "", &sel, &err) ||
            !prepare_scene(sc, sel, 32, 32, Api::GL33, 1.f, &ps, &err))
          return false;
        for (const PreparedDraw &d : ps.draws)
          if (!d.world) {
            std::memcpy(out, d.ambient, sizeof d.ambient);
            for (int f = 0; f < 6; ++f) {
              const ts_vec4f &a = d.shared.at(ML_SLOT_AMBIENT + f);
              folded[f][0] = a.x, folded[f][1] = a.y, folded[f][2] = a.z;
            }
            return true;
          }
        err = "no model draw";
        return false;
      };
      float vol[6][3], hand[6][3], off[6][3];
      const bool ok1 = model_cube(room, vol);
      double sum = 0;
      for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 3; ++k) sum += vol[f][k];
      printf("model cube from the volume: %s\n", cube_sum_text(vol).c_str());
      check(ok1 && sum > 0, "a model in a world scene takes its cube from the volume", ok1 ? cube_sum_text(vol) : err);
      Scene with_hand = room;
      SceneAmbientSample a{};
      for (int k = 0; k < 3; ++k) a.position[k] = at[k];
      for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 3; ++k) a.cube[f][k] = 0.125f * (f + 1);
      with_hand.ambient.push_back(a);
      const bool ok2 = model_cube(with_hand, hand);
      check(ok2 && std::memcmp(hand, a.cube, sizeof hand) == 0, "a hand-typed ambient sample overrides the volume", err);
      Scene disabled = room;
      disabled.volume.enabled = false;
      const bool ok3 = model_cube(disabled, off);
      double osum = 0;
      for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 3; ++k) osum += off[f][k];
      check(ok3 && osum == 0, "volume.enabled false: no volume", err);
      // Samples only where models can be (extras.tiershade.reach): the model as a node instance whose
      // centre may move in a box around `at`; only the samples a lookup inside the box reads are
      // baked, bit-equal to the full bake's, and every lookup inside the box gives the full bake's cube.
      {
        float fc[6][3];
        const bool okf = model_cube(room, fc);
        const IrradianceVolume full = last.volume;
        Scene reach = room;
        SceneInstance inst;
        inst.name = "test model";
        for (int k = 0; k < 16; ++k) inst.world[k] = k % 5 == 0 ? 1 : 0;
        for (int k = 0; k < 3; ++k) {
          inst.center[k] = at[k];
          inst.reach_lo[k] = at[k] - 0.4;
          inst.reach_hi[k] = at[k] + (k == 0 ? 1.5 : 0.4);
        }
        inst.has_reach = true;
        reach.instances.push_back(inst);
        reach.primitives.back().instance = static_cast<int>(reach.instances.size()) - 1;
        float rc[6][3];
        const bool okr = model_cube(reach, rc);
        const IrradianceVolume &part = last.volume;
        long baked = 0, equal = 0, others_zero = 0;
        if (full.cube.empty()) err = "no full volume";
        const std::vector<uint8_t> need = volume_needed_samples(full, {{inst.reach_lo[0], inst.reach_lo[1],
                                                                         inst.reach_lo[2], inst.reach_hi[0],
                                                                         inst.reach_hi[1], inst.reach_hi[2]}});
        const bool sizes = okf && okr && !full.cube.empty() && part.cube.size() == full.cube.size();
        for (size_t i = 0; sizes && i < part.cube.size(); ++i) {
          baked += need[i];
          if (need[i])
            equal += part.valid[i] == full.valid[i] && std::memcmp(&part.cube[i], &full.cube[i], sizeof part.cube[i]) == 0;
          else
            others_zero += !part.valid[i];
        }
        const long all = static_cast<long>(full.cube.size());
        // Lookups at 200 points inside the box (and on its corners) against the full volume's.
        uint64_t rng = 12345;
        int same = 0, points = 0;
        for (int t = 0; t < 208; ++t) {
          double p[3];
          for (int k = 0; k < 3; ++k) {
            rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
            const double u = t < 8 ? ((t >> k) & 1) : static_cast<double>(rng >> 11) / 9007199254740992.0;
            p[k] = inst.reach_lo[k] + u * (inst.reach_hi[k] - inst.reach_lo[k]);
          }
          for (VolumeLookup lk : {VolumeLookup::Trilinear, VolumeLookup::InverseSquare}) {
            float a[6][3], b[6][3];
            const bool fa = volume_cube_at(full, p, lk, a, nullptr), fb = volume_cube_at(part, p, lk, b, nullptr);
            same += fa == fb && std::memcmp(a, b, sizeof a) == 0;
            ++points;
          }
        }
        char d[200];
        snprintf(d, sizeof d, "%ld of %ld samples baked (part.baked %ld), %ld bit-equal, %ld others invalid; %d of %d lookups equal",
                 baked, all, part.baked, equal, others_zero, same, points);
        printf("reach: %s\n", d);
        check(okr && part.cube.size() == full.cube.size() && baked > 0 && baked < all && part.baked == baked &&
                  equal == baked && others_zero == all - baked && same == points &&
                  part.rays == baked * static_cast<long>(volume_ray_directions().size()),
              "a model's reach bakes only the samples its lookups read, equal to the full bake's", d);
        Scene no_reach = reach;
        no_reach.instances.back().has_reach = false;
        float nc[6][3];
        const bool okn = model_cube(no_reach, nc);
        check(okn && last.volume.baked == all, "no model names its reach: the whole volume is baked", err);
      }
      // Lights beyond the tier's limit fold into the volume's cube (docs/light_folding.md): the room's
      // 4 lights fit sm3's 4, so the sm3 shader cube is the volume's at the model's centre (tolerance
      // 1e-5: the centre from float positions differs from `at` by ~1e-7 m, the cube's slope is ~1 per
      // m); ps20 keeps 2 and folds 2: its shader cube is the sm3 one plus non-negative amounts (>= -1e-6,
      // float additions), more than 1e-4 on some face.
      float sm3[6][3], ps20[6][3], at_vol[6][3], unused[6][3];
      const bool ok4 = model_cube(room, unused, Tier::SM3);
      std::memcpy(sm3, folded, sizeof sm3);
      volume_cube_at(last.volume, at, VolumeLookup::Trilinear, at_vol, nullptr);
      const bool ok5 = ok4 && model_cube(room, unused, Tier::PS20);
      std::memcpy(ps20, folded, sizeof ps20);
      double d_vol = 0, d_min = 1e30, d_max = -1e30;
      for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 3; ++k) {
          d_vol = std::fmax(d_vol, std::fabs(sm3[f][k] - at_vol[f][k]));
          d_min = std::fmin(d_min, ps20[f][k] - sm3[f][k]);
          d_max = std::fmax(d_max, ps20[f][k] - sm3[f][k]);
        }
      char fd[160];
      snprintf(fd, sizeof fd, "%zu lights; sm3 - volume %.3g; ps20 - sm3 in [%.3g, %.3g]", room.lights.size(), d_vol,
               d_min, d_max);
      printf("light folding on the volume's cube: %s\n", fd);
      check(ok5 && room.lights.size() == 4 && d_vol < 1e-5 && d_min >= -1e-6 && d_max > 1e-4,
            "lights beyond the tier's limit fold into the volume's cube (ps20), none within it (sm3)", ok5 ? fd : err);
      // No models, no volume: the room alone bakes none.
      Scene world_only = room;
      world_only.primitives.pop_back();
      world_only.materials.pop_back();
      SceneSelection wsel;
      PreparedScene wps;
      const bool ok6 = select_scene_variants(world_only, Tier::SM3, "", &wsel, &err) &&
          prepare_scene(world_only, wsel, 32, 32, Api::GL33, 1.f, &wps, &err);
      check(ok6 && wps.volume.cube.empty() && !last.volume.cube.empty(), "no volume for a scene without models",
            ok6 ? std::to_string(wps.volume.cube.size()) + " samples" : err);
    }
  }
  // 8. A model (a closed box of id -2, other geometry) in the emitting room: by default (models_occlude
  //    false, the scenes' setting, as vrad) the ray passes through both of its walls to the room
  //    (radiance L, exact: the emission is read unchanged) and the sample inside sees the room: valid,
  //    cube L; with models_occlude a ray into it stops as a black back-face hit and a sample inside it
  //    is invalid.
  {
    std::vector<WorldFace> faces;
    const glm::dvec3 em[6] = {L, L, L, L, L, L};
    add_box(glm::dvec3(0, 0, 0), glm::dvec3(4, 3, 5), true, em, &faces);
    RayScene rays;
    bool ok = true;
    for (size_t i = 0; i < faces.size() && ok; ++i) {
      const WorldFace &f = faces[i];
      const glm::dvec3 o(f.origin.x, f.origin.y, f.origin.z), u = glm::dvec3(f.u.x, f.u.y, f.u.z) * f.su,
                       v = glm::dvec3(f.v.x, f.v.y, f.v.z) * f.sv;
      std::vector<float> p;
      for (const glm::dvec3 &q : {o, o + u, o + u + v, o + v})
        for (int k = 0; k < 3; ++k) p.push_back(static_cast<float>(q[k]));
      ok = rays.add_mesh(p, {0, 1, 2, 0, 2, 3}, static_cast<int>(i), f.name, &err);
    }
    // The model: the box [1.5, 2.5] x [1, 2] x [2, 3] as 12 triangles.
    std::vector<float> mp;
    for (int c = 0; c < 8; ++c)
      for (float x : {(c & 1) ? 2.5f : 1.5f, (c & 2) ? 2.f : 1.f, (c & 4) ? 3.f : 2.f}) mp.push_back(x);
    const std::vector<uint32_t> mi = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                      2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    ok = ok && rays.add_mesh(mp, mi, -2, "model box", &err) && rays.commit(&err);
    if (!ok) {
      check(false, "room with a model box", err);
    } else {
      const std::vector<LuxelGrid> grids = dark_grids(faces.size());
      VolumeSettings occ, through;  // through: the default
      occ.models_occlude = true;
      const glm::dvec3 from(2, 1.5, 0.5), dir(0, 0, 1);  // towards the model, the room's z+ wall behind it
      bool b1 = false, b2 = true;
      const glm::dvec3 r1 = volume_ray_radiance(from, dir, faces, grids, rays, occ, &b1);
      const glm::dvec3 r2 = volume_ray_radiance(from, dir, faces, grids, rays, through, &b2);
      check(b1 && r1 == glm::dvec3(0.0) && !b2 && r2 == L,
            "a ray into a model: through it to the room (the default), a black back-face hit with models_occlude",
            "occlude " + std::to_string(r1.x) + ", through " + std::to_string(r2.x));
      float c1[6][3], c2[6][3];
      const double s1 = volume_sample_cube(glm::dvec3(2, 1.5, 2.5), faces, grids, rays, occ, c1);
      const double s2 = volume_sample_cube(glm::dvec3(2, 1.5, 2.5), faces, grids, rays, through, c2);
      double worst = 0;
      for (int f = 0; f < 6; ++f)
        for (int c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs(c2[f][c] - L[c]) / L[c]);
      // Tolerance 1e-6 relative: float rounding of the fitted cube, as in check 2.
      check(s1 == 1.0 && s2 == 0.0 && worst < 1e-6,
            "a sample inside a model: the room's cube L (the default), all back-face hits with models_occlude",
            "shares " + std::to_string(s1) + " / " + std::to_string(s2) + ", worst " + std::to_string(worst));
    }
  }
  return finish();
}

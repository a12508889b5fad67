// tiershade cli: `light` subcommand: what the bake says at a point (docs/baking.md, "tiershade
// light"): the world face nearest the point (with --normal, the nearest whose front normal agrees),
// its luxel there, the irradiance and the four lightmap values (flat, b0, b1, b2) before any
// run-time encoding, from the scene's bake directory (extras.tiershade.lightmaps.bake) or baked here;
// for a scene with an irradiance volume, the models' ambient cube interpolated at the point and the
// samples that contributed with their weights (docs/irradiance_volume.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "bake/bake_dir.h"
#include "cli/args.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/scene_volume.h"
#include "scene/selection.h"

namespace {

const char kHelp[] = R"(usage: tiershade light SCENE.gltf --at X,Y,Z [--normal NX,NY,NZ] [--lookup L] [--json]
Bakes the scene's lightmaps (or reads its bake directory, extras.tiershade.lightmaps.bake) and prints
what they hold at the world surface nearest the point: the face (primitive), the luxel, the
irradiance E there (the flat value, bilinear between the luxels as LINEAR sampling reads it) and the
four values of the nearest luxel (flat and the three basis directions b0, b1, b2) before any
run-time encoding. --normal: only faces whose front normal is within 60 degrees of it.
With models and an irradiance volume (docs/irradiance_volume.md), also the ambient cube a model
centred at the point takes (+X -X +Y -Y +Z -Z, before lights are folded in) and the samples that
contributed with their weights; --lookup trilinear|inverse_square|nearest (default: the scene's).
Units (docs/baking.md): a point light of glTF color x intensity I at distance d gives E = I cos / d^2;
a value is the radiance a white diffuse surface lit by E reflects (the shader multiplies it by the
base colour).)";

const char kUnits[] =
    "irradiance in lightmap units: E = sum of I cos(theta) / d^2 over the lights that reach the point (I = glTF "
    "color x intensity), plus (1/pi) integral of L cos over the bounces; a lightmap value is the radiance a white "
    "diffuse surface reflects (the shader multiplies it by the base colour; docs/baking.md)";

bool parse3(const std::string &s, double v[3]) {
  std::istringstream in(s);
  char c1 = 0, c2 = 0;
  std::string rest;
  if (!(in >> v[0] >> c1 >> v[1] >> c2 >> v[2]) || c1 != ',' || c2 != ',' || (in >> rest)) return false;
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

double dot3(const double a[3], const ts_vec3d &b) { return a[0] * b.x + a[1] * b.y + a[2] * b.z; }

const char *const kFaces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

const char *lookup_name(VolumeLookup l) {
  return l == VolumeLookup::InverseSquare ? "inverse_square" : l == VolumeLookup::Nearest ? "nearest" : "trilinear";
}

// The volume's cube at the point: JSON (null without a volume) and the text lines.
nlohmann::ordered_json volume_json(const IrradianceVolume &v, VolumeLookup look, const double at[3], std::string *text) {
  char b[300];
  if (v.cube.empty()) {
    *text = "volume: none (the scene has no models, hand-typed ambient samples, or extras.tiershade.volume.enabled false)\n";
    return nullptr;
  }
  float cube[6][3];
  std::vector<VolumeContribution> used;
  if (!volume_cube_at(v, at, look, cube, &used)) {
    *text = "volume: no valid sample: the cube is zero\n";
    return {{"lookup", lookup_name(look)}, {"cube", nullptr}, {"samples", nlohmann::ordered_json::array()}};
  }
  nlohmann::ordered_json j, faces, samples = nlohmann::ordered_json::array();
  snprintf(b, sizeof b, "volume: %d x %d x %d samples, %s lookup: the ambient cube at the point (before lights are folded in):\n",
           v.n[0], v.n[1], v.n[2], lookup_name(look));
  *text = b;
  for (int f = 0; f < 6; ++f) {
    faces[kFaces[f]] = {cube[f][0], cube[f][1], cube[f][2]};
    snprintf(b, sizeof b, "  %s %.9g %.9g %.9g\n", kFaces[f], cube[f][0], cube[f][1], cube[f][2]);
    *text += b;
  }
  double sum = 0;
  for (const VolumeContribution &u : used) {
    const glm::dvec3 p = v.position(u.i, u.j, u.k);
    samples.push_back({{"sample", {u.i, u.j, u.k}}, {"position", {p.x, p.y, p.z}}, {"weight", u.weight}});
    snprintf(b, sizeof b, "  sample (%d, %d, %d) at (%.6g, %.6g, %.6g): weight %.9g\n", u.i, u.j, u.k, p.x, p.y, p.z,
             u.weight);
    *text += b;
    sum += u.weight;
  }
  snprintf(b, sizeof b, "  %zu samples contributed, weights sum to %.9g\n", used.size(), sum);
  *text += b;
  j["lookup"] = lookup_name(look);
  j["samples_grid"] = {v.n[0], v.n[1], v.n[2]};
  j["cube"] = faces;
  j["samples"] = samples;
  j["weight_sum"] = sum;
  return j;
}

}  // namespace

int cmd_light(int argc, char **argv) {
  Args a("light", argc, argv, {"--help", "--json"}, {"--at", "--normal", "--lookup"});
  if (a.help(kHelp)) return 0;
  if (a.positional().size() != 1) a.fail("expected one scene file (tiershade light SCENE.gltf --at X,Y,Z)");
  if (!a.has("--at")) a.fail("--at X,Y,Z is required");
  double at[3], nrm[3] = {0, 0, 0};
  if (!parse3(a.get("--at"), at)) a.fail("--at '" + a.get("--at") + "': expected three numbers X,Y,Z");
  const bool want_normal = a.has("--normal");
  if (want_normal) {
    if (!parse3(a.get("--normal"), nrm)) a.fail("--normal '" + a.get("--normal") + "': expected three numbers");
    const double l = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(l > 0)) a.fail("--normal: a zero vector");
    for (double &c : nrm) c /= l;
  }
  if (a.has("--lookup") && a.get("--lookup") != "trilinear" && a.get("--lookup") != "inverse_square" &&
      a.get("--lookup") != "nearest")
    a.fail("--lookup '" + a.get("--lookup") + "': expected trilinear, inverse_square or nearest");
  Scene scene;
  std::string err;
  if (!load_scene(a.positional()[0], &scene, &err)) {
    fprintf(stderr, "tiershade light: %s\n", err.c_str());
    return 1;
  }
  const VolumeLookup look = !a.has("--lookup")            ? scene_volume_lookup(scene)
      : a.get("--lookup") == "inverse_square" ? VolumeLookup::InverseSquare
      : a.get("--lookup") == "nearest"        ? VolumeLookup::Nearest
                                              : VolumeLookup::Trilinear;
  scene.lightmaps.bake_progress = true;
  SceneSelection sel;
  PreparedScene ps;
  if (!select_scene_variants(scene, Tier::SM3, "", &sel, &err) ||
      !prepare_scene(scene, sel, 16, 16, Api::GL33, 1.f, &ps, &err)) {
    fprintf(stderr, "tiershade light: %s: %s\n", scene.path.c_str(), err.c_str());
    return 1;
  }
  const BakeSummary &sum = ps.bake_summary;
  if (sum.faces.empty()) {
    fprintf(stderr, "tiershade light: %s: no LightmappedGeneric primitive: the scene has no lightmaps\n",
            scene.path.c_str());
    return 1;
  }
  // The nearest point of each face (its rectangle), the nearest face (the lowest index on a tie).
  int best = -1;
  double best_d = 0, best_a = 0, best_b = 0;
  for (size_t i = 0; i < sum.faces.size(); ++i) {
    const WorldFace &f = sum.faces[i].face;
    if (f.chart) {  // a TEXCOORD_1 chart (glue/bake/charts.h): its nearest lit luxel's point
      for (int j = 0; j < f.chart->h; ++j)
        for (int k = 0; k < f.chart->w; ++k) {
          const LuxelFrame &lf = f.chart->at(k, j);
          if (!lf.lit || (want_normal && !(dot3(nrm, lf.n) > 0.5))) continue;
          const double d = std::sqrt((at[0] - lf.p.x) * (at[0] - lf.p.x) + (at[1] - lf.p.y) * (at[1] - lf.p.y) +
                                     (at[2] - lf.p.z) * (at[2] - lf.p.z));
          if (best < 0 || d < best_d) {
            best = static_cast<int>(i);
            best_d = d;
            best_a = static_cast<double>(k) / (f.chart->w - 1);
            best_b = static_cast<double>(j) / (f.chart->h - 1);
          }
        }
      continue;
    }
    const ts_vec3d n = world_face_normal(f);
    if (want_normal && !(dot3(nrm, n) > 0.5)) continue;  // within 60 degrees
    const double q[3] = {at[0] - f.origin.x, at[1] - f.origin.y, at[2] - f.origin.z};
    const double fa = std::clamp(dot3(q, f.u) / f.su, 0.0, 1.0), fb = std::clamp(dot3(q, f.v) / f.sv, 0.0, 1.0);
    const ts_vec3d p = world_face_point(f, fa, fb);
    const double d =
        std::sqrt((at[0] - p.x) * (at[0] - p.x) + (at[1] - p.y) * (at[1] - p.y) + (at[2] - p.z) * (at[2] - p.z));
    if (best < 0 || d < best_d) {
      best = static_cast<int>(i);
      best_d = d;
      best_a = fa;
      best_b = fb;
    }
  }
  if (best < 0) {
    fprintf(stderr, "tiershade light: %s: no world face whose front normal is within 60 degrees of --normal %s\n",
            scene.path.c_str(), a.get("--normal").c_str());
    return 1;
  }
  const BakeFace &bf = sum.faces[static_cast<size_t>(best)];
  const int w = bf.luxels_w, h = bf.luxels_h;
  const double x = best_a * (w - 1), y = best_b * (h - 1);
  const int li = static_cast<int>(std::lround(x)), lj = static_cast<int>(std::lround(y));
  auto value = [&](int k, int i, int j, double out[3]) {
    int tx, ty;
    lm_page_texel(&bf.place, k, i, j, &tx, &ty);
    const float *t = &ps.lightmap_page[(static_cast<size_t>(ty) * ps.lightmap_w + tx) * 4];
    for (int c = 0; c < 3; ++c) out[c] = t[c];
  };
  double vals[4][3], e[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) value(k, li, lj, vals[k]);
  {  // the flat value bilinear at the point (between the luxel grid points)
    const int i0 = std::min(w - 2, static_cast<int>(x)), j0 = std::min(h - 2, static_cast<int>(y));
    const double fx = x - i0, fy = y - j0;
    double c00[3], c10[3], c01[3], c11[3];
    value(0, i0, j0, c00);
    value(0, i0 + 1, j0, c10);
    value(0, i0, j0 + 1, c01);
    value(0, i0 + 1, j0 + 1, c11);
    for (int c = 0; c < 3; ++c)
      e[c] = (c00[c] * (1 - fx) + c10[c] * fx) * (1 - fy) + (c01[c] * (1 - fx) + c11[c] * fx) * fy;
  }
  const char *names[4] = {"flat", "b0", "b1", "b2"};
  const std::string source = sum.from_dir.empty() ? "baked at load" : sum.from_dir;
  std::string volume_text;
  const nlohmann::ordered_json vol = volume_json(ps.volume, look, at, &volume_text);
  if (a.flag("--json")) {
    nlohmann::ordered_json j;
    j["scene"] = scene.path;
    j["bake"] = source;
    j["face"] = best;
    j["material"] = bf.name;
    j["primitive"] = bf.where;
    j["distance"] = best_d;
    j["luxel"] = {li, lj};
    j["luxel_coords"] = {x, y};
    j["luxels"] = {w, h};
    j["bumped"] = bf.face.bumped;
    j["irradiance"] = {e[0], e[1], e[2]};
    for (int k = 0; k < 4; ++k) j["values"][names[k]] = {vals[k][0], vals[k][1], vals[k][2]};
    j["units"] = kUnits;
    j["volume"] = vol;
    printf("%s\n", j.dump(1).c_str());
    return 0;
  }
  printf("surface: face %d (%s, %s), %.6g from the point (%s)\n", best, bf.name.c_str(), bf.where.c_str(), best_d,
         source.c_str());
  printf("luxel: (%d, %d) of %d x %d; the point at luxel coordinates (%.4f, %.4f)\n", li, lj, w, h, x, y);
  printf("irradiance: %.9g %.9g %.9g (the flat value, bilinear at the point)\n", e[0], e[1], e[2]);
  printf("values at luxel (%d, %d), before encoding%s:\n", li, lj,
         bf.face.bumped ? "" : " (no normal map: the shader reads the flat one)");
  for (int k = 0; k < 4; ++k) printf("  %-4s %.9g %.9g %.9g\n", names[k], vals[k][0], vals[k][1], vals[k][2]);
  printf("units: %s\n", kUnits);
  printf("%s", volume_text.c_str());
  return 0;
}

// tiershade cli: `fold` subcommand: which lights a tier shades locally, the ambient cube
// the others are folded into (c_ref/offline/light_folding.c, docs/light_folding.md), and a
// numerical check, with the real C twin, that the folding conserves the sphere integral.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <glm/gtc/constants.hpp>

#include "families/family.h"
#include "offline/light_folding.h"
#include "io/lights_file.h"
#include "twins/model_lighting.h"
#include "demo/scene_files.h"
#include "cli/select_args.h"

namespace {

// Integral over the unit sphere of normals of the twin's linear output at `center`
// (Fibonacci sphere), for a record with the given cube and local lights.
double sphere_integral(const ts_vec4f rec_in[ML_SLOTS], int channel, int half_lambert, int lights) {
  const int n = 20000;
  ml_variant v = {};
  v.tier = TS_TIER_ID_PS2B;
  v.half_lambert = half_lambert;
  v.num_lights = lights;
  ts_vec4f rec[ML_SLOTS];
  for (int k = 0; k < ML_SLOTS; ++k) rec[k] = rec_in[k];
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), phi = i * 2.39996322972865332;
    rec[ML_SLOT_NORMAL] =
        ts_v4f(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z), 0);
    const ts_vec4d c = model_lighting_d(&v, rec, nullptr);
    sum += channel == 0 ? c.x : channel == 1 ? c.y : c.z;
  }
  return sum * 4 * glm::pi<double>() / n;
}

}  // namespace

// `tiershade fold --help`.
const char kHelp[] = R"(usage: tiershade fold [--tier ps20|ps2b|sm3] [--lights FILE] [--center X,Y,Z] [--lambert]
Chooses the lights a tier shades locally (ps20: 2, ps2b and sm3: 4; the brightest at the
model centre) and folds the others into the ambient cube, conserving the sphere integral of
the half-Lambert (or, with --lambert, Lambert) shading (docs/light_folding.md). Prints the
kept lights, the cube, and for each folded light the integral over all normals of its
shading as a local light and folded, computed with the C twin.
Lights file lines ('#' comments):
  point       R G B  X Y Z  C L Q
  spot        R G B  X Y Z  DX DY DZ  EXPONENT INNER_DEG OUTER_DEG  C L Q
  directional R G B  DX DY DZ
Without --lights, the demo scene's six lights are used (scenes/sphere_grid.lights, run from the
repository root).)";

int cmd_fold(int argc, char **argv) {
  Args a("fold", argc, argv, {"--help", "--lambert"}, {"--tier", "--lights", "--center"});
  if (a.help(kHelp)) return 0;
  a.no_positional();
  Tier tier = Tier::PS20;
  if (a.has("--tier") && !parse_tier(a.get("--tier"), &tier)) a.fail("unknown tier '" + a.get("--tier") + "'");
  float center[3] = {0, 0, 0};
  if (a.has("--center")) {
    char extra;
    if (sscanf(a.get("--center").c_str(), "%f,%f,%f%c", &center[0], &center[1], &center[2], &extra) != 3 ||
        !std::isfinite(center[0]) || !std::isfinite(center[1]) || !std::isfinite(center[2]))
      a.fail("--center wants X,Y,Z, got '" + a.get("--center") + "'");
  }
  std::vector<ts_light> lights;
  std::string err;
  if (a.has("--lights")) {
    if (!read_lights(a.get("--lights"), &lights, &err)) a.fail(err);
  } else {
    if (!read_lights(kSphereGridLights, &lights, &err)) a.fail(err);
  }
  const int max_local = max_local_lights(tier);
  const int half_lambert = a.flag("--lambert") ? 0 : 1;
  const int n = static_cast<int>(lights.size());
  float cube[6][3] = {};
  std::vector<int> kept(n + 1);
  const int nk = ts_fold_lights(lights.data(), n, max_local, center, half_lambert, cube, kept.data());
  const char *types[3] = {"point", "spot", "directional"};
  printf("%s keeps %d of %d lights (%s):\n", tier_name(tier), nk, n, half_lambert ? "half-Lambert" : "Lambert");
  std::vector<int> is_kept(n, 0);
  for (int i = 0; i < nk; ++i) is_kept[kept[i]] = 1;
  for (int i = 0; i < n; ++i) {
    double rgb[3], dir[3];
    ts_light_incident(&lights[i], center, rgb, dir);
    printf("  light %d %-11s %-6s incident rgb %.4f %.4f %.4f from (%.3f, %.3f, %.3f)\n", i, types[lights[i].type],
           is_kept[i] ? "local" : "folded", rgb[0], rgb[1], rgb[2], dir[0], dir[1], dir[2]);
  }
  const char *faces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  printf("ambient cube added by the folded lights:\n");
  for (int f = 0; f < 6; ++f) printf("  %s %.5f %.5f %.5f\n", faces[f], cube[f][0], cube[f][1], cube[f][2]);
  // Conservation check: each folded light, local (alone) vs folded (alone).
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    if (is_kept[i]) continue;
    ts_vec4f local[ML_SLOTS], folded[ML_SLOTS];
    for (int k = 0; k < ML_SLOTS; ++k) local[k] = folded[k] = ts_v4f(0, 0, 0, 0);
    local[ML_SLOT_POSITION] = folded[ML_SLOT_POSITION] = ts_v4f(center[0], center[1], center[2], 1);
    local[ML_SLOT_PARAMS] = folded[ML_SLOT_PARAMS] = ts_v4f(1, 1, 0, 0);
    local[ML_SLOT_ALBEDO] = folded[ML_SLOT_ALBEDO] = ts_v4f(1, 1, 1, 1);
    float packed[5][4];
    char msg[256];
    ts_light_pack(&lights[i], packed, msg, sizeof msg);
    for (int k = 0; k < 5; ++k)
      local[ML_SLOT_LIGHT0 + k] = ts_v4f(packed[k][0], packed[k][1], packed[k][2], packed[k][3]);
    // The light's own cube contribution: fold it alone into an empty cube.
    float c1[6][3] = {};
    int kept1 = 0;
    ts_fold_lights(&lights[i], 1, 0, center, half_lambert, c1, &kept1);
    for (int f = 0; f < 6; ++f) folded[ML_SLOT_AMBIENT + f] = ts_v4f(c1[f][0], c1[f][1], c1[f][2], 0);
    for (int ch = 0; ch < 3; ++ch) {
      const double il = sphere_integral(local, ch, half_lambert, 1), ifo = sphere_integral(folded, ch, half_lambert, 0);
      const double rel = il > 0 ? std::fabs(ifo - il) / il : std::fabs(ifo);
      worst = std::max(worst, rel);
      if (ch == 0) printf("light %d: sphere integral local vs folded:", i);
      printf("  %.5f / %.5f", il, ifo);
    }
    printf("\n");
  }
  printf("worst relative difference of the sphere integrals: %.2e (Fibonacci sphere, 20000 normals)\n", worst);
  // The quadrature itself is good to ~1e-6 here (docs/light_folding.md); 1e-3 means the rule broke.
  if (worst > 1e-3) {
    printf("fold: the folding did not conserve the sphere integral\n");
    return 1;
  }
  return 0;
}

// tiershade cli: `ambient` subcommand: the six colours of the ambient cube fitted to a lat-long light
// probe (glue/bake/ambient_fit.h), as text or JSON, so a fit can be compared with other tools.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "bake/ambient_fit.h"
#include "cli/args.h"

namespace {
const char kHelp[] = R"(usage: tiershade ambient PROBE.hdr|PROBE.exr [--fit lsq|mean|lsq-pixels|lsq-radiance] [--json] [--error]
Fits the six colours of an ambient cube (+X -X +Y -Y +Z -Z) to a latitude-longitude light probe
(glue's probe convention: +Y up, u = atan2(x, -z) / 2pi + 0.5, v = acos(y) / pi) and prints them.
The cube's value for a normal n stands for the irradiance over pi, E(n)/pi.
  --fit lsq           non-negative least squares against the probe's irradiance, solid-angle weighted (default)
  --fit mean          Source's per-axis cosine-weighted mean radiance (vrad; exact on the six axes only)
  --fit lsq-pixels    least squares with every lat-long pixel weighted alike (Probulator's fit)
  --fit lsq-radiance  least squares against the radiance itself (for comparison)
  --json              one JSON object: {"probe", "width", "height", "fit", "faces": {"+X": [r,g,b], ...}}
  --error             also the irradiance RMS against the probe's exact irradiance (pixels, solid angle)
docs/irradiance_volume.md has the measured errors of each fit.)";

const char *const kFaceNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
}  // namespace

int cmd_ambient(int argc, char **argv) {
  Args a("ambient", argc, argv, {"--help", "--json", "--error"}, {"--fit"});
  if (a.help(kHelp)) return 0;
  if (a.positional().size() != 1) a.fail("expected one probe file (.hdr or .exr); --help for usage");
  AmbientFit fit = AmbientFit::Lsq;
  if (a.has("--fit") && !ambient_fit_from_name(a.get("--fit"), &fit))
    a.fail("--fit: '" + a.get("--fit") + "' is not one of lsq, mean, lsq-pixels, lsq-radiance");
  const std::string path = a.positional()[0];
  ImageF probe;
  std::string err;
  if (!read_latlong_probe(path, &probe, &err)) {
    fprintf(stderr, "tiershade ambient: %s\n", err.c_str());
    return 1;
  }
  float cube[6][3];
  fit_probe_cube(probe, fit, cube);
  CubeIrradianceError e;
  if (a.flag("--error")) e = cube_irradiance_error(cube, probe_irradiance(probe, 0), probe.w, probe.h);
  if (a.flag("--json")) {
    nlohmann::ordered_json j;
    j["probe"] = path;
    j["width"] = probe.w;
    j["height"] = probe.h;
    j["fit"] = ambient_fit_name(fit);
    nlohmann::ordered_json faces;
    for (int f = 0; f < 6; ++f) faces[kFaceNames[f]] = {cube[f][0], cube[f][1], cube[f][2]};
    j["faces"] = faces;
    if (a.flag("--error")) j["irradiance_rms"] = {{"pixels", e.rms_pixels}, {"solid_angle", e.rms_solid_angle}};
    printf("%s\n", j.dump(2).c_str());
    return 0;
  }
  printf("%s (%d x %d), fit %s: ambient cube (irradiance over pi)\n", path.c_str(), probe.w, probe.h,
         ambient_fit_name(fit));
  for (int f = 0; f < 6; ++f) printf("  %s  %.9g %.9g %.9g\n", kFaceNames[f], cube[f][0], cube[f][1], cube[f][2]);
  if (a.flag("--error"))
    printf("irradiance RMS against the exact irradiance: %.6f (lat-long pixels), %.6f (solid angle)\n", e.rms_pixels,
           e.rms_solid_angle);
  return 0;
}

// tiershade bench: the ambient section of `tiershade bench` (docs/accuracy_cost.md): the ambient-cube
// fits of the two shipped light probes (irradiance RMS against the exact irradiance, both metrics,
// and the time per fit), and the irradiance volume of the lightmapped room with a model in it at
// Source's density, half and double (bake time, memory, and how far each lookup's cube along a walk
// through the room is from a volume four times as dense). Not a test: nothing here passes or fails.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bake/ambient_fit.h"
#include "bake/probulator_reference.h"
#include "bench/ambient_volume.h"
#include "base/stats.h"
#include "demo/scene_files.h"
#include "families/family.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"

namespace {
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

bool probe_rows(const BenchOptions &opt, std::ostringstream &o, std::string *err) {
  struct Probe {
    const char *name;
    double ac, projection;  // Probulator's published irradiance RMS (issue 13; kayru/Probulator reports)
  } const probes[] = {{"grace", 0.0436, 0.0516}, {"uffizi", 0.181, 0.219}};
  o << "| probe | fit | irradiance RMS, lat-long pixels | irradiance RMS, solid angle | ms per fit |\n|---|---|---|---|---|\n";
  char b[256];
  for (const Probe &p : probes) {
    ImageF img;
    const std::string path = std::string("../shared/data/probes/") + p.name + ".hdr";
    if (!read_latlong_probe(path, &img, err)) return false;
    const std::vector<double> exact = probe_irradiance(img, 0);
    for (AmbientFit fit : {AmbientFit::Mean, AmbientFit::Lsq, AmbientFit::LsqPixels, AmbientFit::LsqRadiance}) {
      float cube[6][3];
      std::vector<double> times;
      const int runs = fit == AmbientFit::LsqPixels ? 1 : std::max(1, opt.runs);
      for (int r = 0; r < runs; ++r) {
        const auto t0 = Clock::now();
        fit_probe_cube(img, fit, cube);
        times.push_back(ms_since(t0));
      }
      const CubeIrradianceError e = cube_irradiance_error(cube, exact, img.w, img.h);
      snprintf(b, sizeof b, "| %s %dx%d | %s | %.4f | %.4f | %.2f |\n", p.name, img.w, img.h, ambient_fit_name(fit),
               e.rms_pixels, e.rms_solid_angle, median(times));
      o << b;
    }
    snprintf(b, sizeof b, "| %s | Probulator AC (published) | %.4f | - | - |\n| %s | Probulator projection (published) | %.4f | - | - |\n",
             p.name, p.ac, p.name, p.projection);
    o << b;
    // The same cubes on Probulator's own reference (its Monte Carlo estimate and pixel grid, reproduced:
    // glue/bake/probulator_reference.h), where its published numbers were measured.
    const ProbulatorReference ref = probulator_reference(img);
    float fitted[6][3];
    fit_cube_to_reference(ref, false, fitted);
    for (AmbientFit fit : {AmbientFit::Mean, AmbientFit::Lsq, AmbientFit::LsqPixels}) {
      float cube[6][3];
      fit_probe_cube(img, fit, cube);
      const ReferenceError e = cube_reference_error(cube, ref);
      snprintf(b, sizeof b, "| %s | %s, on Probulator's reference | %.4f | %.4f | - |\n", p.name, ambient_fit_name(fit),
               e.rms_pixels, e.rms_solid_angle);
      o << b;
    }
    const ReferenceError ef = cube_reference_error(fitted, ref);
    snprintf(b, sizeof b, "| %s | Probulator's AC reproduced (NNLS on its reference) | %.4f | %.4f | - |\n", p.name,
             ef.rms_pixels, ef.rms_solid_angle);
    o << b;
  }
  return true;
}

// The room with a small model (a copy of its first primitive at 5 % scale) at `at`: a scene with world
// faces, a sky, bounces and a model (large_hall_40, below, has world and models but no sky or bounces).
Scene room_with_model(const Scene &room, const double at[3]) {
  Scene s = room;
  SceneMaterial mm;
  mm.name = "bench_model";
  mm.where = "materials[bench]";
  mm.shader = SceneShader::Model;
  s.materials.push_back(mm);
  ScenePrimitive m = scene_flattened(room, room.primitives[0]);  // its vertices are edited below
  m.material = static_cast<int>(s.materials.size()) - 1;
  m.instance = -1;
  m.where = "bench model";
  double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30};
  for (size_t i = 0; i < m.position.size(); ++i) {
    lo[i % 3] = std::fmin(lo[i % 3], m.position[i]);
    hi[i % 3] = std::fmax(hi[i % 3], m.position[i]);
  }
  for (size_t i = 0; i < m.position.size(); ++i)
    m.position[i] = static_cast<float>((m.position[i] - 0.5 * (lo[i % 3] + hi[i % 3])) * 0.05 + at[i % 3]);
  s.primitives.push_back(m);
  return s;
}

bool volume_of(const Scene &s, double scale, PreparedScene *ps, std::string *err) {
  Scene v = s;
  for (double &x : v.volume.spacing) x *= scale;
  SceneSelection sel;
  return select_scene_variants(v, Tier::SM3, "", &sel, err) && prepare_scene(v, sel, 16, 16, Api::GL33, 1.f, ps, err);
}

// RMS over a walk of 64 points (and the six faces, three channels) of a lookup against the reference.
double walk_rms(const IrradianceVolume &v, VolumeLookup look, const IrradianceVolume &ref) {
  double sum = 0;
  int n = 0;
  for (int i = 0; i < 64; ++i) {
    const double t = (i + 0.5) / 64;
    const double p[3] = {ref.origin[0] + t * (ref.n[0] - 1) * ref.step[0], 1.0,
                         ref.origin[2] + (1 - t) * (ref.n[2] - 1) * ref.step[2]};
    float a[6][3], r[6][3];
    volume_cube_at(v, p, look, a, nullptr);
    volume_cube_at(ref, p, VolumeLookup::Trilinear, r, nullptr);
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 3; ++k, ++n) sum += (a[f][k] - r[f][k]) * (a[f][k] - r[f][k]);
  }
  return std::sqrt(sum / n);
}

bool volume_rows(std::ostringstream &o, std::string *err) {
  Scene room;
  if (!load_scene(kWorldLightingGltf, &room, err)) return false;
  const double at[3] = {0.5, 1.0, 0.3};
  const Scene s = room_with_model(room, at);
  PreparedScene ref;
  if (!volume_of(s, 0.25, &ref, err)) return false;
  o << "\nThe irradiance volume of `" << kWorldLightingGltf << "` with a small model added (the room has the sky and "
    << "the bounces that large_hall_40 below lacks),\nbaked at each density over the world faces' box (162 rays per sample, lsq fit; "
    << "docs/irradiance_volume.md). **walk RMS**: the model's cube\nalong 64 points of a diagonal walk at 1 m height "
    << "against the volume four times as dense as Source's (" << ref.volume.cube.size() << " samples), trilinear.\n\n"
    << "| density | spacing (m) | samples | valid | rays | bake ms | memory KiB | walk RMS trilinear | walk RMS inverse-square |\n"
    << "|---|---|---|---|---|---|---|---|---|\n";
  struct Row {
    const char *label;
    double scale;
  } const rows[] = {{"Source's 4 x 8 x 4 ft", 1.0}, {"half (8 x 16 x 8 ft)", 2.0}, {"double (2 x 4 x 2 ft)", 0.5}};
  char b[320];
  for (const Row &r : rows) {
    PreparedScene ps;
    if (!volume_of(s, r.scale, &ps, err)) return false;
    const IrradianceVolume &v = ps.volume;
    int valid = 0;
    for (uint8_t x : v.valid) valid += x;
    snprintf(b, sizeof b, "| %s | %.3f x %.3f x %.3f | %d x %d x %d | %d | %ld | %.1f | %.1f | %.4f | %.4f |\n", r.label,
             v.step[0], v.step[1], v.step[2], v.n[0], v.n[1], v.n[2], valid, v.rays, v.bake_ms, v.bytes() / 1024.0,
             walk_rms(v, VolumeLookup::Trilinear, ref.volume), walk_rms(v, VolumeLookup::InverseSquare, ref.volume));
    o << b;
  }
  return true;
}

bool run(const BenchOptions &opt, std::string *md, std::string *err) {
  std::ostringstream o;
  o << "## ambient (ambient-cube fits and the irradiance volume)\n\n"
    << "Each fit of the shipped probes (`../shared/data/probes/`, 256 x 128 lat-long) against the exact irradiance over pi "
    << "at every texel\ncentre (docs/irradiance_volume.md): RMS over the lat-long pixels (Probulator's metric) and "
    << "solid-angle weighted; ms per fit: median\nof the runs (lsq-pixels: one run, it computes the exact irradiance "
    << "first). Rows \"on Probulator's reference\": the same cubes measured against Probulator's own\nreference, "
    << "where its published numbers come from (its 5000-sample importance-sampled Monte Carlo estimate, jitter off, "
    << "at its pixel\ndirections (p + 0.5) / (size - 1), reproduced by glue/bake/probulator_reference.cpp), and "
    << "Probulator's AC itself reproduced: the NNLS fit\nto that reference.\n\n";
  if (!probe_rows(opt, o, err)) return false;
  o << "\nThe per-pixel error of a cube against the exact irradiance of the same probe (`make demo`, section "
       "ambient_sphere: glue/demo/ambient_sphere.cpp): a diffuse sphere from +Z and from -Z per probe (rows: grace, "
       "grace, uffizi, uffizi), lit by\nthe exact irradiance, by the lsq cube, by the mean cube, then the lsq and the "
       "mean cube's signed luminance error (orange: too bright, blue: too dark, linear, full colour at 50 % of the\nexact "
       "sphere's mean luminance).\n\n![ambient cube error on a sphere](images/ambient_sphere.png)\n";
  if (!volume_rows(o, err) || !ambient_volume_rows(o, err)) return false;
  *md = o.str();
  return true;
}

const BenchSection kSection = {"ambient", run};
const BenchRegistrar kRegister(&kSection);
}  // namespace

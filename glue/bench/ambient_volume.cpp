// tiershade bench: the ambient section's model frame error (docs/accuracy_cost.md, issue 13): on a
// shipped scene with world faces and models (scenes/large_hall_40.gltf), each model pixel's ambient
// term (the cube at its normal, white albedo, linear) against the exact irradiance over pi at that
// shaded point, ray traced through the bake's Embree scene (glue/bake/ray_scene.h) with the baked
// world's radiosity and the sky (volume_ray_radiance: what the volume's own rays see; the models
// occlude), many cosine-weighted rays per pixel; for the hand-placed samples (nearest), the volume
// (nearest, trilinear, inverse-square), the mean and least-squares fits, and Source's density, half
// and double with bake time and memory, with the volume's rays passing through the models (the
// default) and stopped by them. Not a test: nothing here passes or fails.
#include "bench/ambient_volume.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "bake/ray_scene.h"
#include "bake/volume_file.h"
#include "base/parallel_rows.h"
#include "scene/bake_inputs.h"
#include "scene/deferred.h"
#include "scene/scene_volume.h"
#include "shaderlib/variants.h"

namespace {
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

const char kScene[] = "scenes/large_hall_40.gltf";
const int kW = 320, kH = 180;  // the frame (the scene's camera)
const int kStrata = 48;  // 48 x 48 = 2304 cosine-weighted rays per model pixel

// A shaded point of a model: its draw, position, unit normal, and the exact E / pi there.
struct ModelPixel {
  int draw;
  glm::dvec3 p, n;
  glm::dvec3 e;  // E / pi, the reference
  glm::dvec3 se;  // its Monte Carlo standard error
};

// The ambient cube at normal n (fact sheet section 3: n.x^2 C[x sign] + n.y^2 C[y sign] + n.z^2 C[z sign]).
glm::dvec3 cube_at(const float c[6][3], const glm::dvec3 &n) {
  const double a[3] = {n.x, n.y, n.z};
  glm::dvec3 r(0.0);
  for (int k = 0; k < 3; ++k) {
    const float *f = c[2 * k + (a[k] < 0 ? 1 : 0)];
    r += a[k] * a[k] * glm::dvec3(f[0], f[1], f[2]);
  }
  return r;
}

uint64_t splitmix(uint64_t *s) {
  uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
double uniform(uint64_t *s) { return (splitmix(s) >> 11) * (1.0 / 9007199254740992.0); }

// The world as the bake saw it: faces (in the bake's order), their flat lightmaps, the ray scene
// (rebuilt with the same face ids) and the volume's settings; checked against the volume's hash.
struct World {
  std::vector<WorldFace> faces;
  std::vector<LuxelGrid> grids;
  RayScene rays;
  SceneVolumeSetup setup;
  std::vector<ModelEmitter> emitters;  // the emissive models the volume's rays see (glue/bake/area_lights.h)
};
bool world_of(const Scene &s, const SceneSelection &sel, const PreparedScene &p, World *w, std::string *err) {
  std::vector<int> face_of_draw(sel.draws.size(), -1);
  int nf = 0;
  for (size_t di = 0; di < sel.draws.size(); ++di)
    if (sel.draws[di].family == "world_lighting" && s.primitives[sel.draws[di].primitive].indices.size() >= 3)
      face_of_draw[di] = nf++;
  for (const BakeFace &f : p.bake_summary.faces) w->faces.push_back(f.face);
  if (nf != static_cast<int>(w->faces.size())) {
    *err = "ambient bench: " + std::to_string(nf) + " world draws, the bake has " + std::to_string(w->faces.size()) + " faces";
    return false;
  }
  w->grids = flat_grids_from_page(p.lightmap_places, p.lightmap_page, p.lightmap_w);
  std::vector<int> emitter_of;
  w->emitters = scene_model_emitters(s, face_of_draw, &emitter_of);
  if (!build_scene_rays(s, face_of_draw, &w->rays, err, &emitter_of)) return false;
  w->setup = scene_volume_setup(s, w->faces);
  w->setup.set.model_emitters = &w->emitters;
  const uint64_t h = volume_inputs_hash(volume_inputs(w->setup.lo, w->setup.hi, w->setup.set, w->faces, w->grids,
                                                      w->rays.content_hash(), w->setup.sky_hash));
  if (h != p.volume.inputs_hash) {
    *err = "ambient bench: the rebuilt world is not the one the volume was baked from (inputs hash differs)";
    return false;
  }
  return true;
}

// The model pixels of the G-buffer and their exact E / pi (kStrata^2 stratified cosine-weighted rays).
std::vector<ModelPixel> model_pixels(const SceneGBufferCpu &g, const World &w, long *rays, double *ms) {
  const auto t0 = Clock::now();
  // The truth at a model pixel: every model (itself and the others) stops light, whatever the volume does.
  VolumeSettings truth = w.setup.set;
  truth.models_occlude = true;
  std::vector<ModelPixel> px;
  for (size_t i = 0; i < g.draw.size(); ++i) {
    const int d = g.draw[i];
    if (d < 0 || g.p.draws[static_cast<size_t>(d)].world) continue;
    const float *sl = &g.slots[i * 24];
    const glm::dvec3 n(sl[0], sl[1], sl[2]);
    if (!(glm::length(n) > 0)) continue;
    px.push_back({d, glm::dvec3(sl[4], sl[5], sl[6]), glm::normalize(n), glm::dvec3(0.0), glm::dvec3(0.0)});
  }
  parallel_rows(static_cast<int>(px.size()), 0, [&](int i) {
    ModelPixel &m = px[static_cast<size_t>(i)];
    const glm::dvec3 t = glm::normalize(std::fabs(m.n.x) > 0.5 ? glm::cross(m.n, glm::dvec3(0, 1, 0))
                                                               : glm::cross(m.n, glm::dvec3(1, 0, 0)));
    const glm::dvec3 b = glm::cross(m.n, t);
    uint64_t seed = 0x5eed0000ull + static_cast<uint64_t>(i);
    glm::dvec3 sum(0.0), sum2(0.0);
    const glm::dvec3 o = m.p + m.n * 1e-4;
    for (int a = 0; a < kStrata; ++a)
      for (int c = 0; c < kStrata; ++c) {
        // Cosine-weighted (Malley): the mean radiance of these directions is E / pi.
        const double u1 = (a + uniform(&seed)) / kStrata, u2 = (c + uniform(&seed)) / kStrata;
        const double r = std::sqrt(u1), phi = 2 * 3.14159265358979323846 * u2;
        const glm::dvec3 d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + m.n * std::sqrt(1 - u1);
        const glm::dvec3 l = volume_ray_radiance(o, d, w.faces, w.grids, w.rays, truth, nullptr);
        sum += l;
        sum2 += l * l;
      }
    const double nr = kStrata * kStrata;
    m.e = sum / nr;
    // The standard error of an unstratified estimate: an upper bound of the stratified one's.
    m.se = glm::sqrt(glm::max(sum2 / nr - m.e * m.e, glm::dvec3(0.0)) / nr);
  });
  *rays = static_cast<long>(px.size()) * kStrata * kStrata;
  *ms = ms_since(t0);
  return px;
}

// A model draw's centre (prepare.cpp's: the instance's, else the primitive's box centre).
glm::dvec3 draw_center(const Scene &s, const PreparedDraw &d) {
  const ScenePrimitive &p = s.primitives[static_cast<size_t>(d.choice->primitive)];
  if (p.instance >= 0) {
    const double *c = s.instances.at(static_cast<size_t>(p.instance)).center;
    return glm::dvec3(c[0], c[1], c[2]);
  }
  glm::dvec3 lo(1e300), hi(-1e300);
  for (size_t i = 0; i + 2 < p.position.size(); i += 3) {
    const glm::dvec3 q(p.position[i], p.position[i + 1], p.position[i + 2]);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  return 0.5 * (lo + hi);
}

struct Err {
  double rms = 0, rel = 0, bias = 0;
};
// RMS over the model pixels and channels of cube(n) - E/pi; rel: RMS / the mean of E/pi; bias: mean.
Err frame_error(const std::vector<ModelPixel> &px, const std::vector<std::array<std::array<float, 3>, 6>> &cubes) {
  double s2 = 0, s1 = 0, se = 0;
  for (const ModelPixel &m : px) {
    float c[6][3];
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 3; ++k) c[f][k] = cubes[static_cast<size_t>(m.draw)][f][k];
    const glm::dvec3 d = cube_at(c, m.n) - m.e;
    s2 += glm::dot(d, d);
    s1 += d.x + d.y + d.z;
    se += m.e.x + m.e.y + m.e.z;
  }
  const double n = 3.0 * px.size();
  return {std::sqrt(s2 / n), std::sqrt(s2 / n) / (se / n), s1 / n};
}

// Each draw's cube from the volume with `look` (world draws: unused zeros).
std::vector<std::array<std::array<float, 3>, 6>> volume_cubes(const Scene &s, const PreparedScene &p,
                                                              const IrradianceVolume &v, VolumeLookup look) {
  std::vector<std::array<std::array<float, 3>, 6>> out(p.draws.size());
  for (size_t i = 0; i < p.draws.size(); ++i) {
    if (p.draws[i].world) continue;
    const glm::dvec3 c = draw_center(s, p.draws[i]);
    const double at[3] = {c.x, c.y, c.z};
    float cube[6][3];
    volume_cube_at(v, at, look, cube, nullptr);
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 3; ++k) out[i][f][k] = cube[f][k];
  }
  return out;
}

bool volume_of(const Scene &s, double scale, const char *fit, PreparedScene *p, std::string *err) {
  Scene v = s;
  for (double &x : v.volume.spacing) x *= scale;
  v.volume.fit = fit;
  SceneSelection sel;
  return select_scene_variants(v, Tier::SM3, "", &sel, err) && prepare_scene(v, sel, 16, 16, Api::GL33, 1.f, p, err);
}

}  // namespace

bool ambient_volume_rows(std::ostringstream &o, std::string *err) {
  Scene hand;
  if (!load_scene(kScene, &hand, err)) return false;
  Scene s = hand;
  s.ambient.clear();  // the models take the volume (hand-typed samples are the override)
  SceneGBufferCpu g;
  if (!scene_gbuffer_cpu(s, Tier::SM3, kW, kH, false, &g, err)) return false;
  World w;
  if (!world_of(s, g.sel, g.p, &w, err)) return false;
  long rays = 0;
  double gt_ms = 0;
  const std::vector<ModelPixel> px = model_pixels(g, w, &rays, &gt_ms);
  if (px.empty()) {
    *err = std::string("ambient bench: no model pixel in ") + kScene;
    return false;
  }
  double mean_e = 0, se2 = 0;
  for (const ModelPixel &m : px) {
    mean_e += (m.e.x + m.e.y + m.e.z) / (3.0 * px.size());
    se2 += glm::dot(m.se, m.se) / (3.0 * px.size());
  }
  char b[2400];
  snprintf(b, sizeof b,
           "\n### Model frame error against per-pixel ground truth\n\n`%s` (world faces, %zu draws, %zu lights, its %zu "
           "hand-placed ambient samples) at %d x %d, its camera: %zu model pixels. Reference: the exact irradiance "
           "over pi at each shaded point (G-buffer position and normal), %d cosine-weighted stratified rays per pixel "
           "(%ld rays, %.0f ms) through the bake's Embree scene, each seeing the baked world's radiosity (flat "
           "lightmap x reflectivity + emission) or the sky, as the volume's own rays do, and the models as "
           "occluders (radiance 0; the volume's rays pass through them); its mean %.4f, Monte Carlo standard error "
           "(RMS, an upper bound) %.5f. Error: the ambient "
           "term cube(n) (white albedo, linear, before lights are folded in; the lights are shaded the same way in "
           "every row) minus the reference, RMS over model pixels and channels, relative to the reference's mean; "
           "bias: the mean signed error.\n\n",
           kScene, g.p.draws.size(), s.lights.size(), hand.ambient.size(), kW, kH, px.size(), kStrata * kStrata, rays, gt_ms, mean_e, std::sqrt(se2));
  o << b;
  o << "| cube source | lookup | fit | RMS | relative | bias |\n|---|---|---|---|---|---|\n";
  auto row = [&](const char *src, const char *look, const char *fit, const Err &e) {
    snprintf(b, sizeof b, "| %s | %s | %s | %.4f | %.1f %% | %+.4f |\n", src, look, fit, e.rms, 100 * e.rel, e.bias);
    o << b;
  };
  {  // the scene's own hand-placed samples, nearest to the model's centre (prepare.cpp's nearest_of)
    std::vector<std::array<std::array<float, 3>, 6>> cubes(g.p.draws.size());
    for (size_t i = 0; i < g.p.draws.size(); ++i) {
      if (g.p.draws[i].world) continue;
      const glm::dvec3 c = draw_center(s, g.p.draws[i]);
      double best = INFINITY;
      for (const SceneAmbientSample &a : hand.ambient) {
        const glm::dvec3 d = glm::dvec3(a.position[0], a.position[1], a.position[2]) - c;
        if (a.from_probe < 0 && glm::dot(d, d) < best) {
          best = glm::dot(d, d);
          for (int f = 0; f < 6; ++f)
            for (int k = 0; k < 3; ++k) cubes[i][f][k] = a.cube[f][k];
        }
      }
    }
    row("hand-placed samples (the scene's)", "nearest", "-", frame_error(px, cubes));
  }
  const IrradianceVolume &v = g.p.volume;
  row("volume, Source's density", "nearest", "lsq", frame_error(px, volume_cubes(s, g.p, v, VolumeLookup::Nearest)));
  row("volume, Source's density", "trilinear", "lsq", frame_error(px, volume_cubes(s, g.p, v, VolumeLookup::Trilinear)));
  row("volume, Source's density", "inverse-square", "lsq",
      frame_error(px, volume_cubes(s, g.p, v, VolumeLookup::InverseSquare)));
  PreparedScene mean;
  if (!volume_of(s, 1.0, "mean", &mean, err)) return false;
  row("volume, Source's density", "trilinear", "mean",
      frame_error(px, volume_cubes(s, g.p, mean.volume, VolumeLookup::Trilinear)));
  row("volume, Source's density", "inverse-square", "mean",
      frame_error(px, volume_cubes(s, g.p, mean.volume, VolumeLookup::InverseSquare)));

  o << "\nAgainst density (lsq fit): the volume over the world faces' box, 162 rays per sample; bake ms: the "
       "volume alone (not the lightmaps), one run; memory: the samples (cubes, validity, back-face shares) and "
       "volume.bin's size in the bake directory.\n\n"
    << "The volume's rays pass through the models to the world behind (as vrad, which never sees dynamic "
       "models). Rows \"rays stopped by the models\": the models are black back-face hits for the volume's rays "
       "too (`VolumeSettings::models_occlude` true), what the scenes baked before.\n\n"
    << "| density | spacing (m) | samples | valid | rays | bake ms | memory KiB | volume.bin KiB | RMS trilinear | "
       "bias trilinear | RMS inverse-square | RMS nearest | mean back-face share of the samples used |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  struct Density {
    const char *label;
    double scale;
  } const rows[] = {{"Source's 4 x 8 x 4 ft", 1.0}, {"half (8 x 16 x 8 ft)", 2.0}, {"double (2 x 4 x 2 ft)", 0.5}};
  // One row: a volume's frame errors, bake and memory, and the back-face share of the samples the
  // models' trilinear lookups use.
  auto density_row = [&](const std::string &label, const IrradianceVolume &dv) {
    int valid = 0;
    for (uint8_t x : dv.valid) valid += x;
    double share = 0, wsum = 0;
    for (const PreparedDraw &d : g.p.draws) {
      if (d.world) continue;
      const glm::dvec3 c = draw_center(s, d);
      const double at[3] = {c.x, c.y, c.z};
      float cube[6][3];
      std::vector<VolumeContribution> used;
      volume_cube_at(dv, at, VolumeLookup::Trilinear, cube, &used);
      for (const VolumeContribution &u : used) {
        share += u.weight * dv.back_share[dv.index(u.i, u.j, u.k)];
        wsum += u.weight;
      }
    }
    const Err tri = frame_error(px, volume_cubes(s, g.p, dv, VolumeLookup::Trilinear));
    snprintf(b, sizeof b,
             "| %s | %.3f x %.3f x %.3f | %d x %d x %d | %d | %ld | %.0f | %.1f | %.1f | %.4f | %+.4f | %.4f | %.4f | %.3f |\n",
             label.c_str(), dv.step[0], dv.step[1], dv.step[2], dv.n[0], dv.n[1], dv.n[2], valid, dv.rays, dv.bake_ms,
             dv.bytes() / 1024.0, volume_file_bytes(dv).size() / 1024.0, tri.rms, tri.bias,
             frame_error(px, volume_cubes(s, g.p, dv, VolumeLookup::InverseSquare)).rms,
             frame_error(px, volume_cubes(s, g.p, dv, VolumeLookup::Nearest)).rms, wsum > 0 ? share / wsum : 0.0);
    o << b;
  };
  for (const Density &r : rows) {
    PreparedScene p;
    if (!volume_of(s, r.scale, "lsq", &p, err)) return false;
    density_row(r.label, p.volume);
  }
  // The same densities with the models stopping the volume's rays as black back-face hits
  // (VolumeSettings::models_occlude true): not what the scenes bake, measured to show what the models'
  // occlusion of their own samples costs.
  for (const Density &r : rows) {
    VolumeSettings vs = w.setup.set;
    for (double &x : vs.spacing) x *= r.scale;
    vs.models_occlude = true;
    IrradianceVolume wv;
    if (!bake_irradiance_volume(w.setup.lo, w.setup.hi, w.faces, w.grids, w.rays, vs, &wv, err)) return false;
    density_row(std::string(r.label) + ", rays stopped by the models", wv);
  }
  return true;
}

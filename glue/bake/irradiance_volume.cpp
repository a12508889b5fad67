// tiershade bake: the irradiance volume (irradiance_volume.h): its ray directions, the samples' bake
// through the ray scene and the interpolated cube at a point.
#include "bake/irradiance_volume.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <tuple>

#include "bake/area_lights.h"
#include "bake/glm_ts.h"
#include "bake/ray_scene.h"
#include "bake/world_faces.h"
#include "base/parallel_rows.h"
#include "offline/ambient_cube_fit.h"

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kMetresPerSourceUnit = 0.0254;  // Source's unit is the inch (4 ft = 48 units = 1.2192 m)

int fit_code(AmbientFit f) {
  return f == AmbientFit::Mean ? TS_AC_FIT_MEAN : f == AmbientFit::LsqRadiance ? TS_AC_FIT_LSQ_RADIANCE : TS_AC_FIT_LSQ;
}

std::vector<glm::dvec3> make_directions() {
  // Icosahedron: the cyclic permutations of (0, +-1, +-phi); its 30 edges have length 2.
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<glm::dvec3> v;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) {
      v.emplace_back(0, a, b);
      v.emplace_back(a, b, 0);
      v.emplace_back(b, 0, a);
    }
  std::map<std::tuple<long long, long long, long long>, glm::dvec3> points;  // deduplicated, ordered by key
  const int f = 4;  // each face split into f x f triangles: 10 f^2 + 2 = 162 vertices
  for (size_t a = 0; a < v.size(); ++a)
    for (size_t b = a + 1; b < v.size(); ++b)
      for (size_t c = b + 1; c < v.size(); ++c) {
        auto edge = [&](size_t x, size_t y) { return std::fabs(glm::length(v[x] - v[y]) - 2) < 1e-9; };
        if (!edge(a, b) || !edge(b, c) || !edge(a, c)) continue;
        for (int i = 0; i <= f; ++i)
          for (int j = 0; i + j <= f; ++j) {
            const glm::dvec3 p = glm::normalize(v[a] * double(i) + v[b] * double(j) + v[c] * double(f - i - j));
            const auto key = std::make_tuple(std::llround(p.x * 1e9), std::llround(p.y * 1e9), std::llround(p.z * 1e9));
            points.emplace(key, p);
          }
      }
  std::vector<glm::dvec3> out;
  for (const auto &kv : points) out.push_back(kv.second);
  return out;
}
}  // namespace

const std::vector<glm::dvec3> &volume_ray_directions() {
  static const std::vector<glm::dvec3> dirs = make_directions();
  return dirs;
}

glm::dvec3 IrradianceVolume::position(int i, int j, int k) const {
  return glm::dvec3(origin[0] + i * step[0], origin[1] + j * step[1], origin[2] + k * step[2]);
}

size_t IrradianceVolume::bytes() const {
  return cube.size() * sizeof(cube[0]) + valid.size() * sizeof(valid[0]) + back_share.size() * sizeof(back_share[0]);
}

std::vector<LuxelGrid> flat_grids_from_page(const std::vector<lm_face_place> &place, const std::vector<float> &page,
                                            int page_w) {
  std::vector<LuxelGrid> grids(place.size());
  for (size_t fi = 0; fi < place.size(); ++fi) {
    LuxelGrid &g = grids[fi];
    g.w = place[fi].block_w - 2;
    g.h = place[fi].block_h - 2;
    g.v.assign(static_cast<size_t>(g.w) * g.h * 4, ts_v3d(0, 0, 0));
    for (int j = 0; j < g.h; ++j)
      for (int i = 0; i < g.w; ++i) {
        int tx, ty;
        lm_page_texel(&place[fi], 0, i, j, &tx, &ty);
        const float *t = &page[(static_cast<size_t>(ty) * page_w + tx) * 4];
        g.at(i, j, 0) = ts_v3d(t[0], t[1], t[2]);
      }
  }
  return grids;
}

void world_faces_bounds(const std::vector<WorldFace> &faces, double lo[3], double hi[3]) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = faces.empty() ? 0 : INFINITY;
    hi[k] = faces.empty() ? 0 : -INFINITY;
  }
  for (const WorldFace &f : faces)
    for (double a : {0.0, 1.0})
      for (double b : {0.0, 1.0}) {
        const ts_vec3d q = world_face_point(f, a, b);
        const double qq[3] = {q.x, q.y, q.z};
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::fmin(lo[k], qq[k]);
          hi[k] = std::fmax(hi[k], qq[k]);
        }
      }
}

glm::dvec3 volume_ray_radiance(const glm::dvec3 &p, const glm::dvec3 &d, const std::vector<WorldFace> &faces,
                               const std::vector<LuxelGrid> &grids, const RayScene &rays, const VolumeSettings &set,
                               bool *back) {
  if (back) *back = false;
  glm::dvec3 o = p;
  RayScene::Hit hit = rays.intersect(o, d, 1e-5, INFINITY);
  // An emissive model's front: its emission (glue/bake/area_lights.h).
  auto emitter = [&](const RayScene::Hit &h, glm::dvec3 *le) {
    const int k = model_emitter_of_id(h.id);
    return set.model_emitters && h.triangle >= 0 && h.id <= model_emitter_id(0) &&
        k < static_cast<int>(set.model_emitters->size()) &&
        model_emitter_seen((*set.model_emitters)[static_cast<size_t>(k)], h.triangle, d, le);
  };
  glm::dvec3 le;
  // (At most 1024 model surfaces passed: beyond that the ray counts as stopped by geometry.)
  for (int k = 0; k < 1024 && !set.models_occlude && (hit.id < -1 || hit.id >= static_cast<int>(faces.size())) &&
       hit.triangle >= 0;
       ++k) {
    if (emitter(hit, &le)) return le;
    o += d * hit.t;  // through the model to what lies behind it
    hit = rays.intersect(o, d, 1e-5, INFINITY);
  }
  if (emitter(hit, &le)) return le;
  if (hit.id < 0 || hit.id >= static_cast<int>(faces.size())) {
    if (hit.id < 0 && hit.triangle < 0) return set.sky_radiance ? set.sky_radiance(d) : glm::dvec3(0.0);  // a miss
    if (back) *back = true;  // other geometry (a model): counted with the back faces, no radiance
    return glm::dvec3(0.0);
  }
  const WorldFace &f = faces[static_cast<size_t>(hit.id)];
  double ha, hb;
  if (!world_face_hit(f, o + d * hit.t, hit, d, &ha, &hb)) {
    if (back) *back = true;  // the face's back: the sample is behind a wall or inside a solid
    return glm::dvec3(0.0);
  }
  // The face's radiosity where the ray lands (fact sheet section 3: reflectivity applied).
  return to_glm(luxel_exitant(f, grids[static_cast<size_t>(hit.id)], ha, hb));
}

double volume_sample_cube(const glm::dvec3 &p, const std::vector<WorldFace> &faces,
                          const std::vector<LuxelGrid> &grids, const RayScene &rays, const VolumeSettings &set,
                          float cube[6][3]) {
  const std::vector<glm::dvec3> &dirs = volume_ray_directions();
  const double dw = 4 * kPi / static_cast<double>(dirs.size());
  ts_ac_accum acc;
  ts_ac_accum_init(&acc, fit_code(set.fit));
  int back = 0;
  for (const glm::dvec3 &d : dirs) {
    bool b = false;
    const glm::dvec3 rad = volume_ray_radiance(p, d, faces, grids, rays, set, &b);
    back += b;
    const double dd[3] = {d.x, d.y, d.z}, rgb[3] = {rad.x, rad.y, rad.z};
    ts_ac_accum_add(&acc, dd, rgb, dw);
  }
  ts_ac_accum_solve(&acc, cube);
  return back / static_cast<double>(dirs.size());
}

bool bake_irradiance_volume(const double lo[3], const double hi[3], const std::vector<WorldFace> &faces,
                            const std::vector<LuxelGrid> &grids, const RayScene &rays, const VolumeSettings &set,
                            IrradianceVolume *out, std::string *err) {
  const auto t0 = std::chrono::steady_clock::now();
  if (grids.size() != faces.size()) {
    *err = "irradiance volume: " + std::to_string(grids.size()) + " luxel grids for " + std::to_string(faces.size()) +
        " faces";
    return false;
  }
  if (set.fit == AmbientFit::LsqPixels) {
    *err = "irradiance volume: the lsq-pixels fit is for lat-long probes only";
    return false;
  }
  IrradianceVolume v;
  long long total = 1;
  for (int a = 0; a < 3; ++a) {
    const double ext = hi[a] - lo[a];
    if (!(ext >= 0) || !std::isfinite(ext) || !(set.spacing[a] > 0)) {
      *err = "irradiance volume: empty or non-finite bounds or spacing on axis " + std::to_string(a);
      return false;
    }
    v.n[a] = std::max(1, static_cast<int>(std::lround(ext / set.spacing[a])));
    total *= v.n[a];
    if (total > (1LL << 22)) {
      *err = "irradiance volume: more than 4194304 samples (bounds / spacing too fine)";
      return false;
    }
    v.step[a] = ext > 0 ? ext / v.n[a] : set.spacing[a];
    v.origin[a] = lo[a] + 0.5 * (ext > 0 ? v.step[a] : 0);
  }
  const size_t count = static_cast<size_t>(total);
  v.cube.assign(count, {});
  v.valid.assign(count, 0);
  v.back_share.assign(count, 0.f);
  const std::vector<uint8_t> needed = volume_needed_samples(v, set.regions);
  // One row of samples (fixed j, k) per task: each sample depends on its position alone.
  const int rows = v.n[1] * v.n[2];
  parallel_rows(rows, set.threads, [&](int r) {
    const int j = r % v.n[1], k = r / v.n[1];
    for (int i = 0; i < v.n[0]; ++i) {
      if (!needed[v.index(i, j, k)]) continue;  // no model can be near it: invalid, no rays
      float c[6][3];
      const double share = volume_sample_cube(v.position(i, j, k), faces, grids, rays, set, c);
      const size_t idx = v.index(i, j, k);
      for (int f = 0; f < 6; ++f)
        for (int ch = 0; ch < 3; ++ch) v.cube[idx][f][ch] = c[f][ch];
      v.back_share[idx] = static_cast<float>(share);
      v.valid[idx] = share <= set.max_back_share;
    }
  });
  for (uint8_t x : needed) v.baked += x;
  v.rays = static_cast<long>(static_cast<size_t>(v.baked) * volume_ray_directions().size());
  v.bake_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  *out = std::move(v);
  return true;
}

// The low sample of the cell a lookup at coordinate x (axis a) reads, and its fraction: x clamped to
// the sample centres (volume_cube_at and volume_needed_samples share it).
static int volume_cell_base(const IrradianceVolume &v, int a, double x, double *frac = nullptr) {
  const double g = std::clamp((x - v.origin[a]) / v.step[a], 0.0, static_cast<double>(v.n[a] - 1));
  const int base = std::min(std::max(0, v.n[a] - 2), static_cast<int>(std::floor(g)));
  if (frac) *frac = v.n[a] > 1 ? g - base : 0.0;
  return base;
}

std::vector<uint8_t> volume_needed_samples(const IrradianceVolume &grid,
                                           const std::vector<std::array<double, 6>> &regions) {
  const size_t count = static_cast<size_t>(grid.n[0]) * grid.n[1] * grid.n[2];
  std::vector<uint8_t> need(count, regions.empty() ? 1 : 0);
  for (int a = 0; a < 3; ++a)
    if (grid.n[a] < 1) return need;
  for (const std::array<double, 6> &b : regions) {
    int first[3], last[3];
    bool empty = false;
    for (int a = 0; a < 3; ++a) {
      // A lookup at coordinate x reads the samples base(x) and base(x) + 1 (volume_cube_at's clamp);
      // base is monotone in x, so the box reads base(lo) .. base(hi) + 1.
      first[a] = volume_cell_base(grid, a, b[a]);
      last[a] = std::min(grid.n[a] - 1, volume_cell_base(grid, a, b[3 + a]) + 1);
      empty = empty || !(b[3 + a] >= b[a]);
    }
    if (empty) continue;
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i) need[grid.index(i, j, k)] = 1;
  }
  return need;
}

bool volume_cube_at(const IrradianceVolume &v, const double p[3], VolumeLookup lookup, float cube[6][3],
                    std::vector<VolumeContribution> *contrib) {
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) cube[f][c] = 0.f;
  if (contrib) contrib->clear();
  if (v.cube.empty()) return false;
  int base[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    // Grid coordinate of p, clamped to the sample centres; the cell's low corner and the fraction.
    base[a] = volume_cell_base(v, a, p[a], &t[a]);
  }
  std::vector<VolumeContribution> used;
  double wsum = 0;
  for (int c = 0; c < (lookup == VolumeLookup::Nearest ? 0 : 8); ++c) {
    const int o[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
    int q[3];
    bool in = true;
    for (int a = 0; a < 3; ++a) {
      q[a] = base[a] + o[a];
      in = in && q[a] < v.n[a];
    }
    if (!in || !v.valid[v.index(q[0], q[1], q[2])]) continue;
    double w;
    if (lookup == VolumeLookup::Trilinear) {
      w = 1;
      for (int a = 0; a < 3; ++a) w *= o[a] ? t[a] : 1 - t[a];
    } else {
      // Fact sheet section 3: weight 1 / (d^2 + 1), d in Source units (inches).
      const glm::dvec3 d = (v.position(q[0], q[1], q[2]) - glm::dvec3(p[0], p[1], p[2])) / kMetresPerSourceUnit;
      w = 1 / (glm::dot(d, d) + 1);
    }
    if (w <= 0) continue;
    used.push_back({q[0], q[1], q[2], w});
    wsum += w;
  }
  if (used.empty()) {
    // No valid sample around p: the nearest valid sample of the volume (Source: an empty leaf points
    // at the nearest leaf with samples).
    double best = INFINITY;
    for (int k = 0; k < v.n[2]; ++k)
      for (int j = 0; j < v.n[1]; ++j)
        for (int i = 0; i < v.n[0]; ++i) {
          if (!v.valid[v.index(i, j, k)]) continue;
          const glm::dvec3 d = v.position(i, j, k) - glm::dvec3(p[0], p[1], p[2]);
          if (glm::dot(d, d) < best) {
            best = glm::dot(d, d);
            used.assign(1, {i, j, k, 1.0});
          }
        }
    if (used.empty()) return false;
    wsum = 1;
  }
  double acc[6][3] = {};
  for (VolumeContribution &u : used) {
    u.weight /= wsum;
    const auto &cb = v.cube[v.index(u.i, u.j, u.k)];
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) acc[f][c] += u.weight * cb[f][c];
  }
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) cube[f][c] = static_cast<float>(acc[f][c]);
  if (contrib) *contrib = used;
  return true;
}

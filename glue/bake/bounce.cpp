// tiershade bake: diffuse interreflection by gathering (bounce.h).
#include "bake/bounce.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "bake/area_lights.h"
#include "bake/glm_ts.h"
#include "bake/ray_scene.h"
#include "bake/world_faces.h"
#include "base/parallel_rows.h"

namespace {

// splitmix64 (Steele, Lea, Flood 2014): a seeded stream per luxel and pass, so that every luxel's
// rays are the same on any thread count.
struct Rng {
  uint64_t s;
  double next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

// Bilinear over a w x h luxel grid at (a, b) in [0, 1]^2 of the values value(i, j).
template <class V>
ts_vec3d bilinear(int w, int h, double a, double b, V value) {
  const double x = std::clamp(a, 0.0, 1.0) * (w - 1), y = std::clamp(b, 0.0, 1.0) * (h - 1);
  const int i = std::min(w - 2, static_cast<int>(x)), j = std::min(h - 2, static_cast<int>(y));
  const double fx = x - i, fy = y - j;
  const glm::dvec3 r = (value(i, j) * (1 - fx) + value(i + 1, j) * fx) * (1 - fy) +
      (value(i, j + 1) * (1 - fx) + value(i + 1, j + 1) * fx) * fy;
  return to_ts(r);
}

// A gather ray's hit as the passes after the first read it back (vrad likewise computes its transfers
// once, MakeTransfers, and iterates the bounces over them): the face it hit (-1: nothing that sends;
// kBehind: not traced; model_emitter_id(k): an emissive model's front) and the face's grid coordinates.
struct GatherHit {
  int32_t id;
  float a, b;
};
// The cache's budget (12 bytes a ray): the shipped room's 2.2M rays a pass take 27 MB; a bake past it
// traces the rest every pass (the same rays, so the same bytes).
const size_t kGatherCacheBytes = size_t(512) << 20;
const int32_t kBehind = -2;  // GatherHit::id of a direction behind the face (not traced)

ts_vec3d lookup(const std::vector<ts_vec3d> &out, const LuxelGrid &g, double a, double b) {
  return bilinear(g.w, g.h, a, b, [&](int i, int j) { return to_glm(out[static_cast<size_t>(j) * g.w + i]); });
}

}  // namespace

ts_vec3d luxel_exitant(const WorldFace &f, const LuxelGrid &g, double a, double b) {
  return bilinear(g.w, g.h, a, b,
                  [&](int i, int j) { return to_glm(f.emission) + to_glm(f.reflectivity) * to_glm(g.at(i, j, 0)); });
}

bool bounce_light(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
                  const RayScene &rays, const BounceSettings &set, std::vector<LuxelGrid> *grids, BounceReport *report,
                  std::string *err, const BakeHooks *hooks, BakePassState *state) {
  *report = BounceReport();
  if (set.max_bounces <= 0) return true;
  BakePassState own;
  BakePassState &st = state ? *state : own;
  const BakePassState *resume = hooks && hooks->resume && hooks->resume->pass > 0 ? hooks->resume : nullptr;
  if (resume && resume->stopped) {  // every pass was saved: *grids is the result
    *report = resume->report;
    return true;
  }
  if (grids->size() != faces.size()) {
    *err = "bounce: " + std::to_string(grids->size()) + " luxel grids for " + std::to_string(faces.size()) + " faces";
    return false;
  }
  const int side_n = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(set.gather_rays)))));
  const int m = side_n * side_n;
  // The radiance each face's luxels send into the next pass: emission + reflectivity x direct.
  std::vector<std::vector<ts_vec3d>> send(faces.size());
  double total = 0;  // the flat light of every luxel so far (r + g + b), for the stopping rule
  for (size_t f = 0; !resume && f < faces.size(); ++f) {
    const LuxelGrid &g = (*grids)[f];
    send[f].resize(static_cast<size_t>(g.w) * g.h);
    for (int j = 0; j < g.h; ++j)
      for (int i = 0; i < g.w; ++i) {
        const glm::dvec3 e = to_glm(g.at(i, j, 0));
        total += e.x + e.y + e.z;
        // Emission the area lights sampled (glue/bake/area_lights.h) is not sent again.
        const glm::dvec3 le = set.emission_sampled ? glm::dvec3(0.0) : to_glm(faces[f].emission);
        send[f][static_cast<size_t>(j) * g.w + i] = to_ts(le + to_glm(faces[f].reflectivity) * e);
      }
  }
  if (resume) {  // after a saved bounce: what it sends, the sums so far
    send = resume->send;
    total = resume->total;
    *report = resume->report;
  }
  long luxels_total = 0;
  for (const LuxelGrid &g : *grids) luxels_total += static_cast<long>(g.w) * g.h;
  std::vector<LuxelGrid> added = *grids;
  std::vector<std::vector<GatherHit>> cache(faces.size());  // per face: its gather rays' hits
  size_t cache_bytes = 0;
  for (int pass = resume ? resume->pass + 1 : 1; pass <= set.max_bounces; ++pass) {
    const auto t_pass = std::chrono::steady_clock::now();
    const long rays_before = report->rays;
    long luxels_done = 0;
    // Nothing sent (no light, or reflectivity 0 everywhere): no rays to trace.
    // The emissive models' emission, not sampled as area lights: the first pass's rays take it.
    const std::vector<ModelEmitter> *models =
        pass == 1 && !set.emission_sampled && set.model_emitters && !set.model_emitters->empty() ? set.model_emitters
                                                                                                  : nullptr;
    bool sends = false;
    for (size_t k = 0; models && k < models->size(); ++k) {
      const ts_vec3d &le = (*models)[k].emission;
      sends = sends || le.x > 0 || le.y > 0 || le.z > 0;
    }
    for (const std::vector<ts_vec3d> &v : send)
      for (const ts_vec3d &e : v) sends = sends || e.x > 0 || e.y > 0 || e.z > 0;
    if (!sends) break;
    double pass_max = 0, pass_sum = 0;
    for (size_t f = 0; f < faces.size(); ++f) {
      const WorldFace &face = faces[f];
      LuxelGrid &a = added[f];
      if (face.reflectivity.x == 0 && face.reflectivity.y == 0 && face.reflectivity.z == 0) {
        // A black face shows base x lightmap = 0 whatever it gathers, and reflects nothing: no rays.
        std::fill(a.v.begin(), a.v.end(), ts_v3d(0, 0, 0));
        report->skipped_black += static_cast<long>(a.w) * a.h;
        luxels_done += static_cast<long>(a.w) * a.h;
        continue;
      }
      // The gather rays' hits: traced in the first pass that reaches this face and kept for the
      // passes after while the cache's budget lasts (GatherHit); a face beyond it traces every pass.
      const int nv = face.bumped ? 4 : 1;
      const size_t slots = static_cast<size_t>(a.w) * a.h * nv * m;
      std::vector<GatherHit> &hits = cache[f];
      const bool cached = !hits.empty();
      if (!cached && cache_bytes + slots * sizeof(GatherHit) <= kGatherCacheBytes) {
        hits.assign(slots, GatherHit{-1, 0.f, 0.f});
        cache_bytes += slots * sizeof(GatherHit);
      }
      const bool filling = !cached && !hits.empty();
      std::vector<long> rows_traced(static_cast<size_t>(a.h), 0);
      parallel_rows(a.h, set.threads, [&](int j) {
        long traced = 0;
        for (int i = 0; i < a.w; ++i) {
          // The same rays in every pass (the stream of pass 1): the passes iterate one transfer set.
          Rng rng{(static_cast<uint64_t>(1) << 48) ^ (static_cast<uint64_t>(f) << 32) ^
                  (static_cast<uint64_t>(j) << 16) ^ static_cast<uint64_t>(i) ^ (set.seed * 0xD1B54A32D192ED03ull)};
          const size_t slot0 = (static_cast<size_t>(j) * a.w + i) * nv * m;
          glm::dvec3 sum[4] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
          int front[4] = {0, 0, 0, 0};  // per value: its rays on the face's front
          double lobe[4] = {1, 0, 0, 0};  // per value: the share of its cosine lobe on the face's front
          auto add = [&](int k, const GatherHit &g) {
            if (g.id == kBehind) return;
            ++front[k];
            if (g.id >= 0)
              sum[k] += to_glm(lookup(send[static_cast<size_t>(g.id)], (*grids)[static_cast<size_t>(g.id)], g.a, g.b));
            else if (models && g.id <= model_emitter_id(0))  // an emissive model's front (first pass only)
              sum[k] += to_glm((*models)[static_cast<size_t>(model_emitter_of_id(g.id))].emission);
          };
          // Value k is the mean radiance over its lobe's rays on the front times that share of the lobe,
          // (1 + a_k . n) / 2 (the irradiance a plane tilted by acos(a_k . n) receives from a uniform
          // hemisphere, over pi): a ratio estimator, exact in a uniform field, where counting the rays
          // behind the face as 0 would leave each luxel the noise of how many of its rays fell there.
          auto store = [&]() {
            for (int k = 0; k < 4; ++k)
              a.at(i, j, k) = to_ts(front[k] > 0 ? sum[k] * (lobe[k] / front[k]) : glm::dvec3(0.0));
          };
          const LuxelFrame lf = world_luxel_frame(face, bump[f].data(), i, j, a.w, a.h);
          if (!lf.lit) continue;  // a chart's luxel no triangle touches: nothing to gather
          const glm::dvec3 n = to_glm(lf.n), p = to_glm(lf.p) + n * 1e-4;
          for (int k = 1; k < nv; ++k) lobe[k] = std::clamp((1 + glm::dot(to_glm(lf.bump[k - 1]), n)) / 2, 0.0, 1.0);
          if (cached) {
            for (int k = 0; k < nv; ++k)
              for (int s = 0; s < m; ++s) add(k, hits[slot0 + static_cast<size_t>(k) * m + s]);
            store();
            continue;
          }
          // Value k: (1/pi) of the integral of L (a_k . w)+ over the face's front, a_0 = n, a_k = b_k: the
          // mean of L over directions drawn with the cosine lobe of a_k (Malley: a stratified disc
          // sample lifted to the hemisphere), the directions behind the face left out (the ratio
          // estimator above). Each lobe
          // has its own rays, so every estimate is bounded (a 1 / (n . w) weight would not be).
          // A face the shader reads flat (no normal map) gathers its flat value only; its bumped
          // values keep the direct light (nothing samples them).
          for (int k = 0; k < nv; ++k) {
            const glm::dvec3 ax = k == 0 ? n : to_glm(lf.bump[k - 1]);
            const glm::dvec3 side = std::fabs(ax.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
            const glm::dvec3 au = glm::normalize(glm::cross(side, ax)), av = glm::cross(ax, au);
            for (int s = 0; s < m; ++s) {
              const double r1 = (s % side_n + rng.next()) / side_n, r2 = (s / side_n + rng.next()) / side_n;
              const double rad = std::sqrt(r1), phi = 2 * M_PI * r2;
              const glm::dvec3 d = au * (rad * std::cos(phi)) + av * (rad * std::sin(phi)) + ax * std::sqrt(1 - r1);
              GatherHit g{kBehind, 0.f, 0.f};  // behind the face: it feeds none of the values
              if (glm::dot(d, n) > 0) {
                g.id = -1;  // nothing that sends: other geometry, a back, a miss
                ++traced;
                const RayScene::Hit h = rays.intersect(p, d, 0.0, INFINITY);
                glm::dvec3 le;
                if (h.triangle >= 0 && h.id <= model_emitter_id(0) && set.model_emitters &&
                    model_emitter_of_id(h.id) < static_cast<int>(set.model_emitters->size())) {
                  if (model_emitter_seen((*set.model_emitters)[static_cast<size_t>(model_emitter_of_id(h.id))],
                                         h.triangle, d, &le))
                    g.id = h.id;  // an emissive model's front
                } else if (h.id >= 0 && h.id < static_cast<int>(faces.size())) {
                  double ha, hb;  // (kept as floats, traced or cached alike: the same bytes either way)
                  if (world_face_hit(faces[static_cast<size_t>(h.id)], p + d * h.t, h, d, &ha, &hb))
                    g = GatherHit{h.id, static_cast<float>(ha), static_cast<float>(hb)};  // a face's back sends nothing
                }
              }
              if (filling) hits[slot0 + static_cast<size_t>(k) * m + s] = g;
              add(k, g);
            }
          }
          store();
        }
        rows_traced[static_cast<size_t>(j)] = traced;
      });
      if (cached) report->cached += static_cast<long>(slots);
      for (long t : rows_traced) report->rays += t;
      luxels_done += static_cast<long>(a.w) * a.h;
      if (hooks && hooks->progress) hooks->progress("bounce " + std::to_string(pass), luxels_done, luxels_total);
    }
    // Add this pass, and send its flat light on (times the reflectivity) into the next.
    for (size_t f = 0; f < faces.size(); ++f) {
      LuxelGrid &g = (*grids)[f];
      const LuxelGrid &a = added[f];
      for (int j = 0; j < g.h; ++j)
        for (int i = 0; i < g.w; ++i) {
          for (int k = 0; k < 4; ++k) g.at(i, j, k) = to_ts(to_glm(g.at(i, j, k)) + to_glm(a.at(i, j, k)));
          const glm::dvec3 e = to_glm(a.at(i, j, 0));
          pass_max = std::max(pass_max, std::max(e.x, std::max(e.y, e.z)));
          pass_sum += e.x + e.y + e.z;
          send[f][static_cast<size_t>(j) * g.w + i] = to_ts(to_glm(faces[f].reflectivity) * e);
        }
    }
    report->passes = pass;
    report->added.push_back(pass_max);
    report->pass_rays.push_back(report->rays - rays_before);
    report->pass_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_pass).count());
    total += pass_sum;
    const bool stop = pass_sum <= set.threshold * total;
    if (hooks && hooks->on_pass) {  // the state pass + 1 starts from (a checkpoint)
      st.pass = pass;
      st.stopped = stop || pass == set.max_bounces;
      st.grids = *grids;
      st.send = send;
      st.total = total;
      st.report = *report;
      if (!hooks->on_pass(st, err)) return false;
    }
    if (stop) break;
  }
  return true;
}

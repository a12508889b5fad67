// tiershade bake: emissive faces as area lights (area_lights.h).
#include "bake/area_lights.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bake/glm_ts.h"
#include "bake/luxel_rng.h"
#include "bake/ray_scene.h"
#include "bake/world_faces.h"
#include "base/parallel_rows.h"

SphericalRect spherical_rect(const glm::dvec3 &o, const glm::dvec3 &c, const glm::dvec3 &ex, const glm::dvec3 &ey) {
  // Urena, Fajardo, King 2013, section 3.1: the rectangle in a frame centred on o, its plane at
  // z = z0 < 0; the spherical rectangle's four edge-plane normals n0..n3 and internal angles
  // g0..g3 give its solid angle S = g0 + g1 + g2 + g3 - 2 pi.
  SphericalRect r;
  const double exl = glm::length(ex), eyl = glm::length(ey);
  if (!(exl > 0 && eyl > 0)) return r;
  r.o = o;
  r.x = ex / exl;
  r.y = ey / eyl;
  r.z = glm::cross(r.x, r.y);
  const glm::dvec3 d = c - o;
  r.z0 = glm::dot(d, r.z);
  if (r.z0 > 0) {
    r.z = -r.z;
    r.z0 = -r.z0;
  }
  if (!(r.z0 < -1e-9)) return r;  // o in the rectangle's plane: it subtends nothing
  r.x0 = glm::dot(d, r.x);
  r.y0 = glm::dot(d, r.y);
  r.x1 = r.x0 + exl;
  r.y1 = r.y0 + eyl;
  const glm::dvec3 v00(r.x0, r.y0, r.z0), v01(r.x0, r.y1, r.z0), v10(r.x1, r.y0, r.z0), v11(r.x1, r.y1, r.z0);
  const glm::dvec3 n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11));
  const glm::dvec3 n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
  auto angle = [](const glm::dvec3 &a, const glm::dvec3 &b) { return std::acos(std::clamp(-glm::dot(a, b), -1.0, 1.0)); };
  const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
  r.b0 = n0.z;
  r.b1 = n2.z;
  r.k = 2 * M_PI - g2 - g3;
  r.solid_angle = g0 + g1 - r.k;
  r.ok = r.solid_angle > 0;
  return r;
}

glm::dvec3 spherical_rect_point(const SphericalRect &r, double u, double v) {
  // Section 3.2: u picks the sub-rectangle of solid angle u S (its edge at x = xu), then v the
  // height along it, uniform in the sine of the elevation (h0..h1).
  const double au = u * r.solid_angle + r.k, fu = (std::cos(au) * r.b0 - r.b1) / std::sin(au);
  double cu = (fu > 0 ? 1.0 : -1.0) / std::sqrt(fu * fu + r.b0 * r.b0);
  cu = std::clamp(cu, -1.0, 1.0);
  double xu = -(cu * r.z0) / std::sqrt(std::max(1e-300, 1 - cu * cu));
  xu = std::clamp(xu, r.x0, r.x1);
  const double dd = std::sqrt(xu * xu + r.z0 * r.z0);
  const double h0 = r.y0 / std::sqrt(dd * dd + r.y0 * r.y0), h1 = r.y1 / std::sqrt(dd * dd + r.y1 * r.y1);
  const double hv = h0 + v * (h1 - h0), hv2 = hv * hv;
  const double yv = hv2 < 1 - 1e-12 ? std::clamp(hv * dd / std::sqrt(1 - hv2), r.y0, r.y1) : r.y1;
  return r.o + r.x * xu + r.y * yv + r.z * r.z0;
}

namespace {

// The polygon (vertices relative to the luxel) clipped to the half-space a . x >= 0 (Sutherland and
// Hodgman 1974, one plane through the origin).
std::vector<glm::dvec3> clip(const std::vector<glm::dvec3> &poly, const glm::dvec3 &a) {
  std::vector<glm::dvec3> out;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 &p = poly[i], &q = poly[(i + 1) % poly.size()];
    const double dp = glm::dot(a, p), dq = glm::dot(a, q);
    if (dp >= 0) out.push_back(p);
    if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return out;
}

// (1/pi) integral over the polygon's solid angle of (a . w) dw, for a polygon on a's side: Lambert's
// formula for the form factor of a polygon (the vector irradiance (1/2pi) sum_i theta_i u_i, theta_i
// the angle an edge subtends, u_i its plane's unit normal; Arvo, "Applications of irradiance
// tensors", SIGGRAPH 1995, eq. 9), its sign set by the winding.
double polygon_factor(const std::vector<glm::dvec3> &poly, const glm::dvec3 &a) {
  if (poly.size() < 3) return 0;
  double sum = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 p = glm::normalize(poly[i]), q = glm::normalize(poly[(i + 1) % poly.size()]);
    const glm::dvec3 c = glm::cross(p, q);
    const double len = glm::length(c);
    if (!(len > 1e-15)) continue;  // a vanishing edge subtends nothing
    sum += std::acos(std::clamp(glm::dot(p, q), -1.0, 1.0)) * glm::dot(a, c / len);
  }
  return std::fabs(sum) / (2 * M_PI);
}

}  // namespace

bool area_lights(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
                 const RayScene &rays, const AreaLightSettings &set, std::vector<LuxelGrid> *grids,
                 AreaLightReport *report, std::string *err) {
  *report = AreaLightReport();
  if (grids->size() != faces.size() || bump.size() != faces.size()) {
    *err = "area lights: " + std::to_string(grids->size()) + " luxel grids for " + std::to_string(faces.size()) +
        " faces";
    return false;
  }
  std::vector<size_t> emitters;
  for (size_t e = 0; e < faces.size(); ++e) {
    const ts_vec3d &le = faces[e].emission;
    // A TEXCOORD_1 chart is not a parallelogram: its emission reaches the luxels through the bounces.
    if ((le.x > 0 || le.y > 0 || le.z > 0) && !faces[e].chart) emitters.push_back(e);
  }
  report->emitters = static_cast<int>(emitters.size());
  if (emitters.empty() || set.samples <= 0) return true;
  const auto t0 = std::chrono::steady_clock::now();
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(set.samples)))));
  const int m = side * side;
  for (size_t f = 0; f < faces.size(); ++f) {
    const WorldFace &face = faces[f];
    LuxelGrid &g = (*grids)[f];
    std::vector<long> traced_rows(static_cast<size_t>(g.h), 0);
    parallel_rows(g.h, set.threads, [&](int j) {
      long traced = 0;
      for (int i = 0; i < g.w; ++i) {
        const LuxelFrame lf = world_luxel_frame(face, bump[f].data(), i, j, g.w, g.h);
        if (!lf.lit) continue;  // a chart's luxel no triangle touches
        const glm::dvec3 n = to_glm(lf.n), p = to_glm(lf.p) + n * 1e-4;
        const glm::dvec3 ax[4] = {n, to_glm(lf.bump[0]), to_glm(lf.bump[1]), to_glm(lf.bump[2])};
        glm::dvec3 sum[4] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
        for (size_t e : emitters) {
          if (e == f) continue;  // a face does not light itself (a plane sees none of itself)
          const WorldFace &ef = faces[e];
          const glm::dvec3 en = to_glm(world_face_normal(ef)), c = to_glm(ef.origin);
          if (!(glm::dot(p - c, en) > 1e-9)) continue;  // behind the emitter: its back sends nothing
          const glm::dvec3 eu = to_glm(ef.u) * ef.su, ev = to_glm(ef.v) * ef.sv;
          const SphericalRect r = spherical_rect(p, c, eu, ev);
          if (!r.ok) continue;
          // Value k = (1/pi) integral over the emitter of Le V(w) (a_k . w)+ dw, w in front of the
          // face (docs/baking.md). Unoccluded, it is Le times the form factor of the emitter clipped
          // to the front of the face and of a_k (Lambert's formula, exact); the shadow rays estimate
          // only the visible share of it (Heitz, Hill, McGuire, "Combining analytic direct
          // illumination and stochastic shadows", I3D 2018: the ratio of the sampled integrals with
          // and without visibility), so an unoccluded emitter adds no noise at all.
          const std::vector<glm::dvec3> front = clip({c - p, c + eu - p, c + eu + ev - p, c + ev - p}, n);
          double exact[4], with[4] = {0, 0, 0, 0}, without[4] = {0, 0, 0, 0};
          for (int k = 0; k < 4; ++k) exact[k] = polygon_factor(k == 0 ? front : clip(front, ax[k]), ax[k]);
          if (!(exact[0] > 0)) continue;
          LuxelRng rng = LuxelRng::of(0x417265 /* "Are" */, f, static_cast<uint64_t>(j), static_cast<uint64_t>(i), e,
                                      set.seed);
          int seen = 0, sent = 0;
          for (int s = 0; s < m; ++s) {
            double r1, r2;
            stratum(s, side, &rng, &r1, &r2);
            const glm::dvec3 to = spherical_rect_point(r, r1, r2) - p;
            const double len = glm::length(to);
            const glm::dvec3 w = to / len;
            if (!(glm::dot(w, n) > 0)) continue;  // behind the face: it feeds none of the values
            ++traced;
            ++sent;
            // Stopped 1e-4 short of the emitter, which would block its own light.
            const bool vis = !rays.occluded(p, to, 0.0, 1.0 - std::min(0.5, 1e-4 / len));
            seen += vis;
            for (int k = 0; k < 4; ++k) {
              const double cw = std::max(0.0, glm::dot(ax[k], w));
              without[k] += cw;
              if (vis) with[k] += cw;
            }
          }
          if (seen == 0) continue;
          for (int k = 0; k < 4; ++k) {
            // No sample in a_k's lobe: the share of the rays that reached the emitter.
            const double share = without[k] > 0 ? with[k] / without[k] : static_cast<double>(seen) / sent;
            sum[k] += to_glm(ef.emission) * (exact[k] * share);
          }
        }
        for (int k = 0; k < 4; ++k) g.at(i, j, k) = to_ts(to_glm(g.at(i, j, k)) + sum[k]);
      }
      traced_rows[static_cast<size_t>(j)] = traced;
    });
    for (long t : traced_rows) report->rays += t;
  }
  report->ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return true;
}

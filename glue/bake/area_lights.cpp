// tiershade bake: emissive faces and model primitives as area lights (area_lights.h).
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

SphericalTri spherical_tri(const glm::dvec3 &a, const glm::dvec3 &b, const glm::dvec3 &c) {
  // Arvo 1995, section 2: the angle alpha at vertex a between the great circles a-b and a-c, and the
  // triangle's solid angle, here by Van Oosterom and Strackee's formula ("The solid angle of a plane
  // triangle", IEEE Trans. Biomed. Eng. 30(2), 1983: tan(area / 2) = |a . (b x c)| / (1 + a.b + b.c +
  // c.a) for unit vectors), which keeps its precision on small triangles where the angle sum
  // alpha + beta + gamma - pi cancels.
  SphericalTri t;
  t.a = a;
  t.b = b;
  t.c = c;
  const glm::dvec3 nab = glm::cross(a, b), nac = glm::cross(a, c);
  const double lab = glm::length(nab), lac = glm::length(nac);
  if (!(lab > 1e-15 && lac > 1e-15)) return t;  // a vanishing edge: no area
  t.alpha = std::acos(std::clamp(glm::dot(nab, nac) / (lab * lac), -1.0, 1.0));
  t.cos_c = glm::dot(a, b);
  t.area = 2 * std::atan2(std::fabs(glm::dot(a, glm::cross(b, c))), 1 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
  return t;
}

glm::dvec3 spherical_tri_dir(const SphericalTri &t, double u, double v) {
  // Arvo 1995, figure 2: the sub-triangle (a, b, c') of area u x area fixes c' on the arc a-c; then
  // the point on the arc b-c' with 1 - cos of its arc from b uniform, v x (1 - b . c').
  const double ah = u * t.area, s = std::sin(ah - t.alpha), co = std::cos(ah - t.alpha);
  const double ca = std::cos(t.alpha), sa = std::sin(t.alpha);
  const double uu = co - ca, vv = s + sa * t.cos_c;
  const double den = (vv * s + uu * co) * sa;
  const double q = den != 0 ? std::clamp(((vv * co - uu * s) * ca - vv) / den, -1.0, 1.0) : 1.0;
  glm::dvec3 e = t.c - t.a * glm::dot(t.c, t.a);
  const double el = glm::length(e);
  const glm::dvec3 ch = el > 0 ? t.a * q + e * (std::sqrt(std::max(0.0, 1 - q * q)) / el) : t.a;
  const double z = std::clamp(1 - v * (1 - glm::dot(ch, t.b)), -1.0, 1.0);
  glm::dvec3 f = ch - t.b * glm::dot(ch, t.b);
  const double fl = glm::length(f);
  return fl > 0 ? glm::normalize(t.b * z + f * (std::sqrt(std::max(0.0, 1 - z * z)) / fl)) : t.b;
}

ModelEmitter model_emitter(const std::vector<float> &position, const std::vector<float> &normal,
                           const std::vector<uint32_t> &indices, bool mirrored, const ts_vec3d &emission,
                           const std::string &where) {
  ModelEmitter e;
  e.where = where;
  e.emission = emission;
  const size_t nv = position.size() / 3;
  const bool has_normals = normal.size() == position.size();
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    glm::dvec3 v[3], sn(0.0);
    for (int k = 0; k < 3; ++k) {
      const size_t i = indices[t + k] < nv ? indices[t + k] : 0;  // (the ray scene refuses bad indices)
      v[k] = glm::dvec3(position[i * 3], position[i * 3 + 1], position[i * 3 + 2]);
      if (has_normals) sn += glm::dvec3(normal[i * 3], normal[i * 3 + 1], normal[i * 3 + 2]);
    }
    const glm::dvec3 wn = glm::cross(v[1] - v[0], v[2] - v[0]);
    const bool flip = has_normals && glm::dot(sn, sn) > 0 ? glm::dot(wn, sn) < 0 : mirrored;
    if (flip) std::swap(v[1], v[2]);
    for (const glm::dvec3 &q : v)
      for (int k = 0; k < 3; ++k) e.tri.push_back(q[k]);
  }
  return e;
}

bool model_emitter_seen(const ModelEmitter &e, int t, const glm::dvec3 &d, glm::dvec3 *radiance) {
  if (t < 0 || t >= e.triangles()) return false;
  const double *v = &e.tri[static_cast<size_t>(t) * 9];
  const glm::dvec3 a(v[0], v[1], v[2]), b(v[3], v[4], v[5]), c(v[6], v[7], v[8]);
  if (!(glm::dot(glm::cross(b - a, c - a), d) < 0)) return false;  // its back
  *radiance = to_glm(e.emission);
  return true;
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

// An emitting triangle mesh (a TEXCOORD_1 chart or a model primitive): its oriented triangles, its
// emission and the tag of its luxels' streams.
struct MeshLight {
  const double *tri = nullptr;  // 9 per triangle, counter-clockwise seen from the front
  int n = 0;
  glm::dvec3 le{0.0};
  uint64_t stream = 0;
};

// One triangle of a mesh light as a luxel sees it: its spherical triangle, the running sum of the
// pieces' solid angles (the pick's CDF), its first vertex relative to the luxel and its front normal.
struct Piece {
  SphericalTri st;
  double cdf;
  glm::dvec3 a, tn;
};

// Value k of one mesh light at the luxel (p, front n, axes ax[0] = n, ax[1..3] = b_k), as the
// rectangles' (area_lights below): Le times the exact unoccluded factor of the triangles whose front
// faces p, each clipped to the front of the face and of a_k (Lambert's formula), times the visible
// share the shadow rays estimate; the rays' points uniform in the pieces' solid angle (a piece picked
// by its solid angle with r1, then Arvo's map with the rest of r1 and r2).
void mesh_light(const MeshLight &L, const glm::dvec3 &p, const glm::dvec3 ax[4], int side, LuxelRng *rng,
                const RayScene &rays, std::vector<Piece> *pieces, glm::dvec3 sum[4], long *traced) {
  const glm::dvec3 &n = ax[0];
  double exact[4] = {0, 0, 0, 0}, total = 0;
  pieces->clear();
  for (int t = 0; t < L.n; ++t) {
    const double *v = L.tri + static_cast<size_t>(t) * 9;
    const glm::dvec3 a = glm::dvec3(v[0], v[1], v[2]) - p, b = glm::dvec3(v[3], v[4], v[5]) - p,
                     c = glm::dvec3(v[6], v[7], v[8]) - p;
    const glm::dvec3 tn = glm::cross(b - a, c - a);
    if (!(glm::dot(-a, tn) > 1e-12 * glm::length(tn))) continue;  // p behind it or in its plane: nothing
    const std::vector<glm::dvec3> front = clip({a, b, c}, n);
    const double f0 = polygon_factor(front, n);
    if (!(f0 > 0)) continue;  // wholly behind the face
    exact[0] += f0;
    for (int k = 1; k < 4; ++k) exact[k] += polygon_factor(clip(front, ax[k]), ax[k]);
    const SphericalTri st = spherical_tri(glm::normalize(a), glm::normalize(b), glm::normalize(c));
    if (!(st.area > 0)) continue;
    total += st.area;
    pieces->push_back({st, total, a, tn});
  }
  if (!(exact[0] > 0) || pieces->empty()) return;
  const int m = side * side;
  int seen = 0, sent = 0;
  double with[4] = {0, 0, 0, 0}, without[4] = {0, 0, 0, 0};
  for (int s = 0; s < m; ++s) {
    double r1, r2;
    stratum(s, side, rng, &r1, &r2);
    const double x = r1 * total;
    size_t q = 0;
    while (q + 1 < pieces->size() && (*pieces)[q].cdf <= x) ++q;
    const Piece &pc = (*pieces)[q];
    const double lo = pc.cdf - pc.st.area;
    const glm::dvec3 w = spherical_tri_dir(pc.st, std::clamp((x - lo) / pc.st.area, 0.0, 1.0), r2);
    if (!(glm::dot(w, n) > 0)) continue;  // behind the face: it feeds none of the values
    const double dn = glm::dot(w, pc.tn), len = dn < 0 ? glm::dot(pc.a, pc.tn) / dn : 0;
    if (!(len > 0 && std::isfinite(len))) continue;  // (grazing: the direction misses the plane in floating point)
    ++*traced;
    ++sent;
    // Stopped 1e-4 short of the emitter, which would block its own light.
    const bool vis = !rays.occluded(p, w * len, 0.0, 1.0 - std::min(0.5, 1e-4 / len));
    seen += vis;
    for (int k = 0; k < 4; ++k) {
      const double cw = std::max(0.0, glm::dot(ax[k], w));
      without[k] += cw;
      if (vis) with[k] += cw;
    }
  }
  if (seen == 0) return;
  for (int k = 0; k < 4; ++k) {
    const double share = without[k] > 0 ? with[k] / without[k] : static_cast<double>(seen) / sent;
    sum[k] += L.le * (exact[k] * share);
  }
}

}  // namespace

bool area_lights(const std::vector<WorldFace> &faces, const std::vector<std::array<ts_vec3d, 3>> &bump,
                 const std::vector<ModelEmitter> &models, const RayScene &rays, const AreaLightSettings &set,
                 std::vector<LuxelGrid> *grids, AreaLightReport *report, std::string *err) {
  *report = AreaLightReport();
  if (grids->size() != faces.size() || bump.size() != faces.size()) {
    *err = "area lights: " + std::to_string(grids->size()) + " luxel grids for " + std::to_string(faces.size()) +
        " faces";
    return false;
  }
  auto emits = [](const ts_vec3d &le) { return le.x > 0 || le.y > 0 || le.z > 0; };
  std::vector<size_t> emitters;  // planar faces: rectangles
  std::vector<MeshLight> meshes;  // TEXCOORD_1 charts, then the model primitives
  std::vector<std::vector<double>> chart_tris;  // the charts' triangles, oriented
  for (size_t e = 0; e < faces.size(); ++e) {
    if (!emits(faces[e].emission)) continue;
    if (!faces[e].chart) {
      emitters.push_back(e);
      continue;
    }
    // A chart's triangles, each wound to face the side of its corners' normals (the chart's front).
    const WorldChart &c = *faces[e].chart;
    std::vector<double> tri;
    for (int t = 0; t < c.triangles(); ++t) {
      glm::dvec3 v[3], sn(0.0);
      for (int k = 0; k < 3; ++k) {
        const size_t q = static_cast<size_t>(t) * 3 + k;
        v[k] = glm::dvec3(c.pos[q * 3], c.pos[q * 3 + 1], c.pos[q * 3 + 2]);
        sn += glm::dvec3(c.nrm[q * 3], c.nrm[q * 3 + 1], c.nrm[q * 3 + 2]);
      }
      if (glm::dot(glm::cross(v[1] - v[0], v[2] - v[0]), sn) < 0) std::swap(v[1], v[2]);
      for (const glm::dvec3 &q : v)
        for (int k = 0; k < 3; ++k) tri.push_back(q[k]);
    }
    chart_tris.push_back(std::move(tri));
    meshes.push_back({nullptr, c.triangles(), to_glm(faces[e].emission), e});
  }
  for (size_t k = 0, ci = 0; k < meshes.size(); ++k) meshes[k].tri = chart_tris[ci++].data();
  for (size_t k = 0; k < models.size(); ++k)
    if (emits(models[k].emission) && models[k].triangles() > 0)
      meshes.push_back({models[k].tri.data(), models[k].triangles(), to_glm(models[k].emission), faces.size() + k});
  report->emitters = static_cast<int>(emitters.size() + meshes.size());
  report->meshes = static_cast<int>(meshes.size());
  if (report->emitters == 0 || set.samples <= 0) return true;
  const auto t0 = std::chrono::steady_clock::now();
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(set.samples)))));
  const int m = side * side;
  for (size_t f = 0; f < faces.size(); ++f) {
    const WorldFace &face = faces[f];
    LuxelGrid &g = (*grids)[f];
    std::vector<long> traced_rows(static_cast<size_t>(g.h), 0);
    parallel_rows(g.h, set.threads, [&](int j) {
      long traced = 0;
      std::vector<Piece> pieces;
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
        // The meshes (a chart lights its own luxels where it faces itself: a concave mesh).
        for (const MeshLight &L : meshes) {
          LuxelRng rng = LuxelRng::of(0x417265 /* "Are" */, f, static_cast<uint64_t>(j), static_cast<uint64_t>(i),
                                      L.stream, set.seed);
          mesh_light(L, p, ax, side, &rng, rays, &pieces, sum, &traced);
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

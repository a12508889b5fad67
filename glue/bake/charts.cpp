// tiershade bake: lightmap charts from TEXCOORD_1 (glue/bake/charts.h): validation, the luxels'
// triangles (centre coverage, else the nearest point of a grazing triangle), their frames, and the
// dilation of a chart's block, in double with GLM.
#include "bake/charts.h"

#include <algorithm>
#include <cmath>

#include "bake/glm_ts.h"
#include "offline/rnm_bake.h"

namespace {

using glm::dvec2;
using glm::dvec3;

double cross2(const dvec2 &a, const dvec2 &b) { return a.x * b.y - a.y * b.x; }

// Barycentrics of p in triangle (a, b, c) (d = the doubled signed area, nonzero).
glm::dvec3 bary(const dvec2 &p, const dvec2 &a, const dvec2 &b, const dvec2 &c) {
  const double d = cross2(b - a, c - a);
  const double l1 = cross2(p - a, c - a) / d, l2 = cross2(b - a, p - a) / d;
  return dvec3(1 - l1 - l2, l1, l2);
}

dvec2 nearest_on_segment(const dvec2 &p, const dvec2 &a, const dvec2 &b) {
  const dvec2 e = b - a;
  const double t = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
  return a + e * t;
}

// Whether the closed triangle overlaps the open box (x0, x1) x (y0, y1): separating axes (the box's
// and the three edge normals; a shared boundary alone is no overlap).
bool tri_box_overlap(const dvec2 t[3], double x0, double y0, double x1, double y1) {
  const double tx0 = std::min({t[0].x, t[1].x, t[2].x}), tx1 = std::max({t[0].x, t[1].x, t[2].x});
  const double ty0 = std::min({t[0].y, t[1].y, t[2].y}), ty1 = std::max({t[0].y, t[1].y, t[2].y});
  if (tx1 <= x0 || tx0 >= x1 || ty1 <= y0 || ty0 >= y1) return false;
  const dvec2 q[4] = {dvec2(x0, y0), dvec2(x1, y0), dvec2(x1, y1), dvec2(x0, y1)};
  for (int e = 0; e < 3; ++e) {
    const dvec2 a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
    const double side = cross2(b - a, c - a) > 0 ? 1.0 : -1.0;
    bool all_out = true;
    for (const dvec2 &k : q) all_out = all_out && side * cross2(b - a, k - a) <= 0;
    if (all_out) return false;
  }
  return true;
}

dvec3 corner3(const std::vector<double> &v, int tri, int k) {
  const size_t o = (static_cast<size_t>(tri) * 3 + k) * 3;
  return dvec3(v[o], v[o + 1], v[o + 2]);
}
dvec2 corner_uv(const WorldChart &c, int tri, int k) {
  const size_t o = (static_cast<size_t>(tri) * 3 + k) * 2;
  return dvec2(c.uv[o], c.uv[o + 1]);
}

// The fallback tangent of normal n (world_faces.cpp's rule): an axis made orthogonal to n.
dvec3 axis_tangent(const dvec3 &n) {
  return std::fabs(n.x) < 0.9 ? dvec3(1, 0, 0) - n * n.x : dvec3(0, 1, 0) - n * n.y;
}

// The frame at barycentrics l of triangle tri.
bool frame_of(const WorldChart &c, int tri, const dvec3 &l, LuxelFrame *f, std::string *err) {
  dvec3 p(0.0), n(0.0), t(0.0);
  for (int k = 0; k < 3; ++k) {
    p += corner3(c.pos, tri, k) * l[k];
    n += corner3(c.nrm, tri, k) * l[k];
    const size_t o = (static_cast<size_t>(tri) * 3 + k) * 4;
    t += dvec3(c.tan[o], c.tan[o + 1], c.tan[o + 2]) * l[k];
  }
  dvec3 ng = glm::cross(corner3(c.pos, tri, 1) - corner3(c.pos, tri, 0), corner3(c.pos, tri, 2) - corner3(c.pos, tri, 0));
  ng = glm::normalize(ng);
  if (glm::dot(n, n) < 1e-24) n = ng;  // interpolated normals that cancel: the winding's side
  n = glm::normalize(n);
  t = t - n * glm::dot(n, t);
  if (glm::dot(t, t) < 1e-12) t = axis_tangent(n);
  t = glm::normalize(t);
  const double hand = c.tan[static_cast<size_t>(tri) * 12 + 3] < 0 ? -1.0 : 1.0;
  const dvec3 b = glm::cross(n, t) * hand;
  char msg[256];
  if (rnm_bump_basis(to_ts(t), to_ts(b), to_ts(n), to_ts(n), f->bump, msg, sizeof msg) != 0) {
    if (err) *err = c.where + ": triangle " + std::to_string(tri) + ": " + msg;
    return false;
  }
  f->p = to_ts(p);
  f->n = to_ts(n);
  f->lit = true;
  return true;
}

std::string uv_text(const dvec2 &p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

}  // namespace

// Every field a bake reads is hashed below: a new one must be too (and the size here updated).
// (cand_at, cand, luxel_tri and frame follow from what is hashed.)
static_assert(sizeof(WorldChart) == 2 * sizeof(int) + 9 * sizeof(std::vector<double>) + sizeof(std::string),
              "WorldChart changed: hash the new field in chart_hash");

void chart_hash(ContentHash *h, const WorldChart &c) {
  h->value(c.w);
  h->value(c.h);
  h->values(c.pos);
  h->values(c.nrm);
  h->values(c.tan);
  h->values(c.uv);
  h->values(c.vertex_tangent);  // the same as tan's corners; the renderer's
}

int chart_luxels(double units, double per_unit) {
  return std::max(2, static_cast<int>(std::lround(units * per_unit)));
}

bool chart_build(const std::vector<float> &position, const std::vector<float> &normal,
                 const std::vector<float> &tangent, const std::vector<float> &uv1, const std::vector<uint32_t> &indices,
                 double luxels_per_unit, const std::string &where, WorldChart *out, std::string *err) {
  WorldChart c;
  c.where = where;
  const size_t nv = position.size() / 3;
  if (uv1.size() != nv * 2 || indices.size() < 3 || indices.size() % 3 != 0) {
    *err = where + ": TEXCOORD_1 has " + std::to_string(uv1.size() / 2) + " elements for " + std::to_string(nv) +
        " vertices and " + std::to_string(indices.size()) + " indices";
    return false;
  }
  for (size_t v = 0; v < nv; ++v) {
    const double u = uv1[v * 2], w = uv1[v * 2 + 1];
    if (!(u >= 0 && u <= 1 && w >= 0 && w <= 1)) {
      *err = where + ": TEXCOORD_1 of vertex " + std::to_string(v) + " is " + uv_text(dvec2(u, w)) +
          ", outside [0, 1] (a lightmap chart lies in the unit square)";
      return false;
    }
  }
  // Finite geometry only (a NaN or Inf corner would send rays no ray tracer takes).
  const std::vector<float> *arrays[] = {&position, &normal, &tangent};
  const char *names[] = {"POSITION", "NORMAL", "TANGENT"};
  for (int a = 0; a < 3; ++a)
    for (size_t i = 0; i < arrays[a]->size(); ++i)
      if (!std::isfinite((*arrays[a])[i]) || std::fabs((*arrays[a])[i]) > 1e18f) {
        *err = where + ": " + names[a] + " of vertex " + std::to_string(i / (a == 2 ? 4 : 3)) +
            " is not finite or beyond 1e18 (a lightmap chart needs finite geometry)";
        return false;
      }
  // Per-vertex tangents: the mesh's, else the fallback axis (what the renderer is given too).
  c.vertex_tangent.resize(nv * 4);
  for (size_t v = 0; v < nv; ++v) {
    const bool has = tangent.size() == nv * 4;
    const dvec3 n = normal.size() == nv * 3 ? dvec3(normal[v * 3], normal[v * 3 + 1], normal[v * 3 + 2]) : dvec3(0.0);
    dvec3 t = has ? dvec3(tangent[v * 4], tangent[v * 4 + 1], tangent[v * 4 + 2]) : axis_tangent(n);
    if (!has && glm::dot(t, t) > 0) t = glm::normalize(t);
    for (int k = 0; k < 3; ++k) c.vertex_tangent[v * 4 + k] = static_cast<float>(t[k]);
    c.vertex_tangent[v * 4 + 3] = has && tangent[v * 4 + 3] < 0 ? -1.f : 1.f;
  }
  double area_w = 0, area_uv = 0;
  const int nt = static_cast<int>(indices.size() / 3);
  for (int t = 0; t < nt; ++t) {
    dvec3 p[3];
    dvec2 q[3];
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = indices[static_cast<size_t>(t) * 3 + k];
      p[k] = dvec3(position[v * 3], position[v * 3 + 1], position[v * 3 + 2]);
      q[k] = dvec2(uv1[v * 2], uv1[v * 2 + 1]);
      for (int e = 0; e < 3; ++e) c.pos.push_back(p[k][e]);
      for (int e = 0; e < 3; ++e) c.nrm.push_back(normal.size() == nv * 3 ? normal[v * 3 + e] : 0.0);
      for (int e = 0; e < 4; ++e) c.tan.push_back(c.vertex_tangent[v * 4 + e]);
      c.uv.push_back(q[k].x);
      c.uv.push_back(q[k].y);
    }
    const double aw = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    const double auv = 0.5 * std::fabs(cross2(q[1] - q[0], q[2] - q[0]));
    // Thresholds: 1e-12 square units (a micrometre square at metre scale) and 1e-12 of the UV square
    // (below a millionth of a luxel of a 1024-luxel chart): nothing a lightmap can resolve.
    if (!(aw > 1e-12) || !(auv > 1e-12)) {
      *err = where + ": triangle " + std::to_string(t) + " (vertices " +
          std::to_string(indices[static_cast<size_t>(t) * 3]) + ", " +
          std::to_string(indices[static_cast<size_t>(t) * 3 + 1]) + ", " +
          std::to_string(indices[static_cast<size_t>(t) * 3 + 2]) + ") is degenerate " +
          (aw > 1e-12 ? "in TEXCOORD_1 (zero UV area)" : "(zero area)");
      return false;
    }
    area_w += aw;
    area_uv += auv;
  }
  c.w = c.h = chart_luxels(std::sqrt(area_w / area_uv), luxels_per_unit);
  if (c.w > 1024) {
    *err = where + ": the TEXCOORD_1 chart needs " + std::to_string(c.w) + " x " + std::to_string(c.h) +
        " luxels at " + std::to_string(luxels_per_unit) + " luxels per unit (at most 1024 x 1024)";
    return false;
  }
  // Overlaps: each test point strictly inside (barycentrics > 1e-9) two triangles is an error.
  const int sub = static_cast<long>(c.w) * c.h > 65536 ? 2 : 4;
  const int sw = c.w * sub, sh = c.h * sub;
  std::vector<int> owner(static_cast<size_t>(sw) * sh, -1);
  c.luxel_tri.assign(static_cast<size_t>(c.w) * c.h, -1);
  std::vector<double> dist(c.luxel_tri.size(), INFINITY);  // 0: the centre is inside
  std::vector<dvec3> best(c.luxel_tri.size());
  std::vector<std::vector<int>> touch(c.luxel_tri.size());
  for (int t = 0; t < nt; ++t) {
    const dvec2 q[3] = {corner_uv(c, t, 0), corner_uv(c, t, 1), corner_uv(c, t, 2)};
    const double u0 = std::min({q[0].x, q[1].x, q[2].x}), u1 = std::max({q[0].x, q[1].x, q[2].x});
    const double v0 = std::min({q[0].y, q[1].y, q[2].y}), v1 = std::max({q[0].y, q[1].y, q[2].y});
    const int sx0 = std::max(0, static_cast<int>(u0 * sw) - 1), sx1 = std::min(sw - 1, static_cast<int>(u1 * sw) + 1);
    const int sy0 = std::max(0, static_cast<int>(v0 * sh) - 1), sy1 = std::min(sh - 1, static_cast<int>(v1 * sh) + 1);
    for (int y = sy0; y <= sy1; ++y)
      for (int x = sx0; x <= sx1; ++x) {
        const dvec2 s((x + 0.5) / sw, (y + 0.5) / sh);
        const dvec3 l = bary(s, q[0], q[1], q[2]);
        if (!(l.x > 1e-9 && l.y > 1e-9 && l.z > 1e-9)) continue;
        int &o = owner[static_cast<size_t>(y) * sw + x];
        if (o >= 0) {
          *err = where + ": TEXCOORD_1 triangles " + std::to_string(o) + " and " + std::to_string(t) +
              " overlap at " + uv_text(s) + " (each luxel needs one place on the surface)";
          return false;
        }
        o = t;
      }
    // The luxels it touches: its centre inside wins, else the nearest point of a grazing triangle.
    for (int j = std::max(0, sy0 / sub); j <= std::min(c.h - 1, sy1 / sub); ++j)
      for (int i = std::max(0, sx0 / sub); i <= std::min(c.w - 1, sx1 / sub); ++i) {
        const double x0 = static_cast<double>(i) / c.w, x1 = static_cast<double>(i + 1) / c.w;
        const double y0 = static_cast<double>(j) / c.h, y1 = static_cast<double>(j + 1) / c.h;
        if (!tri_box_overlap(q, x0, y0, x1, y1)) continue;
        touch[static_cast<size_t>(j) * c.w + i].push_back(t);
        const dvec2 centre((i + 0.5) / c.w, (j + 0.5) / c.h);
        dvec3 l = bary(centre, q[0], q[1], q[2]);
        double d = 0;
        if (!(l.x >= 0 && l.y >= 0 && l.z >= 0)) {
          dvec2 near = nearest_on_segment(centre, q[0], q[1]);
          for (int e = 1; e < 3; ++e) {
            const dvec2 m = nearest_on_segment(centre, q[e], q[(e + 1) % 3]);
            if (glm::length(m - centre) < glm::length(near - centre)) near = m;
          }
          d = glm::length(near - centre);
          l = glm::clamp(bary(near, q[0], q[1], q[2]), 0.0, 1.0);
          l /= l.x + l.y + l.z;
        }
        const size_t li = static_cast<size_t>(j) * c.w + i;
        if (d < dist[li]) {
          dist[li] = d;
          best[li] = l;
          c.luxel_tri[li] = t;
        }
      }
  }
  c.cand_at.push_back(0);
  for (const std::vector<int> &t : touch) {
    c.cand.insert(c.cand.end(), t.begin(), t.end());
    c.cand_at.push_back(static_cast<int>(c.cand.size()));
  }
  c.frame.assign(c.luxel_tri.size(), LuxelFrame());
  for (size_t li = 0; li < c.frame.size(); ++li)
    if (c.luxel_tri[li] >= 0 && !frame_of(c, c.luxel_tri[li], best[li], &c.frame[li], err)) return false;
  *out = std::move(c);
  return true;
}

bool chart_frame_at(const WorldChart &c, double u, double v, LuxelFrame *f) {
  const dvec2 s(u, v);
  const int i = std::clamp(static_cast<int>(u * c.w), 0, c.w - 1), j = std::clamp(static_cast<int>(v * c.h), 0, c.h - 1);
  const size_t li = static_cast<size_t>(j) * c.w + i;
  for (int k = c.cand_at[li]; k < c.cand_at[li + 1]; ++k) {
    const int t = c.cand[static_cast<size_t>(k)];
    const dvec3 l = bary(s, corner_uv(c, t, 0), corner_uv(c, t, 1), corner_uv(c, t, 2));
    if (l.x >= 0 && l.y >= 0 && l.z >= 0) return frame_of(c, t, l, f, nullptr);
  }
  return false;
}

void chart_hit_ab(const WorldChart &c, int tri, double bu, double bv, double *a, double *b) {
  tri = std::clamp(tri, 0, c.triangles() - 1);
  const dvec2 q = corner_uv(c, tri, 0) * (1 - bu - bv) + corner_uv(c, tri, 1) * bu + corner_uv(c, tri, 2) * bv;
  const int i = std::clamp(static_cast<int>(q.x * c.w), 0, c.w - 1), j = std::clamp(static_cast<int>(q.y * c.h), 0, c.h - 1);
  *a = static_cast<double>(i) / (c.w - 1);
  *b = static_cast<double>(j) / (c.h - 1);
}

void chart_dilate(float *rgba, int page_w, int x0, int y0, int w, int h, const std::vector<int> &lit, int rings,
                  std::vector<int> *lit_out) {
  const int W = w + 2, H = h + 2;  // the block with its border; mask index (y + 1) * W + x + 1
  std::vector<int> m(static_cast<size_t>(W) * H, 0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) m[static_cast<size_t>(j + 1) * W + i + 1] = lit[static_cast<size_t>(j) * w + i] ? 1 : 0;
  auto px = [&](int x, int y) { return &rgba[(static_cast<size_t>(y0 + y) * page_w + x0 + x) * 4]; };
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next = m;
    for (int y = -1; y <= h; ++y)
      for (int x = -1; x <= w; ++x) {
        if (m[static_cast<size_t>(y + 1) * W + x + 1]) continue;
        double sum[3] = {0, 0, 0};
        int count = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < -1 || ny < -1 || nx > w || ny > h || !m[static_cast<size_t>(ny + 1) * W + nx + 1]) continue;
            const float *q = px(nx, ny);
            for (int k = 0; k < 3; ++k) sum[k] += q[k];
            ++count;
          }
        if (count == 0) continue;
        float *o = px(x, y);
        for (int k = 0; k < 3; ++k) o[k] = static_cast<float>(sum[k] / count);
        next[static_cast<size_t>(y + 1) * W + x + 1] = 1;
      }
    m.swap(next);
  }
  if (lit_out) *lit_out = m;
}

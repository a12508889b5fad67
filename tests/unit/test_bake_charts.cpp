// tiershade tests: TEXCOORD_1 lightmap charts (glue/bake/charts.h, issue "Geometry and lightmap pages"):
//   - bad geometry is refused with a message naming the primitive (and the triangle or vertex):
//     TEXCOORD_1 outside [0, 1], a triangle of zero area, of zero UV area, two triangles
//     overlapping in UV, a chart the page cannot hold;
//   - dilation: on a baked curved chart (a dome, lit everywhere), every texel bilinear filtering
//     reads at points inside the triangles holds light; the same page with the dilated texels
//     cleared fails that check (the check can fail); a ring takes the mean of its lit neighbours;
//   - the content hash changes when TEXCOORD_1 does (a stale bake is refused);
//   - several pages: faces that overflow a page go on the next (stacked rows, uv within the page),
//     a face larger than a page and a full last page are refused; a bake on two small pages holds
//     every luxel value of the bake on one large page, bit for bit.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bake/bake_dir.h"
#include "bake/charts.h"
#include "bake/world_bake.h"
#include "unit_check.h"

using unit_check::check;

namespace {

struct Mesh {
  std::vector<float> pos, nrm, uv1;
  std::vector<uint32_t> idx;
};

// A unit square at y = 0 facing +y, two triangles, TEXCOORD_1 = (x, z) scaled by `s`.
Mesh square(float s = 1.f) {
  Mesh m;
  m.pos = {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1};
  m.nrm = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
  m.uv1 = {0, 0, s, 0, s, s, 0, s};
  m.idx = {0, 2, 1, 0, 3, 2};
  return m;
}

// A dome over a disc of radius 1 (rings x seg, a fan at the top), TEXCOORD_1 its plan in [0.05, 0.95]^2.
Mesh dome(int rings, int seg) {
  Mesh m;
  for (int j = 0; j <= rings; ++j) {
    const double r = static_cast<double>(j) / rings, q = 1 - r * r;
    for (int i = 0; i < (j ? seg : 1); ++i) {
      const double ph = 2 * M_PI * i / seg, x = r * std::cos(ph), z = r * std::sin(ph);
      const double dq = -4 * 0.6 * q;
      const double n[3] = {-dq * x, 1.0, -dq * z}, len = std::sqrt(n[0] * n[0] + 1 + n[2] * n[2]);
      m.pos.insert(m.pos.end(), {static_cast<float>(x), static_cast<float>(0.6 * q * q), static_cast<float>(z)});
      m.nrm.insert(m.nrm.end(), {static_cast<float>(n[0] / len), static_cast<float>(1 / len),
                                 static_cast<float>(n[2] / len)});
      m.uv1.insert(m.uv1.end(), {static_cast<float>(0.5 + 0.45 * x), static_cast<float>(0.5 + 0.45 * z)});
    }
  }
  for (int i = 0; i < seg; ++i) m.idx.insert(m.idx.end(), {0u, static_cast<uint32_t>(1 + i), static_cast<uint32_t>(1 + (i + 1) % seg)});
  for (int j = 1; j < rings; ++j) {
    const uint32_t a = 1 + (j - 1) * seg, b = 1 + j * seg;
    for (int i = 0; i < seg; ++i) {
      const uint32_t i1 = (i + 1) % seg;
      m.idx.insert(m.idx.end(), {a + i, b + i, b + i1, a + i, b + i1, a + i1});
    }
  }
  return m;
}

bool build(const Mesh &m, double per_unit, WorldFace *f, std::string *err) {
  return world_face_from_chart(m.pos, m.nrm, {}, m.uv1, m.idx, "chart", -1, per_unit, "meshes[7].primitives[0]", f,
                               err);
}

void refused(const Mesh &m, const char *what, const std::string &expect, double per_unit = 8) {
  WorldFace f{};
  std::string err;
  const bool ok = build(m, per_unit, &f, &err);
  check(!ok && err.find("meshes[7].primitives[0]") != std::string::npos && err.find(expect) != std::string::npos,
        std::string("refused, naming the primitive: ") + what, ok ? "accepted" : err);
}

void bad_geometry() {
  Mesh m = square();
  m.uv1[4] = 1.25f;
  refused(m, "TEXCOORD_1 outside [0, 1]", "TEXCOORD_1 of vertex 2 is (1.250000, 1.000000), outside [0, 1]");
  m = square();
  m.uv1[1] = NAN;
  refused(m, "TEXCOORD_1 NaN", "TEXCOORD_1 of vertex 0");
  m = square();
  m.pos[6] = 0, m.pos[8] = 0;  // vertex 2 onto vertex 0: both triangles collapse
  refused(m, "a triangle of zero area", "triangle 0 (vertices 0, 2, 1) is degenerate (zero area)");
  m = square();
  m.uv1[4] = 0, m.uv1[5] = 0;  // vertex 2's UV onto vertex 0's
  refused(m, "a triangle of zero UV area", "triangle 0 (vertices 0, 2, 1) is degenerate in TEXCOORD_1");
  m = square();
  m.uv1[6] = 1.f, m.uv1[7] = 0.5f;  // vertex 3 onto the first triangle's UVs
  refused(m, "overlapping TEXCOORD_1 triangles", "TEXCOORD_1 triangles 0 and 1 overlap");
  refused(square(), "more than 1024 luxels a side", "needs 2000 x 2000 luxels", 2000);
  // A chart the page cannot hold: 32 x 32 luxels (4 lightmaps) on a 64 x 64 page.
  WorldBakeInput in;
  WorldFace f{};
  std::string err;
  Mesh big = square();
  for (float &p : big.pos) p *= 4;
  if (!build(big, 8, &f, &err)) return check(false, "build the 4 x 4 chart", err);
  in.faces = {f};
  in.probes = {ts_v3d(0, 1, 0)};
  in.page_w = in.page_h = 64;
  in.cube_size = 4;
  WorldBake out;
  const bool ok = bake_world(in, &out, &err);
  check(!ok && err.find("chart (meshes[7].primitives[0]): ") == 0 && err.find("does not fit in the 64x64 page") != std::string::npos,
        "a chart the page cannot hold is refused, naming the primitive", ok ? "baked" : err);
}

// Whether every texel bilinear filtering reads at points inside the chart's triangles (a 12 x 12
// barycentric grid each) has a flat value > 0; `reads` counts the texels read.
bool reads_lit(const WorldBakeInput &in, const WorldBake &b, const WorldChart &c, long *reads, std::string *why) {
  *reads = 0;
  const int n = 12;
  for (int t = 0; t < c.triangles(); ++t)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double l1 = static_cast<double>(i) / n, l2 = static_cast<double>(j) / n, l0 = 1 - l1 - l2;
        const size_t o = static_cast<size_t>(t) * 6;
        const double u = l0 * c.uv[o] + l1 * c.uv[o + 2] + l2 * c.uv[o + 4];
        const double v = l0 * c.uv[o + 1] + l1 * c.uv[o + 3] + l2 * c.uv[o + 5];
        float uv[2];
        lm_page_chart_uv(&b.place[0], in.page_w, in.page_h, u, v, uv);
        // GL's LINEAR: the texels floor(x - 0.5) and the next, x = uv * size.
        const int x0 = static_cast<int>(std::floor(uv[0] * in.page_w - 0.5)),
                  y0 = static_cast<int>(std::floor(uv[1] * in.page_h - 0.5));
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            ++*reads;
            const float *px = &b.page[(static_cast<size_t>(y0 + dy) * in.page_w + x0 + dx) * 4];
            if (!(px[0] > 0)) {
              *why = "texel (" + std::to_string(x0 + dx) + ", " + std::to_string(y0 + dy) + ") read at uv (" +
                  std::to_string(u) + ", " + std::to_string(v) + ") of triangle " + std::to_string(t) + " is unlit";
              return false;
            }
          }
      }
  return true;
}

void dilation() {
  const Mesh m = dome(6, 20);
  WorldFace f{};
  std::string err;
  if (!build(m, 12, &f, &err)) return check(false, "build the dome chart", err);
  WorldBakeInput in;
  in.faces = {f};
  rnm_light l{};
  l.pos = ts_v3d(0.2, 5, 0.1);
  l.color = ts_v3d(20, 20, 20);
  l.atten[2] = 1;
  in.lights = {l};
  in.probes = {ts_v3d(0, 2, 0)};
  in.luxels_per_unit = 12;
  in.page_w = 256;
  in.page_h = 64;
  in.cube_size = 4;
  WorldBake b;
  if (!bake_world(in, &b, &err)) return check(false, "bake the dome", err);
  const WorldChart &c = *f.chart;
  long unlit = 0;
  for (int li : c.luxel_tri) unlit += li < 0;
  long reads = 0;
  std::string why;
  check(reads_lit(in, b, c, &reads, &why) && reads > 1000 && unlit > 0,
        "dilation: every texel bilinear filtering reads inside the dome's triangles holds light",
        why + " (" + std::to_string(reads) + " reads, " + std::to_string(unlit) + " unlit luxels)");
  // The check can fail: the dilated texels (unlit luxels and the border) cleared.
  WorldBake cleared = b;
  const lm_face_place &p = b.place[0];
  for (int y = -1; y <= c.h; ++y)
    for (int x = -1; x <= c.w; ++x) {
      const bool lit = x >= 0 && y >= 0 && x < c.w && y < c.h && c.luxel_tri[static_cast<size_t>(y) * c.w + x] >= 0;
      if (!lit) cleared.page[(static_cast<size_t>(p.y + 1 + y) * in.page_w + p.x + 1 + x) * 4] = 0;
    }
  check(!reads_lit(in, cleared, c, &reads, &why), "without the dilated texels the same check fails",
        "every read lit");
  // A ring: each unlit texel with lit 8-neighbours takes their mean.
  std::vector<float> page(6 * 6 * 4, 0.f);
  auto at = [&](int x, int y) { return &page[(static_cast<size_t>(y) * 6 + x) * 4]; };
  at(2, 2)[0] = 4, at(3, 2)[0] = 8;  // luxels (1, 1) and (2, 1) of a 4 x 4 block at (1, 1)
  std::vector<int> lit(16, 0), mask;
  lit[1 * 4 + 1] = lit[1 * 4 + 2] = 1;
  chart_dilate(page.data(), 6, 1, 1, 4, 4, lit, 1, &mask);
  check(at(1, 1)[0] == 4 && at(2, 1)[0] == 6 && at(4, 3)[0] == 8 && at(5, 5)[0] == 0 && mask[3 * 6 + 3] == 1 &&
            mask[5 * 6 + 5] == 0,
        "a dilation ring: the mean of the lit neighbours, the next ring untouched",
        std::to_string(at(1, 1)[0]) + " " + std::to_string(at(2, 1)[0]) + " " + std::to_string(at(4, 3)[0]));
}

void content_hash() {
  WorldFace a{}, b{};
  std::string err;
  Mesh m = square();
  if (!build(m, 8, &a, &err)) return check(false, "build", err);
  m.uv1[4] = 0.9f;  // another chart of the same positions
  if (!build(m, 8, &b, &err)) return check(false, "build", err);
  WorldBakeInput in;
  in.faces = {a};
  const uint64_t ha = bake_input_hash(in).geometry;
  in.faces = {b};
  check(bake_input_hash(in).geometry != ha, "the bake's hash changes with TEXCOORD_1 (a stale bake is refused)");
}

void pages() {
  // Three faces of 6 x 6 luxels (8 x 8 blocks, one lightmap) on 20 x 10 pages: two per page.
  lm_face_size f[3] = {{6, 6, 0}, {6, 6, 0}, {6, 6, 0}};
  lm_face_place p[3];
  int n = 0;
  char msg[256];
  const int rc = lm_page_pack_pages(20, 10, 4, f, 3, p, &n, msg, sizeof msg);
  float uv[2];
  if (rc == 0) lm_page_chart_uv(&p[2], 20, 10, 0.0, 0.0, uv);
  check(rc == 0 && n == 2 && p[0].page == 0 && p[1].page == 0 && p[1].x == 8 && p[2].page == 1 && p[2].x == 0 &&
            p[2].y == 10 && uv[0] == 1.f / 20 && uv[1] == 1.f / 10,
        "pages: the third face on page 1 (rows 10.., its uv within its page)", rc ? msg : std::to_string(n));
  check(lm_page_pack_pages(20, 10, 1, f, 3, p, &n, msg, sizeof msg) != 0 &&
            std::string(msg).find("face 2 (6x6 luxels, 1 lightmaps) does not fit in the 20x10 page") != std::string::npos,
        "pages: one page full refuses the face that does not fit", msg);
  lm_face_size big = {20, 6, 0};
  check(lm_page_pack_pages(20, 10, 4, &big, 1, p, &n, msg, sizeof msg) != 0 &&
            std::string(msg).find("face 0 (20x6 luxels, 1 lightmaps) does not fit in the 20x10 page") != std::string::npos,
        "pages: a face wider than a page is refused", msg);
  // A bake on 2 pages = the bake on one page, luxel for luxel (the dome chart and a planar face).
  const Mesh m = dome(6, 20);
  WorldFace chart{};
  std::string err;
  if (!build(m, 12, &chart, &err)) return check(false, "build the dome chart", err);
  WorldFace quad{"quad", ts_v3d(-1, 0, 1), ts_v3d(1, 0, 0), ts_v3d(0, 0, -1), 2, 2, -1, ts_v3d(0, 1, 0)};
  WorldBakeInput in;
  in.faces = {chart, quad};
  rnm_light l{};
  l.pos = ts_v3d(0.2, 3, 0.1);
  l.color = ts_v3d(20, 20, 20);
  l.atten[2] = 1;
  in.lights = {l};
  in.probes = {ts_v3d(0, 2, 0)};
  in.luxels_per_unit = 12;
  in.cube_size = 4;
  in.page_w = 256;
  in.page_h = 128;
  WorldBake one, two;
  if (!bake_world(in, &one, &err)) return check(false, "bake on one page", err);
  in.page_w = 128;
  in.page_h = 32;
  if (!bake_world(in, &two, &err)) return check(false, "bake on two pages", err);
  long differ = 0, texels = 0;
  for (size_t fi = 0; fi < 2; ++fi) {
    const lm_face_place &a = one.place[fi], &b = two.place[fi];
    for (int k = 0; k < a.count; ++k)
      for (int y = 0; y < a.block_h; ++y)
        for (int x = 0; x < a.block_w; ++x) {
          const float *ta = &one.page[(static_cast<size_t>(a.y + y) * 256 + a.x + k * a.block_w + x) * 4];
          const float *tb = &two.page[(static_cast<size_t>(b.y + y) * 128 + b.x + k * b.block_w + x) * 4];
          ++texels;
          differ += ta[0] != tb[0] || ta[1] != tb[1] || ta[2] != tb[2];
        }
  }
  check(one.pages == 1 && two.pages == 2 && two.place[1].page == 1 && differ == 0 && texels > 1000,
        "pages: the bake on two 128 x 32 pages holds the one-page bake's texels bit for bit",
        std::to_string(two.pages) + " pages, " + std::to_string(differ) + " of " + std::to_string(texels) + " differ");
}

}  // namespace

int main() {
  ts_math_init();
  for (void (*test)() : {bad_geometry, dilation, content_hash, pages}) test();
  return unit_check::finish();
}

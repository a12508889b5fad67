// tiershade tests: the baker's visibility (glue/bake/ray_scene.h, Embree) against closed forms, on a
// 4 x 4 floor under a 1 x 1 occluder (issue "the light baker", tests with known answers):
//   - a point light above the floor: every luxel whose samples all lie outside the occluder's
//     shadow (its projection from the light, where geometry puts it) holds the mean over its
//     samples of I cos(theta) / d^2 to 1e-6 relative; every luxel whose samples all lie inside
//     holds 0; the luxels across the boundary lie in between;
//   - a sun straight down: the shadow is the occluder's footprint; with an angular spread a, the
//     umbra and the full light end where the sun's cone does (a penumbra 2 h tan a wide), the
//     penumbra's luxels take the share of the cone the occluder leaves; spread 0: the same bytes;
//   - basis values: a light on the face normal gives each bumped value the flat value times the
//     basis vector's z (1/sqrt(3)); a light behind the face gives zero everywhere;
//   - the ray scene itself: hits and misses, the nearest hit's t and mesh id, a bad index refused;
//   - the same floor as a TEXCOORD_1 chart (glue/bake/charts.h: 32 triangles, luxels at their
//     centres): the point light's I cos(theta) / d^2 and shadow as on the planar floor.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bake/ray_scene.h"
#include "bake/world_bake.h"
#include "unit_check.h"

namespace {

const double kOcc = 0.5;  // the occluder: |x|, |z| <= 0.5 at height kOccY
const double kOccY = 2.0;

void add_quad(RayScene *r, double y, double half, int id, const char *what) {
  const float h = static_cast<float>(half), fy = static_cast<float>(y);
  const std::vector<float> p = {-h, fy, -h, h, fy, -h, h, fy, h, -h, fy, h};
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
  std::string err;
  if (!r->add_mesh(p, idx, id, what, &err)) check(false, std::string("add ") + what, err);
}

struct Floor {
  WorldBakeInput in;
  WorldBake out;
  int w = 0, h = 0;  // luxels
  bool ok = false;
  void (*sample)(int i, int j, int si, int sj, double *x, double *z) = nullptr;  // null: sample_xz
};

// The floor x, z in [-2, 2] at y = 0, facing +y, 8 luxels per unit (33 x 33), lit by `lights`.
void bake_floor(const std::vector<rnm_light> &lights, const RayScene *rays, Floor *f,
                const std::vector<double> &spread = {}) {
  f->in.faces = {{"floor", ts_v3d(-2, 0, 2), ts_v3d(1, 0, 0), ts_v3d(0, 0, -1), 4, 4, -1, ts_v3d(0, 1, 0)}};
  f->in.lights = lights;
  f->in.probes = {ts_v3d(0, 1, 0)};
  f->in.luxels_per_unit = 8;
  f->in.page_w = 256;
  f->in.page_h = 64;
  f->in.cube_size = 4;
  f->in.rays = rays;
  f->in.light_spread = spread;
  std::string err;
  f->ok = bake_world(f->in, &f->out, &err);
  if (!f->ok) check(false, "bake the floor", err);
  f->w = f->h = 33;
}

ts_vec3d value(const Floor &f, int k, int i, int j) {
  int tx, ty;
  lm_page_texel(&f.out.place[0], k, i, j, &tx, &ty);
  const float *t = &f.out.page[(static_cast<size_t>(ty) * f.in.page_w + tx) * 4];
  return ts_v3d(t[0], t[1], t[2]);
}

// The world position of sample (si, sj) of luxel (i, j) (2 x 2 samples, as bake_world places them:
// clipped to the face inset by kWorldSampleInset).
void sample_xz(int i, int j, int si, int sj, double *x, double *z) {
  const double inset = kWorldSampleInset / 4;  // the floor is 4 units wide
  const double a = std::min(1.0 - inset, std::max(inset, (i + (si + 0.5) / 2 - 0.5) / 32));
  const double b = std::min(1.0 - inset, std::max(inset, (j + (sj + 0.5) / 2 - 0.5) / 32));
  *x = -2 + 4 * a;
  *z = 2 - 4 * b;
}

rnm_light point_light(double x, double y, double z, double I) {
  rnm_light l{};
  l.pos = ts_v3d(x, y, z);
  l.color = ts_v3d(I, I, I);
  l.atten[2] = 1;  // 1 / d^2
  return l;
}

rnm_light sun(double dy, double I) {
  rnm_light l{};
  l.directional = 1;
  l.dir = ts_v3d(0, dy, 0);
  l.color = ts_v3d(I, I, I);
  return l;
}

// Shadow test: `half` is the shadow's half-width on the floor; a sample is inside when both |x|, |z|
// are below it by more than `margin`, outside when either is above it by more than `margin`.
void check_shadow(const Floor &f, double half, const char *label, double (*lit)(double x, double z)) {
  const double margin = 1e-6;
  long outside = 0, inside = 0, across = 0, bad_out = 0, bad_in = 0, bad_across = 0;
  double worst = 0;
  for (int j = 0; j < f.h; ++j)
    for (int i = 0; i < f.w; ++i) {
      int n_in = 0, n_out = 0;
      double expect = 0;
      for (int sj = 0; sj < 2; ++sj)
        for (int si = 0; si < 2; ++si) {
          double x, z;
          (f.sample ? f.sample : sample_xz)(i, j, si, sj, &x, &z);
          const double m = std::max(std::fabs(x), std::fabs(z)) - half;
          if (m < -margin) ++n_in;
          if (m > margin) {
            ++n_out;
            expect += lit(x, z) / 4;
          }
        }
      const double v = value(f, 0, i, j).x;
      if (n_out == 4) {
        ++outside;
        const double rel = std::fabs(v - expect) / expect;
        worst = std::max(worst, rel);
        bad_out += rel > 1e-6;
      } else if (n_in == 4) {
        ++inside;
        bad_in += v != 0;
      } else if (n_in + n_out == 4) {
        ++across;
        bad_across += std::fabs(v - expect) > 1e-6 * expect;  // expect > 0: some sample is out
      }
    }
  check(outside > 100 && bad_out == 0,
        std::string(label) + ": lit luxels = mean of I cos(theta) / d^2 over their samples to 1e-6",
        std::to_string(bad_out) + " of " + std::to_string(outside) + " off; worst relative " + std::to_string(worst));
  check(inside > 4 && bad_in == 0, std::string(label) + ": luxels inside the shadow are 0",
        std::to_string(bad_in) + " of " + std::to_string(inside) + " lit");
  check(bad_across == 0, std::string(label) + ": luxels across the boundary = their unshadowed samples' share, to 1e-6",
        std::to_string(bad_across) + " of " + std::to_string(across) + " off");
}

double point_lit(double x, double z) {
  const double dx = -x, dy = 4.0, dz = -z, d2 = dx * dx + dy * dy + dz * dz;
  return 10.0 * (dy / std::sqrt(d2)) / d2;  // I cos(theta) / d^2, I = 10
}
double sun_lit(double, double) { return 3.0; }

// The floor as a TEXCOORD_1 chart: a 4 x 4 grid of quads (32 triangles) over x, z in [-2, 2], u =
// (x + 2) / 4, v = (2 - z) / 4: a 4-unit square at 8 luxels per unit, 32 x 32 luxels, luxel i
// spanning u in [i, i + 1) / 32, its 2 x 2 samples at (i + (si + 0.5) / 2) / 32.
void chart_sample_xz(int i, int j, int si, int sj, double *x, double *z) {
  *x = -2 + 4 * (i + (si + 0.5) / 2) / 32;
  *z = 2 - 4 * (j + (sj + 0.5) / 2) / 32;
}

void chart_shadows() {
  std::vector<float> pos, nrm, uv1;
  std::vector<uint32_t> idx;
  for (int r = 0; r <= 4; ++r)
    for (int c = 0; c <= 4; ++c) {
      const float x = -2.f + c, z = 2.f - r;
      pos.insert(pos.end(), {x, 0.f, z});
      nrm.insert(nrm.end(), {0.f, 1.f, 0.f});
      uv1.insert(uv1.end(), {c / 4.f, r / 4.f});
    }
  for (uint32_t r = 0; r < 4; ++r)
    for (uint32_t c = 0; c < 4; ++c) {
      const uint32_t a = r * 5 + c;
      idx.insert(idx.end(), {a, a + 1, a + 6, a, a + 6, a + 5});
    }
  RayScene rays;
  std::string err;
  if (!rays.add_mesh(pos, idx, 0, "chart floor", &err)) return check(false, "add the chart floor", err);
  add_quad(&rays, kOccY, kOcc, 1, "occluder");
  if (!rays.commit(&err)) return check(false, "commit", err);
  Floor cf;
  WorldFace face{};
  if (!world_face_from_chart(pos, nrm, {}, uv1, idx, "chart floor", -1, 8, "chart floor", &face, &err))
    return check(false, "chart the floor", err);
  check(face.chart->w == 32 && face.chart->h == 32, "the chart floor has 32 x 32 luxels (4 units at 8 per unit)",
        std::to_string(face.chart->w) + " x " + std::to_string(face.chart->h));
  cf.in.faces = {face};
  cf.in.lights = {point_light(0, 4, 0, 10)};
  cf.in.probes = {ts_v3d(0, 1, 0)};
  cf.in.luxels_per_unit = 8;
  cf.in.page_w = 256;
  cf.in.page_h = 64;
  cf.in.cube_size = 4;
  cf.in.rays = &rays;
  cf.ok = bake_world(cf.in, &cf.out, &err);
  if (!cf.ok) return check(false, "bake the chart floor", err);
  cf.w = cf.h = 32;
  cf.sample = chart_sample_xz;
  check_shadow(cf, kOcc * 4.0 / (4.0 - kOccY), "TEXCOORD_1 chart, point light at height 4", point_lit);
}

void shadows() {
  RayScene rays;
  add_quad(&rays, 0.0, 2.0, 0, "floor");
  add_quad(&rays, kOccY, kOcc, 1, "occluder");
  std::string err;
  if (!rays.commit(&err)) return check(false, "commit", err);
  Floor pf;
  bake_floor({point_light(0, 4, 0, 10)}, &rays, &pf);
  if (pf.ok) check_shadow(pf, kOcc * 4.0 / (4.0 - kOccY), "point light at height 4", point_lit);
  Floor sf;
  bake_floor({sun(-1, 3)}, &rays, &sf);
  if (sf.ok) check_shadow(sf, kOcc, "sun straight down", sun_lit);
  // Without a ray scene the bake traces its faces alone: the occluder, not a face, casts nothing.
  Floor nf;
  bake_floor({sun(-1, 3)}, nullptr, &nf);
  if (nf.ok) check(value(nf, 0, 16, 16).x == 3.f, "no ray scene given: the faces alone occlude (the occluder is no face: no shadow)", std::to_string(value(nf, 0, 16, 16).x));
  // The same bake twice gives the same bytes.
  Floor again;
  bake_floor({point_light(0, 4, 0, 10)}, &rays, &again);
  check(again.ok && again.out.page == pf.out.page, "the bake is deterministic");
}

// A sun straight down of angular radius a (WorldBakeInput::light_spread, vrad's _sunspreadangle)
// over the occluder at height h = 2: from a floor point the sun's cone meets the occluder's plane in
// a disc of radius R = h tan a, so the umbra ends R inside the occluder's footprint's edge and the
// full light starts R outside it: a penumbra 2 h tan a wide. The share of the cone (uniform in solid
// angle) that misses the occluder, by quadrature, is what each sample sees.
double sun_share(double x, double z, double a) {
  const int nt = 200, np = 400;
  double seen = 0;
  for (int it = 0; it < nt; ++it)
    for (int ip = 0; ip < np; ++ip) {
      const double ct = 1 - (it + 0.5) / nt * (1 - std::cos(a)), st = std::sqrt(1 - ct * ct);
      const double ph = (ip + 0.5) / np * 2 * M_PI;
      const double hx = x + kOccY * st * std::cos(ph) / ct, hz = z + kOccY * st * std::sin(ph) / ct;
      seen += std::max(std::fabs(hx), std::fabs(hz)) > kOcc;
    }
  return seen / (nt * np);
}

void soft_shadow() {
  RayScene rays;
  add_quad(&rays, 0.0, 2.0, 0, "floor");
  add_quad(&rays, kOccY, kOcc, 1, "occluder");
  std::string err;
  if (!rays.commit(&err)) return check(false, "commit", err);
  const double a = 8 * M_PI / 180, R = kOccY * std::tan(a), I = 3;
  Floor f;
  bake_floor({sun(-1, I)}, &rays, &f, {a});
  if (!f.ok) return;
  // The rows j = 15..17 (|z| <= 0.16 + R < 0.5: only the occluder's x edges shadow them).
  long umbra = 0, lit = 0, partial = 0, bad = 0;
  double worst = 0, last_dark = -1, first_lit = 3;
  for (int j = 15; j <= 17; ++j)
    for (int i = 16; i < f.w; ++i) {
      double expect = 0, lo = 1, hi = 0;
      for (int sj = 0; sj < 2; ++sj)
        for (int si = 0; si < 2; ++si) {
          double x, z;
          sample_xz(i, j, si, sj, &x, &z);
          const double sh = sun_share(x, z, a);
          expect += sh / 4;
          lo = std::min(lo, sh);
          hi = std::max(hi, sh);
        }
      const double v = value(f, 0, i, j).x / I, x = -2 + 4.0 * i / 32;
      if (hi == 0) {
        ++umbra;
        bad += v != 0;
      } else if (lo == 1) {
        ++lit;
        bad += std::fabs(v - 1) > 1e-6;
      } else {
        ++partial;
        worst = std::max(worst, std::fabs(v - expect));
      }
      if (v == 0) last_dark = std::max(last_dark, x);
      if (std::fabs(v - 1) < 1e-6) first_lit = std::min(first_lit, x);
    }
  check(umbra > 3 && lit > 3 && bad == 0,
        "soft shadow: luxels in the umbra are 0, those past the penumbra fully lit (the cone ends where geometry puts it)",
        std::to_string(bad) + " off of " + std::to_string(umbra) + " dark, " + std::to_string(lit) + " lit");
  // 36 stratified shadow rays per luxel (vrad's 30 rounded up), 3 x 3 for each of its 4 samples: a
  // sample's share moves in steps of 1/9 and its strata straddling the occluder's edge are a coin
  // toss each: measured 0.089 of the full light at most; tolerance 0.12.
  check(partial >= 6 && worst < 0.12, "soft shadow: the penumbra's luxels = the share of the sun's cone the occluder leaves",
        std::to_string(partial) + " luxels, worst " + std::to_string(worst));
  // The penumbra's width: from the last dark luxel to the first fully lit one, 2 h tan a plus the
  // luxel's own footprint (1/8), within one luxel (1/8) each side.
  const double width = first_lit - last_dark;
  check(std::fabs(width - (2 * R + 0.125)) <= 2 * 0.125, "soft shadow: the penumbra is 2 h tan(spread) wide, within a luxel",
        "measured " + std::to_string(width) + ", geometry " + std::to_string(2 * R) + " + 0.125");
  // Spread 0 is the hard shadow, byte for byte.
  Floor hard, zero;
  bake_floor({sun(-1, I)}, &rays, &hard);
  bake_floor({sun(-1, I)}, &rays, &zero, {0.0});
  check(hard.ok && zero.ok && hard.out.page == zero.out.page, "soft shadow: spread 0 gives the hard shadow's page bytes");
}

void basis_values() {
  RayScene rays;
  add_quad(&rays, 0.0, 2.0, 0, "floor");
  std::string err;
  if (!rays.commit(&err)) return check(false, "commit", err);
  Floor f;
  bake_floor({sun(-1, 2)}, &rays, &f);
  if (!f.ok) return;
  double worst = 0;
  for (int j = 0; j < f.h; ++j)
    for (int i = 0; i < f.w; ++i) {
      const double flat = value(f, 0, i, j).x;
      for (int k = 1; k < 4; ++k) worst = std::max(worst, std::fabs(value(f, k, i, j).x - flat / std::sqrt(3.0)) / flat);
    }
  check(worst < 1e-6, "basis values: a light on the normal gives flat x 1/sqrt(3) on each basis vector",
        "worst relative " + std::to_string(worst));
  Floor b;
  bake_floor({sun(1, 2)}, &rays, &b);
  bool zero = b.ok;
  for (int j = 0; zero && j < b.h; ++j)
    for (int i = 0; i < b.w; ++i)
      for (int k = 0; k < 4; ++k) zero = zero && value(b, k, i, j).x == 0 && value(b, k, i, j).z == 0;
  check(zero, "basis values: a light behind the face gives zero");
}

void ray_scene() {
  RayScene r;
  add_quad(&r, 1.0, 1.0, 7, "high");
  add_quad(&r, 0.5, 1.0, 9, "low");
  std::string err;
  const std::vector<float> p = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  check(!r.add_mesh(p, {0, 1, 3}, 3, "broken mesh", &err) && err.find("broken mesh") != std::string::npos &&
            err.find("vertex 3") != std::string::npos,
        "ray scene: an index out of range is refused, naming the mesh", err);
  if (!r.commit(&err)) return check(false, "commit", err);
  check(r.triangles() == 4, "ray scene: 4 triangles", std::to_string(r.triangles()));
  const RayScene::Hit h = r.intersect(glm::dvec3(0.2, 3, 0.1), glm::dvec3(0, -1, 0), 0, INFINITY);
  check(h.id == 7 && std::fabs(h.t - 2) < 1e-6, "ray scene: the nearest hit (t, mesh id)",
        std::to_string(h.id) + " t " + std::to_string(h.t));
  const RayScene::Hit l = r.intersect(glm::dvec3(0.2, 0.8, 0.1), glm::dvec3(0, -1, 0), 0, INFINITY);
  check(l.id == 9 && std::fabs(l.t - 0.3) < 1e-6, "ray scene: from between the quads, the lower one");
  check(r.occluded(glm::dvec3(0, 3, 0), glm::dvec3(0, -3, 0), 0, 1) &&
            !r.occluded(glm::dvec3(0, 3, 0), glm::dvec3(0, -1.5, 0), 0, 1) &&
            !r.occluded(glm::dvec3(5, 3, 0), glm::dvec3(0, -3, 0), 0, 1),
        "ray scene: segments blocked and clear");
}

}  // namespace

int main() {
  ts_math_init();
  for (void (*test)() : {ray_scene, shadows, soft_shadow, basis_values, chart_shadows}) test();
  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed ? 1 : 0;
}

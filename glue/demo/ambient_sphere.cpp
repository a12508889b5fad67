// tiershade demo: the ambient_sphere section of `tiershade demo` (issue 13, docs/irradiance_volume.md):
// the per-pixel error of an ambient cube against the exact irradiance of the same light probe, as a
// picture. For each shipped probe (../shared/data/probes/grace.hdr, uffizi.hdr) and two views of a
// diffuse sphere (its +Z and its -Z hemisphere of normals), five panels: the sphere lit by the exact
// irradiance E(n)/pi (glue/bake/ambient_fit.h: probe_irradiance_at, every texel summed), by the
// least-squares cube (`lsq`), by Source's per-axis mean cube (`mean`), then each cube's signed error
// (luminance, orange: the cube too bright, blue: too dark). Cube at a normal: fact sheet section 3,
// n.x^2 C[x sign] + n.y^2 C[y sign] + n.z^2 C[z sign] (c_ref/offline/ambient_cube_fit.h: ts_ac_eval).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bake/ambient_fit.h"
#include "base/srgb.h"
#include "demo/scene_files.h"
#include "families/family.h"
#include "io/png.h"
#include "offline/ambient_cube_fit.h"

namespace {

int g_panel = 128;  // each sphere's square, pixels: 2/5 of the demo's height (128 at the default 640 x 320), >= 24
const int kGap = 4;
// The error panels' scale: full colour at this share of the exact sphere's mean luminance (linear
// display values: brightness proportional to the error).
const double kErrorFull = 0.5;

double luminance(const double c[3]) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

// The normal of panel pixel (x, y) (rows bottom-up) seen from +Z (front) or from -Z, or false off the disc.
bool panel_normal(int x, int y, bool front, double n[3]) {
  const double sx = (x + 0.5) / g_panel * 2 - 1, sy = (y + 0.5) / g_panel * 2 - 1, r2 = sx * sx + sy * sy;
  if (r2 >= 1) return false;
  const double z = std::sqrt(1 - r2);
  // Seen from -Z, the image's right is -X.
  n[0] = front ? sx : -sx;
  n[1] = sy;
  n[2] = front ? z : -z;
  return true;
}

ImageF blank() {
  ImageF im;
  im.w = im.h = g_panel;
  im.rgba.assign(static_cast<size_t>(g_panel) * g_panel * 4, 0.f);
  for (size_t i = 3; i < im.rgba.size(); i += 4) im.rgba[i] = 1.f;
  return im;
}

// Stacks rows top to bottom (ImageF rows are bottom-up: the first row goes highest), kGap apart.
ImageF vstack(const std::vector<ImageF> &rows) {
  ImageF out;
  out.w = rows.at(0).w;
  out.h = 0;
  for (const ImageF &r : rows) out.h += r.h + (out.h ? kGap : 0);
  out.rgba.assign(static_cast<size_t>(out.w) * out.h * 4, 1.f);
  int top = out.h;
  for (const ImageF &r : rows) {
    top -= r.h;
    std::copy(r.rgba.begin(), r.rgba.end(), out.rgba.begin() + static_cast<long>(top) * out.w * 4);
    top -= kGap;
  }
  return out;
}

bool run(const DemoOptions &opt, std::string *err) {
  g_panel = std::max(24, opt.h * 2 / 5);
  const char *const names[] = {"grace", "uffizi"};
  std::vector<ImageF> rows;
  for (const char *name : names) {
    ImageF probe;
    const std::string path = repo_file((std::string("../shared/data/probes/") + name + ".hdr").c_str());
    if (!read_latlong_probe(path, &probe, err)) return false;
    float lsq[6][3], mean[6][3];
    fit_probe_cube(probe, AmbientFit::Lsq, lsq);
    fit_probe_cube(probe, AmbientFit::Mean, mean);
    // Every disc pixel of both views, then their exact E/pi.
    std::vector<double> normals;
    std::vector<int> where;  // view * g_panel^2 + y * g_panel + x
    for (int view = 0; view < 2; ++view)
      for (int y = 0; y < g_panel; ++y)
        for (int x = 0; x < g_panel; ++x) {
          double n[3];
          if (!panel_normal(x, y, view == 0, n)) continue;
          normals.insert(normals.end(), n, n + 3);
          where.push_back((view * g_panel + y) * g_panel + x);
        }
    const std::vector<double> exact = probe_irradiance_at(probe, normals, 0);
    double peak = 0, mean_y = 0, se[2] = {0, 0};
    for (size_t i = 0; i < where.size(); ++i) {
      peak = std::max({peak, exact[i * 3], exact[i * 3 + 1], exact[i * 3 + 2]});
      mean_y += luminance(&exact[i * 3]) / where.size();
      for (int c = 0; c < 2; ++c) {
        double v[3];
        ts_ac_eval(c == 0 ? lsq : mean, &normals[i * 3], v);
        for (int k = 0; k < 3; ++k) se[c] += (v[k] - exact[i * 3 + k]) * (v[k] - exact[i * 3 + k]) / (3.0 * where.size());
      }
    }
    const double exposure = 0.9 / peak, full = kErrorFull * mean_y;
    std::vector<ImageF> panels(10, blank());  // view 0: 0..4, view 1: 5..9
    for (size_t i = 0; i < where.size(); ++i) {
      const int view = where[i] / (g_panel * g_panel), px = where[i] % (g_panel * g_panel);
      double cube_v[2][3];
      ts_ac_eval(lsq, &normals[i * 3], cube_v[0]);
      ts_ac_eval(mean, &normals[i * 3], cube_v[1]);
      const double *shade[3] = {&exact[i * 3], cube_v[0], cube_v[1]};
      for (int p = 0; p < 3; ++p)
        for (int k = 0; k < 3; ++k)
          panels[view * 5 + p].rgba[px * 4 + k] = static_cast<float>(srgb_encode_clamped(shade[p][k] * exposure));
      for (int c = 0; c < 2; ++c) {
        const double d = luminance(cube_v[c]) - luminance(&exact[i * 3]);
        const double t = std::min(1.0, std::fabs(d) / full);
        const double rgb[3] = {d > 0 ? t : 0.0, d > 0 ? 0.35 * t : 0.5 * t, d > 0 ? 0.0 : t};
        for (int k = 0; k < 3; ++k)
          panels[view * 5 + 3 + c].rgba[px * 4 + k] = static_cast<float>(rgb[k]);
      }
    }
    for (int view = 0; view < 2; ++view) {
      std::vector<const ImageF *> row;
      for (int p = 0; p < 5; ++p) row.push_back(&panels[view * 5 + p]);
      rows.push_back(hstack(row, kGap, 1.f));
    }
    printf("%s: %zu sphere pixels (two views); RMS against the exact irradiance over them: lsq %.4f, mean %.4f; "
           "display exposure %.3f, error panels full at %.0f %% of the mean luminance %.4f\n",
           name, where.size(), std::sqrt(se[0]), std::sqrt(se[1]), exposure, 100 * kErrorFull, mean_y);
  }
  const ImageF strip = vstack(rows);
  const std::string out = opt.dir + "/ambient_sphere.png";
  if (!write_png(out, strip, Encode::Linear, err)) return false;
  printf("wrote %s (rows: grace from +Z and -Z, uffizi from +Z and -Z; columns: exact irradiance, lsq cube, mean "
         "cube, lsq error, mean error)\n",
         out.c_str());
  return true;
}

const DemoSection kSection = {"ambient_sphere", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

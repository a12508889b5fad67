// tiershade bake: ambient cubes fitted to lat-long probes and their irradiance error (ambient_fit.h).
#include "bake/ambient_fit.h"

#include <algorithm>
#include <cmath>

#include "base/parallel_rows.h"
#include "io/exr.h"
#include "io/radiance_hdr.h"
#include "offline/ambient_cube_fit.h"

namespace {
constexpr double kPi = 3.14159265358979323846;

int fit_code(AmbientFit fit) {
  switch (fit) {
    case AmbientFit::Mean: return TS_AC_FIT_MEAN;
    case AmbientFit::LsqRadiance: return TS_AC_FIT_LSQ_RADIANCE;
    case AmbientFit::Lsq:
    case AmbientFit::LsqPixels: break;
  }
  return TS_AC_FIT_LSQ;
}

// Polar angle from +Y of row y's centre (row 0 bottom: v = 1 - (y + 0.5) / h, theta = v pi).
double row_theta(int h, double y) { return (1 - (y + 0.5) / h) * kPi; }
}  // namespace

bool ambient_fit_from_name(const std::string &name, AmbientFit *fit) {
  if (name == "mean") *fit = AmbientFit::Mean;
  else if (name == "lsq") *fit = AmbientFit::Lsq;
  else if (name == "lsq-pixels") *fit = AmbientFit::LsqPixels;
  else if (name == "lsq-radiance") *fit = AmbientFit::LsqRadiance;
  else return false;
  return true;
}

const char *ambient_fit_name(AmbientFit fit) {
  switch (fit) {
    case AmbientFit::Mean: return "mean";
    case AmbientFit::LsqRadiance: return "lsq-radiance";
    case AmbientFit::LsqPixels: return "lsq-pixels";
    case AmbientFit::Lsq: break;
  }
  return "lsq";
}

bool read_latlong_probe(const std::string &path, ImageF *probe, std::string *err) {
  const bool exr = path.size() >= 4 && (path.compare(path.size() - 4, 4, ".exr") == 0 ||
                                        path.compare(path.size() - 4, 4, ".EXR") == 0);
  if (!(exr ? read_exr(path, probe, err) : read_hdr(path, probe, err))) return false;
  std::string why;
  if (!image_ok(*probe, &why)) {
    if (err) *err = "probe '" + path + "': " + why;
    return false;
  }
  return true;
}

void latlong_texel(int w, int h, int x, int y, double d[3], double *solid_angle) {
  const double theta = row_theta(h, y);
  const double phi = ((x + 0.5) / w - 0.5) * 2 * kPi;  // u = phi / 2pi + 0.5
  d[0] = std::sin(theta) * std::sin(phi);
  d[1] = std::cos(theta);
  d[2] = -std::sin(theta) * std::cos(phi);
  // The texel spans theta in [pi (h - y - 1) / h, pi (h - y) / h] and 2pi / w in phi.
  const double t0 = kPi * (h - y - 1) / h, t1 = kPi * (h - y) / h;
  *solid_angle = 2 * kPi / w * (std::cos(t0) - std::cos(t1));
}

void fit_probe_cube(const ImageF &probe, AmbientFit fit, float cube[6][3], int threads) {
  if (fit == AmbientFit::LsqPixels) {
    fit_cube_to_irradiance(probe_irradiance(probe, threads), probe.w, probe.h, false, cube);
    return;
  }
  ts_ac_accum acc;
  ts_ac_accum_init(&acc, fit_code(fit));
  for (int y = 0; y < probe.h; ++y)
    for (int x = 0; x < probe.w; ++x) {
      double d[3], dw, rgb[3];
      latlong_texel(probe.w, probe.h, x, y, d, &dw);
      const float *p = &probe.rgba[(static_cast<size_t>(y) * probe.w + x) * 4];
      for (int k = 0; k < 3; ++k) rgb[k] = p[k];
      ts_ac_accum_add(&acc, d, rgb, dw);
    }
  ts_ac_accum_solve(&acc, cube);
}

std::vector<double> probe_irradiance(const ImageF &probe, int threads) {
  const int w = probe.w, h = probe.h;
  std::vector<double> out(static_cast<size_t>(w) * h * 3, 0.0);
  std::vector<double> cosd(w), dw(h), ct(h), st(h);
  for (int m = 0; m < w; ++m) cosd[m] = std::cos(2 * kPi * m / w);
  for (int y = 0; y < h; ++y) {
    double d[3];
    latlong_texel(w, h, 0, y, d, &dw[y]);
    ct[y] = std::cos(row_theta(h, y));
    st[y] = std::sin(row_theta(h, y));
  }
  // E(n)/pi = (1/pi) sum_texels L dw max(0, n . w). Between rows i and k the cosine depends on the
  // azimuth difference alone: n . w = ct_i ct_k + st_i st_k cos(2pi (j - m) / w), so each row pair is
  // one circular correlation of the input row with a precomputed kernel.
  parallel_rows(h, threads, [&](int i) {
    std::vector<double> kern(2 * static_cast<size_t>(w)), acc(static_cast<size_t>(w) * 3, 0.0);
    for (int k = 0; k < h; ++k) {
      if (ct[i] * ct[k] + st[i] * st[k] <= 0) continue;  // row k is below row i's horizon
      // kern[w + j - m] for j - m in (-w, w): the kernel twice over, so the loop needs no modulo.
      for (int m = 0; m < w; ++m) kern[m] = kern[w + m] = std::max(0.0, ct[i] * ct[k] + st[i] * st[k] * cosd[m]) * dw[k] / kPi;
      const float *row = &probe.rgba[static_cast<size_t>(k) * w * 4];
      for (int j = 0; j < w; ++j) {
        double r = 0, g = 0, b = 0;
        const double *kj = &kern[static_cast<size_t>(w) + j];
        for (int m = 0; m < w; ++m) {
          const double kv = kj[-m];
          r += kv * row[m * 4 + 0];
          g += kv * row[m * 4 + 1];
          b += kv * row[m * 4 + 2];
        }
        acc[j * 3 + 0] += r;
        acc[j * 3 + 1] += g;
        acc[j * 3 + 2] += b;
      }
    }
    std::copy(acc.begin(), acc.end(), out.begin() + static_cast<size_t>(i) * w * 3);
  });
  return out;
}

std::vector<double> probe_irradiance_at(const ImageF &probe, const std::vector<double> &n, int threads) {
  const size_t texels = static_cast<size_t>(probe.w) * probe.h, count = n.size() / 3;
  // Each texel's direction and radiance x solid angle / pi: E(n)/pi = sum max(0, n . w) L dw / pi.
  std::vector<double> dir(texels * 3), ldw(texels * 3);
  for (int y = 0; y < probe.h; ++y)
    for (int x = 0; x < probe.w; ++x) {
      const size_t t = static_cast<size_t>(y) * probe.w + x;
      double dw;
      latlong_texel(probe.w, probe.h, x, y, &dir[t * 3], &dw);
      for (int k = 0; k < 3; ++k) ldw[t * 3 + k] = probe.rgba[t * 4 + k] * dw / kPi;
    }
  std::vector<double> out(count * 3, 0.0);
  const int rows = static_cast<int>((count + 255) / 256);
  parallel_rows(rows, threads, [&](int r) {
    for (size_t i = static_cast<size_t>(r) * 256; i < std::min(count, static_cast<size_t>(r + 1) * 256); ++i) {
      double e[3] = {0, 0, 0};
      for (size_t t = 0; t < texels; ++t) {
        const double c = n[i * 3] * dir[t * 3] + n[i * 3 + 1] * dir[t * 3 + 1] + n[i * 3 + 2] * dir[t * 3 + 2];
        if (c <= 0) continue;
        for (int k = 0; k < 3; ++k) e[k] += c * ldw[t * 3 + k];
      }
      for (int k = 0; k < 3; ++k) out[i * 3 + k] = e[k];
    }
  });
  return out;
}

void fit_cube_to_irradiance(const std::vector<double> &exact, int w, int h, bool solid_angle, float cube[6][3]) {
  double g[6][6] = {}, b[6][3] = {};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double d[3], dw, a[6];
      latlong_texel(w, h, x, y, d, &dw);
      ts_ac_basis(d, a);
      const double wt = solid_angle ? dw : 1.0;
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) g[i][j] += wt * a[i] * a[j];
        for (int k = 0; k < 3; ++k) b[i][k] += wt * a[i] * exact[(static_cast<size_t>(y) * w + x) * 3 + k];
      }
    }
  for (int k = 0; k < 3; ++k) {
    double bk[6], xk[6];
    for (int i = 0; i < 6; ++i) bk[i] = b[i][k];
    ts_ac_nnls6(g, bk, xk);
    for (int i = 0; i < 6; ++i) cube[i][k] = static_cast<float>(xk[i]);
  }
}

CubeIrradianceError cube_irradiance_error(const float cube[6][3], const std::vector<double> &exact, int w, int h) {
  double sum_px = 0, sum_sa = 0, sa_total = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double d[3], dw, rgb[3];
      latlong_texel(w, h, x, y, d, &dw);
      ts_ac_eval(cube, d, rgb);
      double e2 = 0;
      for (int k = 0; k < 3; ++k) {
        const double e = rgb[k] - exact[(static_cast<size_t>(y) * w + x) * 3 + k];
        e2 += e * e;
      }
      sum_px += e2 / 3;
      sum_sa += dw * e2 / 3;
      sa_total += dw;
    }
  CubeIrradianceError r;
  r.rms_pixels = std::sqrt(sum_px / (static_cast<double>(w) * h));
  r.rms_solid_angle = std::sqrt(sum_sa / sa_total);
  return r;
}

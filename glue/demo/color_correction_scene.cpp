// tiershade demo: frame and example corrections of the colour-correction demo and benchmark.
#include "demo/color_correction_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "color/ciede2000.h"
#include "io/radiance_hdr.h"
#include "base/srgb.h"

namespace {

// HSV (h in [0, 1)) to RGB, for the chart.
void hsv(double h, double s, double v, double rgb[3]) {
  const double h6 = h * 6.0;
  const int i = static_cast<int>(h6) % 6;
  const double f = h6 - std::floor(h6);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double tab[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  for (int k = 0; k < 3; ++k) rgb[k] = tab[i][k];
}

void put(ImageF *img, int x, int y, const double rgb[3]) {
  float *p = &img->rgba[(static_cast<size_t>(y) * img->w + x) * 4];
  for (int k = 0; k < 3; ++k) p[k] = static_cast<float>(rgb[k]);
  p[3] = 1.f;
}

// Rows [y0, y1) of img (bottom-up) get the chart: hue across, value down, a grey ramp last.
void chart(ImageF *img, int y0, int y1) {
  const int rows = y1 - y0;
  for (int y = y0; y < y1; ++y) {
    const double t = static_cast<double>(y1 - 1 - y) / std::max(1, rows - 1);  // 0 at the top of the band
    for (int x = 0; x < img->w; ++x) {
      const double u = (x + 0.5) / img->w;
      double rgb[3];
      if (t < 0.8) {
        hsv(u, t < 0.4 ? 1.0 : 1.0 - (t - 0.4) / 0.4 * 0.7, t < 0.4 ? 1.0 - t * 1.5 : 0.4 + (t - 0.4), rgb);
      } else {
        rgb[0] = rgb[1] = rgb[2] = u;
      }
      put(img, x, y, rgb);
    }
  }
}

}  // namespace

ImageF cc_frame(int w, int h, std::string *note) {
  ImageF img;
  img.w = w;
  img.h = h;
  img.rgba.assign(static_cast<size_t>(w) * h * 4, 1.f);
  const char *env = std::getenv("TIERSHADE_PROBE_HDR");
  const std::string path = env && *env ? env : "../shared/data/probes/grace.hdr";
  ImageF probe;
  std::string err;
  const int chart_rows = h / 3;
  if (!read_hdr(path, &probe, &err)) {
    chart(&img, 0, h);
    *note = "colour chart only (no probe: " + err + ")";
    return img;
  }
  // Exposure: the log-average luminance (Rec. 709 weights) goes to 0.18.
  double logsum = 0;
  const size_t n = static_cast<size_t>(probe.w) * probe.h;
  for (size_t i = 0; i < n; ++i) {
    const float *p = &probe.rgba[i * 4];
    logsum += std::log(1e-4 + 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
  }
  const double exposure = 0.18 / std::exp(logsum / static_cast<double>(n));
  // The probe, bilinearly resampled into the rows above the chart (rows bottom-up).
  const int top = h - chart_rows;
  for (int y = chart_rows; y < h; ++y) {
    const double v = (y - chart_rows + 0.5) / top * probe.h - 0.5;
    const int y0 = std::max(0, std::min(probe.h - 1, static_cast<int>(std::floor(v))));
    const int y1 = std::min(probe.h - 1, y0 + 1);
    const double fy = std::min(1.0, std::max(0.0, v - y0));
    for (int x = 0; x < w; ++x) {
      const double u = (x + 0.5) / w * probe.w - 0.5;
      const int x0 = std::max(0, std::min(probe.w - 1, static_cast<int>(std::floor(u))));
      const int x1 = std::min(probe.w - 1, x0 + 1);
      const double fx = std::min(1.0, std::max(0.0, u - x0));
      double rgb[3];
      for (int k = 0; k < 3; ++k) {
        auto at = [&](int xx, int yy) {
          return static_cast<double>(probe.rgba[(static_cast<size_t>(yy) * probe.w + xx) * 4 + k]);
        };
        const double c =
            (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
        rgb[k] = srgb_encode_clamped(c * exposure);
      }
      put(&img, x, y, rgb);
    }
  }
  chart(&img, 0, chart_rows);
  *note = path + " (exposure " + std::to_string(exposure).substr(0, 6) + ", clipped, sRGB) above a colour chart";
  return img;
}

bool cc_examples(std::vector<CcExample> *out, std::string *err) {
  out->clear();
  const char *const files[][2] = {{"day_for_night", "scenes/luts/day_for_night.cube"},
                                  {"desaturate", "scenes/luts/desaturate.cube"},
                                  {"warm", "scenes/luts/warm.cc"}};
  for (const auto &f : files) {
    CcExample e;
    e.name = f[0];
    e.file = f[1];
    TransformSpec s;
    s.kind = TransformSpec::Kind::File;
    s.file = f[1];
    if (!e.transform.open(s, err)) return false;
    out->push_back(std::move(e));
  }
  return true;
}

ImageF cc_apply_reference(const ColorTransform &t, const ImageF &frame) {
  ImageF out = frame;
  const size_t n = static_cast<size_t>(frame.w) * frame.h;
  std::vector<float> rgb(n * 3);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) rgb[i * 3 + k] = std::min(1.f, std::max(0.f, frame.rgba[i * 4 + k]));
  t.apply(rgb.data(), n);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const float v = rgb[i * 3 + k];
      out.rgba[i * 4 + k] = std::isnan(v) ? 0.f : std::min(1.f, std::max(0.f, v));
    }
  return out;
}

void cc_frame_difference(const ImageF &a, const ImageF &b, double *max, double *mean) {
  const size_t n = static_cast<size_t>(a.w) * a.h;
  double m = 0, s = 0;
  for (size_t i = 0; i < n; ++i) {
    const float *p = &a.rgba[i * 4], *q = &b.rgba[i * 4];
    const double d = ciede2000(srgb_to_lab(p[0], p[1], p[2]), srgb_to_lab(q[0], q[1], q[2]));
    m = std::max(m, d);
    s += d;
  }
  *max = m;
  *mean = n ? s / static_cast<double>(n) : 0;
}

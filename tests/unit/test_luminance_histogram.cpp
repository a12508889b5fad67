// tiershade tests: the GPU luminance histogram (glue/hdr/luminance_histogram_gl.cpp) against its exact C
// twin (glue/hdr/luminance_histogram_cpu.cpp), on every backend/API pair: OSMesa GL 3.3
// and EGL GL 3.3 (occlusion queries), EGL GLES 3.0 (fenced pixel-pack buffers), EGL
// GLES 2.0 (synchronous readback). For the float path (an RGBA16F frame x tone-map
// scale) and the integer path (an sRGB-encoded RGBA8 frame), with and without the
// temporal prefilter, a sequence of changing frames is measured one bucket per frame;
// every measurement the GPU returns (bucket, frame counted, count) must equal the
// exact count, in the same frames. No tolerance: counts are integers.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if anything failed.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "families/family.h"
#include "math/hdr_formats.h"
#include "hdr/luminance_histogram.h"
#include "unit_gl.h"

namespace {

const int W = 61, H = 37;  // odd sizes: the window margins round

// Frame f: luminance spread over 14 stops, moving with f, with pixels exactly on bucket
// bounds (linear frames) and a few NaN/Inf/negative texels that no bucket may count.
void make_frame(int f, bool srgb8, std::vector<uint16_t> *halves, std::vector<uint8_t> *codes,
                std::vector<float> *texels) {
  Rng r(1234u + static_cast<uint32_t>(f) * 7u);
  const size_t n = static_cast<size_t>(W) * H * 4;
  halves->assign(n, 0);
  codes->assign(n, 0);
  texels->assign(n, 0.f);
  for (size_t p = 0; p < static_cast<size_t>(W) * H; ++p) {
    const double t = std::fmod(p * 0.61803 + f * 0.05, 1.0);
    const float base = static_cast<float>(std::exp2(-12.0 + 14.0 * t));
    for (int c = 0; c < 4; ++c) {
      const size_t i = p * 4 + c;
      const float v = c == 3 ? 1.f : base * r.uniform(0.5f, 1.5f);
      if (srgb8) {
        (*codes)[i] = static_cast<uint8_t>(c == 3 ? 255 : std::fmin(255.f, v * 255.f));
        (*texels)[i] = ts_unorm8_to_float((*codes)[i]);
      } else {
        float x = v;
        if (p % 97 == 5 && c == 0) x = std::nanf("");
        if (p % 89 == 7 && c == 1) x = INFINITY;
        if (p % 83 == 3 && c == 2) x = -2.f;
        if (p % 13 == 0 && c < 3) {  // grey pixels on a bucket bound (luminance ~ bound)
          float lo, hi;
          ae_bucket_bounds(static_cast<int>(p / 13) % 16, &lo, &hi);
          x = lo;
        }
        (*halves)[i] = ts_half_from_float_rz(x);
        (*texels)[i] = ts_half_to_float((*halves)[i]);
      }
    }
  }
}

void run(Backend b, Api api, int encoding, double alpha) {
  const std::string name = config_name(b, api) +
      (encoding ? " integer path" : " float path") + (alpha < 1 ? ", prefilter 1/16" : ", no prefilter");
  std::string err;
  auto ctx = open_context(b, api, "histogram " + name);
  if (!ctx) return;
  GlRenderer r(*ctx);
  PassRunner runner(r);
  HistogramConfig cfg;
  cfg.w = W;
  cfg.h = H;
  cfg.input_encoding = encoding;
  cfg.alpha = alpha;
  LuminanceHistogramGl gpu(runner, b, api, cfg);
  LuminanceHistogramCpu cpu(cfg);
  if (!gpu.init(&err)) {
    check(false, "histogram " + name, err);
    return;
  }
  std::vector<HistogramMeasurement> got, want;
  const int frames = 3 * AE_BUCKETS + 5;
  for (int f = 0; f < frames; ++f) {
    std::vector<uint16_t> halves;
    std::vector<uint8_t> codes;
    std::vector<float> texels;
    make_frame(f, encoding == 1, &halves, &codes, &texels);
    const GLuint tex = encoding ? upload_rgba8(r.gl(), W, H, codes) : upload_rgba16f(r.gl(), W, H, halves);
    const float tscale = encoding ? 1.f : static_cast<float>(0.25 + 0.1 * f);
    const bool ok = gpu.frame(tex, tscale, f, &got, &err);
    r.gl().DeleteTextures(1, &tex);
    if (!ok) {
      check(false, "histogram " + name, err);
      return;
    }
    cpu.frame(texels.data(), tscale, f, &want);
  }
  bool same = got.size() == want.size();
  std::string why =
      same ? "" : std::to_string(got.size()) + " GPU measurements, " + std::to_string(want.size()) + " exact";
  long nonzero = 0, distinct = 0;
  for (size_t i = 0; same && i < got.size(); ++i) {
    if (got[i].bucket != want[i].bucket || got[i].frame != want[i].frame || got[i].count != want[i].count) {
      same = false;
      why = "bucket " + std::to_string(want[i].bucket) + " of frame " + std::to_string(want[i].frame) + ": GPU " +
          std::to_string(got[i].count) + " (bucket " + std::to_string(got[i].bucket) + ", frame " +
          std::to_string(got[i].frame) + "), exact " + std::to_string(want[i].count);
    }
    if (got[i].count) ++nonzero;
    if (i && got[i].count != got[i - 1].count) ++distinct;
  }
  check(same,
        "histogram " + name + ": every GPU bucket count equals the exact count (" + std::to_string(got.size()) +
            " measurements, " + gpu.method() + ", " + std::to_string(gpu.late_reads()) + " reads waited)",
        why);
  // Guard against a test that cannot fail: the frames must fill many buckets differently.
  check(nonzero > static_cast<long>(got.size()) / 2 && distinct > static_cast<long>(got.size()) / 2,
        "histogram " + name + ": the measured counts are non-trivial",
        std::to_string(nonzero) + " non-zero, " + std::to_string(distinct) + " changes");
}

}  // namespace

int main() {
  ts_math_init();
  for (const BackendApi &c : all_gl_configs())
    for (int encoding : {0, 1})
      for (double alpha : {1.0, 0.0625}) run(c.backend, c.api, encoding, alpha);
  return g_failed ? 1 : 0;
}

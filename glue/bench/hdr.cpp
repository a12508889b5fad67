// tiershade bench: the `bench` section of the HDR paths (docs/accuracy_cost.md): what the
// integer path loses against the float path, measured in one run on the HDR scene
// (glue/demo/hdr_scene.h) at tone-map scale 1:
//   - error in 8-bit display codes against the double-precision float path (no storage
//     rounding), with bloom and, to separate precision from bloom, without;
//   - the auto-exposure histogram each path measures (integer: the RGBA8 frame decoded;
//     float: the fp16 frame x scale) against the exact one of the double frame;
//   - bytes per pixel of the render targets each path allocates;
//   - llvmpipe milliseconds per frame (median; OSMesa GL 3.3, glFinish included), and the
//     ratio float / integer measured in the same run.
// Not a test: nothing here passes or fails.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "exposure/auto_exposure.h"
#include "math/hdr_formats.h"
#include "hdr/paths.h"
#include "demo/hdr_scene.h"
#include "twins/luminance_compare.h"
#include "twins/model_lighting.h"
#include "base/stats.h"

namespace {

struct ErrorStats {
  double max = 0, mean = 0, over1 = 0;  // codes; share of channels off by more than 1 code (%)
};

ErrorStats display_error(const std::vector<uint8_t> &codes, const std::vector<double> &ref) {
  ErrorStats e;
  double sum = 0;
  long n = 0, off = 0;
  for (size_t i = 0; i < codes.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = std::fabs(codes[i] - 255.0 * ref[i]);
    e.max = std::max(e.max, d);
    sum += d;
    off += d > 1.0;
    ++n;
  }
  e.mean = sum / std::max(1L, n);
  e.over1 = 100.0 * off / std::max(1L, n);
  return e;
}

// Bucket fractions of a frame over the centred window (luminance_compare's test, in the
// twin for float frames; in double for the reference).
void fractions(const std::vector<float> &texels, int w, int h, int encoding, float tscale, double out[AE_BUCKETS]) {
  const ae_window win = ae_center_window(w, h, 0.9, 0.85);
  const double all = static_cast<double>(ae_exact_count(texels.data(), w, h, win, encoding, tscale, AE_ALL_PIXELS));
  for (int b = 0; b < AE_BUCKETS; ++b)
    out[b] = ae_exact_count(texels.data(), w, h, win, encoding, tscale, b) / std::max(1.0, all);
}

void fractions_exact(const std::vector<double> &lin, int w, int h, double tscale, double out[AE_BUCKETS]) {
  const ae_window win = ae_center_window(w, h, 0.9, 0.85);
  long count[AE_BUCKETS] = {0};
  for (int y = win.y0; y < win.y0 + win.h; ++y)
    for (int x = win.x0; x < win.x0 + win.w; ++x) {
      const double *p = &lin[(static_cast<size_t>(y) * w + x) * 4];
      const double lum = (0.2125 * p[0] + 0.7154 * p[1] + 0.0721 * p[2]) * tscale;
      for (int b = 0; b < AE_BUCKETS; ++b) {
        float lo, hi;
        ae_bucket_bounds(b, &lo, &hi);
        count[b] += lum >= lo && lum <= hi;
      }
    }
  for (int b = 0; b < AE_BUCKETS; ++b) out[b] = static_cast<double>(count[b]) / std::max(1L, count[AE_ALL_PIXELS]);
}

double l1(const double a[AE_BUCKETS], const double b[AE_BUCKETS]) {
  double s = 0;
  for (int i = 0; i < AE_RANGES; ++i) s += std::fabs(a[i] - b[i]);
  return 100.0 * s;
}

bool run_bench(const BenchOptions &opt, std::string *md, std::string *err) {
  const int w = std::max(16, opt.size / 4 * 4), h = std::max(16, opt.size / 2 / 4 * 4);
  std::vector<ShaderDecl> decls;
  Variant lin_v, disp_v;
  if (!load_shader_decls(&decls, err) || !hdr_lit_variant(decls, 0, &lin_v, err) ||
      !hdr_lit_variant(decls, 2, &disp_v, err))
    return false;
  const ShaderFamily *lit = find_family("model_lighting");
  std::string note;
  SceneDeferredFrame frame;
  if (!lit || !hdr_scene_frame(kHdrDaylightGltf, w, h, &frame, &note, err)) {
    if (!lit) *err = "model_lighting is not registered";
    return false;
  }
  const FamilyInputs &in = frame.in;
  HdrSettings bloom_on, bloom_off;
  bloom_off.bloom_amount = 0.f;

  // The references: the float path in double (bloom on and off), and the exact linear frame.
  std::vector<double> ref_on, ref_off;
  hdr_float_frame_reference(*lit, lin_v, in, bloom_on, &ref_on);
  hdr_float_frame_reference(*lit, lin_v, in, bloom_off, &ref_off);
  FamilyInputs unit = in;
  unit.shared.at(ML_SLOT_PARAMS).x = 1.f;  // linear radiance, before any tone map
  std::vector<double> lin;
  cpu_render_frame_double(*lit, lin_v, unit, &lin);

  // The C twins (equal to the GL frames, checked below).
  HdrFrameC ci, cf_on, cf_off;
  hdr_integer_frame_c(*lit, disp_v, in, 1.f, &ci);
  hdr_float_frame_c(*lit, lin_v, in, bloom_on, &cf_on);
  hdr_float_frame_c(*lit, lin_v, in, bloom_off, &cf_off);

  // GL: time and equality with C.
  std::string gl_note;
  double ms_int = 0, ms_float = 0;
  long diff = 0;
  {
    auto ctx = GlContext::create(Backend::OSMesa, Api::GL33, err);
    if (!ctx) return false;
    GlRenderer r(*ctx);
    PassRunner run(r);
    HdrPipelineGl gl(run, Api::GL33);
    if (!gl.init(*lit, lin_v, disp_v, in, err)) return false;
    std::vector<double> ti, tf;
    std::vector<uint8_t> got;
    for (int k = 0; k <= opt.runs; ++k) {  // the first round warms up (JIT)
      auto t0 = std::chrono::steady_clock::now();
      if (!gl.integer_frame(in.shared, 1.f, err)) return false;
      r.gl().Finish();
      auto t1 = std::chrono::steady_clock::now();
      if (k == 0 && read_rgba8(r.gl(), gl.display(), &got, err))
        for (size_t i = 0; i < got.size(); ++i) diff += got[i] != ci.display[i];
      auto t2 = std::chrono::steady_clock::now();
      if (!gl.float_frame(in.shared, bloom_on, err)) return false;
      r.gl().Finish();
      auto t3 = std::chrono::steady_clock::now();
      if (k == 0 && read_rgba8(r.gl(), gl.display(), &got, err))
        for (size_t i = 0; i < got.size(); ++i) diff += got[i] != cf_on.display[i];
      if (k > 0) {
        ti.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        tf.push_back(std::chrono::duration<double, std::milli>(t3 - t2).count());
      }
    }
    ms_int = median(ti);
    ms_float = median(tf);
  }

  const ErrorStats ei_on = display_error(ci.display, ref_on), ef_on = display_error(cf_on.display, ref_on);
  const ErrorStats ei_off = display_error(ci.display, ref_off), ef_off = display_error(cf_off.display, ref_off);
  double h_exact[AE_BUCKETS], h_int[AE_BUCKETS], h_float[AE_BUCKETS];
  fractions_exact(lin, w, h, 1.0, h_exact);
  std::vector<float> tex(ci.display.size());
  for (size_t i = 0; i < tex.size(); ++i) tex[i] = ts_unorm8_to_float(ci.display[i]);
  fractions(tex, w, h, 1, 1.f, h_int);
  fractions(cf_on.hdr, w, h, 0, 1.f, h_float);
  // Bytes per pixel of the targets each path allocates (HdrPipelineGl): integer one RGBA8 frame;
  // float an RGBA16F frame, three quarter-size RGBA16F bloom targets and the RGBA8 result.
  const double px = static_cast<double>(w) * h;
  const double bq = static_cast<double>(hdr_bloom_size(w)) * hdr_bloom_size(h);
  const double b_int = target_bytes_per_pixel(TargetFormat::RGBA8);
  const double b_float = target_bytes_per_pixel(TargetFormat::RGBA16F) +
      3 * target_bytes_per_pixel(TargetFormat::RGBA16F) * bq / px + target_bytes_per_pixel(TargetFormat::RGBA8);
  long hdr_px = 0;
  for (size_t p = 0; p < lin.size() / 4; ++p)
    hdr_px += 0.2125 * lin[p * 4] + 0.7154 * lin[p * 4 + 1] + 0.0721 * lin[p * 4 + 2] > 1.0;

  std::ostringstream o;
  char b[512];
  o << "## HDR: the integer path against the float path, " << w << "x" << h << " frame\n\n"
    << "Scene: the HDR scene of `tiershade demo` (glue/demo/hdr_scene.h; " << note
    << "), tone-map scale 1: " << std::to_string(100.0 * hdr_px / px).substr(0, 4)
    << " % of the pixels have a luminance above 1 before tone mapping. Integer path: model_lighting sm3 with\n"
    << "the tone-map scale and exact sRGB in the shader, into RGBA8. Float path: linear into RGBA16F, bloom\n"
    << "(4x4 box, 13-tap Gaussian X and Y on quarter-size RGBA16F), hdr_tonemap (bloom amount " << bloom_on.bloom_amount
    << ", exponent " << bloom_on.bloom_exponent << ") into RGBA8 (docs/hdr.md).\n\n"
    << "- **error**: |display code - 255 x reference| over every channel, against the float path evaluated in\n"
    << "  double with no storage rounding (intermediate images in float32), with bloom and without bloom.\n"
    << "- **histogram L1**: sum over the 16 ranges of |bucket fraction - exact fraction| (%), the exact\n"
    << "  histogram being that of the double linear frame; what the auto exposure sees of each path.\n"
    << "- **bytes/pixel**: colour targets the path allocates, per frame pixel.\n"
    << "- **ms**: llvmpipe, OSMesa GL 3.3, median of " << opt.runs << " frames, glFinish included.\n"
    << "- GL = C: the GL frames of both paths equal the C twins' (" << diff << " codes differ).\n\n"
    << "| path | error max (codes) | error mean | >1 code | error max, no bloom | mean, no bloom | histogram L1 (%) "
       "| bytes/pixel | llvmpipe ms | x integer time |\n"
    << "|---|---|---|---|---|---|---|---|---|---|\n";
  snprintf(b, sizeof b, "| integer (RGBA8) | %.2f | %.3f | %.2f%% | %.2f | %.3f | %.3f | %.1f | %.2f | 1.00 |\n",
           ei_on.max, ei_on.mean, ei_on.over1, ei_off.max, ei_off.mean, l1(h_int, h_exact), b_int, ms_int);
  o << b;
  snprintf(b, sizeof b,
           "| float (RGBA16F + bloom) | %.2f | %.3f | %.2f%% | %.2f | %.3f | %.3f | %.1f | %.2f | %.2f |\n", ef_on.max,
           ef_on.mean, ef_on.over1, ef_off.max, ef_off.mean, l1(h_float, h_exact), b_float, ms_float,
           ms_int > 0 ? ms_float / ms_int : 0);
  o << b;
  o << "\nReading the table: without bloom both paths are within rounding of the reference (the integer path\n"
    << "rounds once, to 8 bits; the float path rounds to fp16 toward zero, then to 8 bits). With bloom the\n"
    << "integer path has no bloom at all in this comparison: it has no pre-tone-map data to take it from, which\n"
    << "is the talk's \"pre-tone-mapping data available for blooming\" trade-off. Its histogram is measured on\n"
    << "8-bit sRGB codes, so dark pixels are coarse; the float path measures the fp16 values.\n";
  *md = o.str();
  return true;
}

const BenchSection kHdrBench = {"hdr", run_bench};
const BenchRegistrar kRegisterHdrBench(&kHdrBench);

}  // namespace

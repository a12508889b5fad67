// tiershade tests: unit tests of the auto-exposure histogram and controller (c_ref/exposure/auto_exposure.*,
// c_ref/exposure/exposure_control.*), in C only (the GPU counts are checked against these
// exact counts by test_luminance_histogram):
//   * the 17-bucket layout, the centred window, the running-histogram schedule;
//   * the bright-fraction location, the sticky target, the minimum-average rule;
//   * closed loop on a synthetic HDR scene (exact counts, one bucket per frame, read
//     3 frames late, exactly as the GPU module runs): convergence on a static scene,
//     no oscillation on a flickering one, faster adaptation downward;
//   * designer overrides per region.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if anything failed.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <functional>

#include "exposure/auto_exposure.h"
#include "exposure/exposure_control.h"
#include "hdr/luminance_histogram.h"
#include "math/ts_math.h"
#include "unit_check.h"

namespace {

std::string fmt(const char *f, double a, double b = 0, double c = 0) {
  char buf[256];
  snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

// ---- layout, window, schedule -------------------------------------------------------

void test_layout() {
  bool ok = true;
  std::string why;
  double prev_width = 0;
  for (int i = 0; i < AE_RANGES; ++i) {
    float lo, hi;
    ae_bucket_bounds(i, &lo, &hi);
    const float want_lo = static_cast<float>(std::pow(i / 16.0, 1.5));
    if (lo != want_lo) ok = false, why = "bucket " + std::to_string(i) + " min";
    const double width = std::pow((i + 1) / 16.0, 1.5) - std::pow(i / 16.0, 1.5);
    if (width <= prev_width) ok = false, why = "bucket widths do not grow";
    prev_width = width;
    if (i < AE_RANGES - 1 && hi != static_cast<float>(std::pow((i + 1) / 16.0, 1.5))) ok = false, why = "max";
  }
  float lo, hi;
  ae_bucket_bounds(15, &lo, &hi);
  check(hi == 10000.f, "layout: the top bucket's max 1.0 is widened to 10000", fmt("got %g", hi));
  ae_bucket_bounds(AE_ALL_PIXELS, &lo, &hi);
  check(lo == 0.f && hi == 100000.f, "layout: bucket 16 is [0, 100000], every pixel");
  check(ok, "layout: bucket i is [(i/16)^1.5, ((i+1)/16)^1.5], widths growing (more buckets at low luminance)", why);
  double slo, shi;
  ae_bucket_span(15, &slo, &shi);
  check(shi == 1.0, "layout: the controller interpolates bucket 15 up to 1.0");
}

void test_window() {
  const ae_window w = ae_center_window(640, 320, 0.9, 0.85);
  check(w.x0 == 32 && w.w == 576 && w.y0 == 24 && w.h == 272, "window: 0.9 x 0.85 of 640x320 is 576x272 at (32, 24)",
        fmt("%g %g", w.w, w.h));
  const ae_window t = ae_center_window(3, 3, 0.9, 0.85);
  check(t.w == 3 && t.h == 3, "window: a 3x3 viewport keeps every pixel (margins round to 0)");
}

void test_schedule() {
  ae_histogram h;
  ae_histogram_init(&h);
  std::vector<int> order;
  bool ok = true;
  std::string why;
  for (int64_t f = 0; f < 60; ++f) {
    for (int b = 0; b < AE_BUCKETS; ++b) {
      if (h.pending[b] && !ae_may_read(&h, b, f) && f - h.pending_frame[b] > AE_READ_DELAY) ok = false;
      if (ae_may_read(&h, b, f)) {
        if (f - h.pending_frame[b] <= 2) ok = false, why = "read too early";
        ae_store(&h, b, static_cast<uint32_t>(b));
      }
    }
    const int b = ae_next_bucket(&h);
    if (b < 0) {
      ok = false;
      why = "no bucket free";
      break;
    }
    order.push_back(b);
    ae_mark_issued(&h, b, f);
  }
  // The first 17 frames measure every bucket once, in order; after that each bucket comes
  // back every 17 frames (the oldest first).
  for (int i = 0; i < 17; ++i)
    if (order[i] != i) ok = false, why = "first round out of order";
  for (size_t i = 17; i < order.size(); ++i)
    if (order[i] != order[i - 17]) ok = false, why = "period is not 17";
  check(ok, "running histogram: one bucket per frame, oldest first, every bucket every 17 frames, read > 2 frames late",
        why);
  check(ae_histogram_complete(&h), "running histogram: complete after the first round");
}

// ---- location and target ---------------------------------------------------------------

// A histogram whose fractions are given (out of 10000 pixels), measured at frame 0.
ae_histogram make_hist(const std::vector<std::pair<int, uint32_t>> &counts) {
  ae_histogram h;
  ae_histogram_init(&h);
  for (int i = 0; i < AE_BUCKETS; ++i) h.measured_frame[i] = 0;
  for (auto &c : counts) h.count[c.first] = c.second;
  h.count[AE_ALL_PIXELS] = 10000;
  return h;
}

void test_location() {
  double lo, hi;
  // Every pixel in bucket 10: the brightest 2 % start 2 % below its top.
  ae_histogram h = make_hist({{10, 10000}});
  ae_bucket_span(10, &lo, &hi);
  const double l = ae_location_of_bright_fraction(&h, 0.02, -1);
  check(std::fabs(l - (hi - 0.02 * (hi - lo))) < 1e-12, "location: interpolated inside the bucket", fmt("%g", l));
  // 1 % in bucket 15, 99 % in bucket 4: the 2 % point is 1/99 of the way down bucket 4.
  h = make_hist({{15, 100}, {4, 9900}});
  ae_bucket_span(4, &lo, &hi);
  const double l2 = ae_location_of_bright_fraction(&h, 0.02, -1);
  check(std::fabs(l2 - (hi - (0.01 / 0.99) * (hi - lo))) < 1e-12, "location: accumulates from the bright end",
        fmt("%g", l2));
  // Sticky: 0.60 lies in bucket 11 ([0.5700, 0.6495]).
  ae_settings s;
  ae_default_settings(&s);
  h = make_hist({{11, 10000}});
  check(ae_location_of_bright_fraction(&h, 0.02, 0.6) == 0.6 && ae_target_scale(&h, &s, 1.7) == 1.7,
        "target: sticky when 0.60 lies in the 2 % bucket (no change)");
  ae_histogram empty;
  ae_histogram_init(&empty);
  check(ae_target_scale(&empty, &s, 1.3) == 1.3, "target: no change before every bucket was measured");
}

void test_min_avg_rule() {
  ae_settings s;
  ae_default_settings(&s);
  // A dark room with a bright window: 3 % of the pixels in bucket 15, 97 % in bucket 0.
  ae_histogram h = make_hist({{15, 300}, {0, 9700}});
  double lo, hi;
  ae_bucket_span(0, &lo, &hi);
  const double l50 = hi - ((0.5 - 0.03) / 0.97) * (hi - lo);
  const double want = (0.03 / l50) * 2.0;  // brightening wins over 0.6 / L_2%
  const double got = ae_target_scale(&h, &s, 2.0);
  check(std::fabs(got / want - 1) < 1e-12, "target: minimum-average-luminance rule brightens a dark frame",
        fmt("got %g want %g", got, want));
  // Bright frame: the 2 % rule darkens; 0.03 / L_50 is smaller and ignored.
  h = make_hist({{15, 10000}});
  ae_bucket_span(15, &lo, &hi);
  const double lp = hi - 0.02 * (hi - lo);
  check(std::fabs(ae_target_scale(&h, &s, 1.0) - 0.6 / lp) < 1e-12, "target: 0.60 / L_2% on a bright frame");
  // All black: location 0 asks for the maximum brightening, floored and later clamped.
  h = make_hist({{0, 10000}});
  check(ae_target_scale(&h, &s, 1.0) > 10.0, "target: an all-black frame asks to brighten");
}

// ---- closed loop on a synthetic scene ---------------------------------------------------

struct Scene {
  int w = 96, h = 64;
  std::vector<float> rgba;  // linear HDR
};

// Luminance spread over 12 stops (1e-3 .. 4) with a 3 % patch of bright highlights (8 .. 40).
Scene make_scene(double brightness) {
  Scene s;
  s.rgba.resize(static_cast<size_t>(s.w) * s.h * 4);
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) {
      const double t = (x + 0.5) / s.w, u = (y + 0.5) / s.h;
      double l = 1e-3 * std::pow(4000.0, 0.5 * t + 0.5 * u * u);
      if (x > s.w - 6 && y < s.h / 2) l = 8.0 + 32.0 * u;
      float *p = &s.rgba[(static_cast<size_t>(y) * s.w + x) * 4];
      p[0] = static_cast<float>(l * brightness * 1.1);
      p[1] = static_cast<float>(l * brightness);
      p[2] = static_cast<float>(l * brightness * 0.8);
      p[3] = 1.f;
    }
  return s;
}

// Runs the closed loop for `frames` frames at 30 frames per second; scene_of(f) gives the
// frame's scene. The histogram is the GPU module's exact twin (glue/hdr/luminance_histogram_cpu.cpp):
// one bucket per frame, read 3 frames late, on the float path (linear frame x the tone-map
// scale in use), with the temporal prefilter weight alpha (1 = none). Returns the scale per frame.
template <class SceneOf>
std::vector<double> run_loop(SceneOf scene_of, int frames, const ae_settings &set, double scale0, double alpha,
                             ae_state *state_out = nullptr) {
  HistogramConfig cfg;
  const Scene &s0 = scene_of(0);
  cfg.w = s0.w;
  cfg.h = s0.h;
  cfg.input_encoding = 0;
  cfg.alpha = alpha;
  LuminanceHistogramCpu hist(cfg);
  ae_state st;
  ae_state_init(&st, scale0, 0.0);
  std::vector<double> scales;
  for (int f = 0; f < frames; ++f) {
    hist.frame(scene_of(f).rgba.data(), static_cast<float>(st.scale), f, nullptr);
    ae_update(&st, &hist.histogram(), &set, 1.0 / 30.0);
    scales.push_back(st.scale);
  }
  if (state_out) *state_out = st;
  return scales;
}

double log2_peak_to_peak(const std::vector<double> &v, size_t from) {
  double lo = 1e300, hi = -1e300;
  for (size_t i = from; i < v.size(); ++i) {
    lo = std::fmin(lo, std::log2(v[i]));
    hi = std::fmax(hi, std::log2(v[i]));
  }
  return hi - lo;
}

void test_static_convergence(double alpha, const std::string &label) {
  ae_settings set;
  ae_default_settings(&set);
  set.min_exposure = 0.01;  // wide enough that the clamp does not decide the result
  set.max_exposure = 100.0;
  const Scene scene = make_scene(1.0);
  auto same = [&](int) -> const Scene & { return scene; };
  ae_state st;
  const auto scales = run_loop(same, 900, set, 1.0, alpha, &st);
  // Converged: over the last 150 frames (5 s) the scale moves by less than 0.1 %. At a fixed
  // point the sticky rule makes the target equal the current scale exactly, so the scale stops;
  // 0.1 % leaves room only for the chase's geometric approach to a non-sticky fixed point.
  const double p2p = log2_peak_to_peak(scales, scales.size() - 150);
  check(p2p < std::log2(1.001), "controller (" + label + "): converges on a static scene (last 5 s within 0.1 %)",
        fmt("peak-to-peak %g stops, final scale %g", p2p, scales.back()));
  // At the fixed point the exact full histogram of the tone-mapped frame asks for no change:
  // the 2 % point sits in the bucket holding 0.60 (sticky), or the minimum-average rule holds.
  ae_histogram full;
  ae_histogram_init(&full);
  const ae_window win = ae_center_window(scene.w, scene.h, 0.9, 0.85);
  for (int b = 0; b < AE_BUCKETS; ++b) {
    full.count[b] = ae_exact_count(scene.rgba.data(), scene.w, scene.h, win, 0, static_cast<float>(st.scale), b);
    full.measured_frame[b] = 0;
  }
  const double t = ae_target_scale(&full, &set, st.scale);
  check(std::fabs(t / st.scale - 1.0) < 0.001,
        "controller (" + label + "): the converged exposure meets its own target",
        fmt("target / scale = %g", t / st.scale));
  // Also from far away on both sides (16x too dark, 16x too bright). Tolerance: the sticky rule
  // accepts any exposure that puts the 2 % point in the bucket holding 0.60, [(11/16)^1.5,
  // (12/16)^1.5], a band log2((12/11)^1.5) = 0.19 stop wide, so the end points may differ by that.
  const double band = 1.5 * std::log2(12.0 / 11.0);
  const auto lo = run_loop(same, 1500, set, st.scale / 16, alpha);
  const auto hi = run_loop(same, 1500, set, st.scale * 16, alpha);
  check(std::fabs(std::log2(lo.back() / st.scale)) < band && std::fabs(std::log2(hi.back() / st.scale)) < band,
        "controller (" + label +
            "): reaches the same exposure from 4 stops below and above (within the 0.19-stop "
            "sticky band)",
        fmt("from below %g, from above %g, reference %g", lo.back(), hi.back(), st.scale));
}

// A light flickering by 2 stops with a period of 1 .. 12 frames (2.5 .. 30 Hz at 30 frames
// per second). Returns the worst peak-to-peak exposure (stops) after 20 s, and its period.
double worst_flicker(double alpha, int *worst_period) {
  ae_settings set;
  ae_default_settings(&set);
  set.min_exposure = 0.01;
  set.max_exposure = 100.0;
  const Scene dim = make_scene(1.0), bright = make_scene(4.0);
  double worst = 0;
  for (int period = 1; period <= 12; ++period) {
    const auto scales =
        run_loop([&](int f) -> const Scene & { return (f / period) % 2 ? bright : dim; }, 1500, set, 1.0, alpha);
    const double p2p = log2_peak_to_peak(scales, 600);
    if (p2p > worst) {
      worst = p2p;
      *worst_period = period;
    }
  }
  return worst;
}

void test_flicker() {
  int period = 0;
  const double w = worst_flicker(1.0 / 16, &period);
  // Tolerance: over the last 30 s the exposure must stay within 1/3 stop peak-to-peak (the
  // step of a camera's exposure dial, below which a slow drift is not seen as pumping)
  // while the scene swings by 2 stops: the controller passes on at most 1/6 of the flicker.
  check(w < 1.0 / 3,
        "controller (prefilter 1/16): no oscillation on a scene flickering 2 stops, any period of 1 to "
        "12 frames (< 1/3 stop peak-to-peak)",
        fmt("worst %g stops at a period of %g frames", w, period));
  // The same test on Source's histogram of the current frame (no prefilter) fails: sampling
  // each bucket once every 17 frames aliases a flicker near that period into a slow drift.
  int p1 = 0;
  const double w1 = worst_flicker(1.0, &p1);
  check(w1 > 2 * w && w1 > 0.5,
        "controller: the flicker check discriminates: without the prefilter the exposure drifts",
        fmt("worst %g stops at a period of %g frames", w1, p1));
  printf("# flicker: worst peak-to-peak %.3f stops (period %d) with the prefilter, %.3f (period %d) without\n", w,
         period, w1, p1);
}

void test_faster_down() {
  // The chase toward a goal 2 stops away, downward and upward.
  ae_settings set;
  ae_default_settings(&set);
  auto half_way = [&](double goal) {
    double scale = 1.0;
    for (int f = 1; f < 100000; ++f) {
      scale = ae_chase(scale, goal, &set, 1.0 / 30);
      if (std::fabs(std::log2(scale)) >= 1.0) return f;
    }
    return 100000;
  };
  const int down = half_way(0.25), up = half_way(4.0);
  // mat_accelerate_adjust_exposure_down 3: each frame covers 3x the fraction of the log distance
  // downward, so the half-way times are ln 2 / -ln(1 - k) for k = 1/30 and 1/10: 21 and 7 frames.
  check(down == 7 && up == 21,
        "controller: adapts 3x faster downward (half way in " + std::to_string(down) + " frames down, " +
            std::to_string(up) + " up, at 30 frames per second)");
}

void test_regions() {
  ae_settings def, out;
  ae_default_settings(&def);
  const ae_region regions[2] = {
      {{-10, -10, -10}, {0, 10, 10}, 1.0, 16.0, -1.0},  // a dark room: allow up to 16
      {{0, -10, -10}, {10, 10, 10}, 0.05, 1.0, 0.5},  // outdoors
  };
  const double in_room[3] = {-5, 0, 0}, outside[3] = {5, 0, 0}, nowhere[3] = {50, 0, 0};
  ae_settings_at(&def, regions, 2, in_room, &out);
  const bool room = out.min_exposure == 1.0 && out.max_exposure == 16.0 && out.bloom_scale == def.bloom_scale;
  ae_settings_at(&def, regions, 2, outside, &out);
  const bool outdoor = out.min_exposure == 0.05 && out.max_exposure == 1.0 && out.bloom_scale == 0.5;
  ae_settings_at(&def, regions, 2, nowhere, &out);
  const bool none = out.min_exposure == def.min_exposure && out.max_exposure == def.max_exposure;
  check(room && outdoor && none, "designer overrides: per-region exposure range and bloom scale, defaults elsewhere");
  // The clamp follows the region: a very bright target is held at the region's minimum.
  ae_histogram h = make_hist({{15, 10000}});
  ae_state st;
  ae_state_init(&st, 1.0, 0.0);
  ae_settings_at(&def, regions, 2, outside, &out);
  for (int i = 0; i < 600; ++i) ae_update(&st, &h, &out, 1.0 / 30);
  check(std::fabs(st.goal - 0.05) < 1e-12, "designer overrides: the goal is clamped to the region's range",
        fmt("goal %g", st.goal));
}

}  // namespace

int main() {
  ts_math_init();
  test_layout();
  test_window();
  test_schedule();
  test_location();
  test_min_avg_rule();
  test_static_convergence(1.0, "no prefilter");
  test_static_convergence(1.0 / 16, "prefilter 1/16");
  test_flicker();
  test_faster_down();
  test_regions();
  return g_failed ? 1 : 0;
}

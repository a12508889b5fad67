// tiershade hdr: auto exposure of a still frame (glue/hdr/still_frame_exposure.h).
#include "hdr/still_frame_exposure.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

#include "exposure/exposure_control.h"
#include "twins/luminance_compare.h"
#include "math/ts_math.h"

namespace {
const ts_vec3f kLumWeights = {0.2125f, 0.7154f, 0.0721f};  // common_hdr.glsl ts_luminance

// The twin's verdict for one pixel (used for pixels whose luminance is not finite).
bool twin_marks(const float *p, float lo, float hi, float scale) {
  const lc_variant v = {0};
  ts_vec4f rec[LC_SLOTS];
  rec[LC_SLOT_COLOR] = ts_v4f(p[0], p[1], p[2], p[3]);
  rec[LC_SLOT_RANGE] = ts_v4f(lo, hi, scale, 0.0f);
  return luminance_compare_f(&v, rec).x == 1.0f;
}
// Ascending order of finite floats by an LSD radix sort of their order-preserving keys (sign
// flipped for positives, all bits flipped for negatives), 3 passes of 11 bits; -0 sorts before
// +0, which compare equal, so the order is the same as std::sort's for every query here.
void radix_sort(std::vector<float> *v) {
  const size_t n = v->size();
  std::vector<uint32_t> a(n), b(n);
  for (size_t i = 0; i < n; ++i) {
    uint32_t u;
    std::memcpy(&u, &(*v)[i], 4);
    a[i] = (u & 0x80000000u) ? ~u : (u | 0x80000000u);
  }
  for (int pass = 0; pass < 3; ++pass) {
    const int shift = pass * 11;
    size_t count[2049] = {0};
    for (uint32_t k : a) ++count[((k >> shift) & 2047u) + 1];
    for (int i = 0; i < 2048; ++i) count[i + 1] += count[i];
    for (uint32_t k : a) b[count[(k >> shift) & 2047u]++] = k;
    a.swap(b);
  }
  for (size_t i = 0; i < n; ++i) {
    const uint32_t k = a[i];
    const uint32_t u = (k & 0x80000000u) ? (k & 0x7fffffffu) : ~k;
    std::memcpy(&(*v)[i], &u, 4);
  }
}

// The sorted finite luminances of rows ya..yb - 1 of the window (in *sorted) and the rgba of its
// pixels whose luminance is not finite (in *odd, row order).
void window_rows(const float *rgba, int w, const ae_window &win, int ya, int yb, std::vector<float> *sorted,
                 std::vector<float> *odd) {
  sorted->reserve(static_cast<size_t>(std::max(0, yb - ya)) * std::max(0, win.w));
  for (int y = ya; y < yb; ++y)
    for (int x = win.x0; x < win.x0 + win.w && x < w; ++x) {
      const float *p = rgba + (static_cast<size_t>(y) * w + x) * 4;
      const float l = ts_dot3f(ts_v3f(p[0], p[1], p[2]), kLumWeights);
      if (std::isfinite(l)) {
        sorted->push_back(l);
      } else {
        odd->insert(odd->end(), p, p + 4);
      }
    }
  radix_sort(sorted);
}

}  // namespace

StaticLuminance::StaticLuminance(const float *rgba, int w, int h, double wx, double wy) {
  const ae_window win = ae_center_window(w, h, wx, wy);
  const int y0 = win.y0, y1 = std::min(win.y0 + win.h, h);
  if (y1 - y0 < 64 || std::thread::hardware_concurrency() < 2) {
    window_rows(rgba, w, win, y0, y1, &sorted_, &odd_);
    return;
  }
  // The two halves of the rows on two threads, then merged by the radix sort's keys (the
  // ascending order of keys is unique: the same order as one sort of the whole window).
  const int mid = y0 + (y1 - y0) / 2;
  std::vector<float> lo, lo_odd, hi;
  std::thread t([&] { window_rows(rgba, w, win, y0, mid, &lo, &lo_odd); });
  window_rows(rgba, w, win, mid, y1, &hi, &odd_);
  t.join();
  odd_.insert(odd_.begin(), lo_odd.begin(), lo_odd.end());  // row order
  auto key = [](float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
  };
  sorted_.resize(lo.size() + hi.size());
  std::merge(lo.begin(), lo.end(), hi.begin(), hi.end(), sorted_.begin(), [&](float a, float b) { return key(a) < key(b); });
}

uint32_t StaticLuminance::count(int bucket, float scale) const {
  float lo, hi;
  ae_bucket_bounds(bucket, &lo, &hi);
  uint32_t n = 0;
  // in_bucket(lum) = step(lo, lum) * step(lum, hi): marked unless lum < lo or hi < lum.
  if (std::isfinite(scale) && scale >= 0.f) {
    // lum = l * scale is monotone in l: the marked pixels are one run of the sorted luminances.
    const auto first = std::partition_point(sorted_.begin(), sorted_.end(), [&](float l) { return l * scale < lo; });
    const auto last = std::partition_point(first, sorted_.end(), [&](float l) { return !(hi < l * scale); });
    n = static_cast<uint32_t>(last - first);
  } else {
    for (float l : sorted_) {
      const float lum = l * scale;
      if (!(lum < lo) && !(hi < lum)) ++n;
    }
  }
  for (size_t i = 0; i < odd_.size(); i += 4)
    if (twin_marks(&odd_[i], lo, hi, scale)) ++n;
  return n;
}

StaticExposure run_static_exposure(const StaticLuminance &lum, double initial_scale, double min_exposure,
                                   double max_exposure, int frames) {
  ae_settings s;
  ae_default_settings(&s);
  s.min_exposure = min_exposure;
  s.max_exposure = max_exposure;
  ae_state st;
  ae_state_init(&st, initial_scale, 0.0);
  ae_histogram hist;
  ae_histogram_init(&hist);
  uint32_t pending[AE_BUCKETS] = {0};
  for (int f = 0; f < frames; ++f) {
    // The schedule of LuminanceHistogramCpu::frame (glue/hdr/luminance_histogram_cpu.cpp), alpha 1.
    for (int b = 0; b < AE_BUCKETS; ++b)
      if (ae_may_read(&hist, b, f)) ae_store(&hist, b, pending[b]);
    const int b = ae_next_bucket(&hist);
    if (b >= 0) {
      pending[b] = lum.count(b, static_cast<float>(st.scale));
      ae_mark_issued(&hist, b, f);
    }
    ae_update(&st, &hist, &s, 1.0 / 30.0);
  }
  StaticExposure out;
  out.scale = st.scale;
  out.goal = st.goal;
  out.frames = frames;
  return out;
}

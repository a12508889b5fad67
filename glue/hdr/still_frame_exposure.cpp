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
// The order-preserving key of a float (sign flipped for positives, all bits flipped for
// negatives): keys ascend as the floats do, -0 just before +0 (which compare equal).
uint32_t order_key(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}
constexpr int kGroups = 1 << 16;  // groups by the key's top 16 bits: sign, exponent, 7 mantissa bits

// Rows ya..yb - 1 of the window: the finite luminances (in *lum, row order) and their group
// counts (in *hist, kGroups entries, added to), and the rgba of the pixels whose luminance is not
// finite (in *odd, row order).
void window_rows(const float *rgba, int w, const ae_window &win, int ya, int yb, std::vector<float> *lum,
                 std::vector<uint32_t> *hist, std::vector<float> *odd) {
  lum->clear();
  lum->reserve(static_cast<size_t>(std::max(0, yb - ya)) * std::max(0, win.w));
  hist->assign(kGroups, 0u);
  for (int y = ya; y < yb; ++y)
    for (int x = win.x0; x < win.x0 + win.w && x < w; ++x) {
      const float *p = rgba + (static_cast<size_t>(y) * w + x) * 4;
      const float l = ts_dot3f(ts_v3f(p[0], p[1], p[2]), kLumWeights);
      if (std::isfinite(l)) {
        lum->push_back(l);
        ++(*hist)[order_key(l) >> 16];
      } else {
        odd->insert(odd->end(), p, p + 4);
      }
    }
}

}  // namespace

StaticLuminance::StaticLuminance(const float *rgba, int w, int h, double wx, double wy) {
  const ae_window win = ae_center_window(w, h, wx, wy);
  const int y0 = win.y0, y1 = std::min(win.y0 + win.h, h);
  // The rows in two halves, on two threads when there are enough of them; each half keeps its
  // luminances in row order and its group counts.
  std::vector<float> lum[2], lo_odd;
  std::vector<uint32_t> hist[2];
  const bool two = y1 - y0 >= 64 && std::thread::hardware_concurrency() >= 2;
  const int mid = two ? y0 + (y1 - y0) / 2 : y1;
  {
    std::thread t;
    if (two) t = std::thread([&] { window_rows(rgba, w, win, y0, mid, &lum[0], &hist[0], &lo_odd); });
    window_rows(rgba, w, win, mid, y1, &lum[1], &hist[1], &odd_);
    if (!two) window_rows(rgba, w, win, y0, mid, &lum[0], &hist[0], &lo_odd);
    if (t.joinable()) t.join();
  }
  odd_.insert(odd_.begin(), lo_odd.begin(), lo_odd.end());  // row order
  // Counting placement: group g's elements at its start, half 0's first (any order within a
  // group serves count(): it only counts them).
  std::vector<uint32_t> at0(kGroups), at1(kGroups);
  uint32_t n = 0;
  for (int g = 0; g < kGroups; ++g) {
    const uint32_t c = hist[0][g] + hist[1][g];
    if (c == 0) continue;
    start_.push_back(n);
    at0[g] = n;
    at1[g] = n + hist[0][g];
    n += c;
  }
  start_.push_back(n);
  grouped_.resize(n);
  auto place = [&](const std::vector<float> &v, std::vector<uint32_t> &at) {
    for (float l : v) grouped_[at[order_key(l) >> 16]++] = l;
  };
  {
    std::thread t;
    if (two) t = std::thread([&] { place(lum[0], at0); });
    place(lum[1], at1);
    if (!two) place(lum[0], at0);
    if (t.joinable()) t.join();
  }
  const size_t groups = start_.size() - 1;
  lo_.resize(groups);
  hi_.resize(groups);
  for (size_t g = 0; g < groups; ++g) {
    uint32_t kl = 0xffffffffu, kh = 0;
    float fl = 0.f, fh = 0.f;
    for (uint32_t i = start_[g]; i < start_[g + 1]; ++i) {
      const uint32_t k = order_key(grouped_[i]);
      if (k < kl) kl = k, fl = grouped_[i];
      if (k >= kh) kh = k, fh = grouped_[i];
    }
    lo_[g] = fl;
    hi_[g] = fh;
  }
}

template <class Below>
size_t StaticLuminance::count_below(Below below) const {
  // The groups whose greatest element is below form a prefix (below is monotone); the next
  // group may hold both kinds.
  size_t a = 0, b = hi_.size();
  while (a < b) {
    const size_t m = a + (b - a) / 2;
    if (below(hi_[m]))
      a = m + 1;
    else
      b = m;
  }
  size_t n = start_[a];
  if (a < lo_.size() && below(lo_[a]))
    for (uint32_t i = start_[a]; i < start_[a + 1]; ++i) n += below(grouped_[i]) ? 1 : 0;
  return n;
}

uint32_t StaticLuminance::count(int bucket, float scale) const {
  float lo, hi;
  ae_bucket_bounds(bucket, &lo, &hi);
  uint32_t n = 0;
  // in_bucket(lum) = step(lo, lum) * step(lum, hi): marked unless lum < lo or hi < lum.
  if (std::isfinite(scale) && scale >= 0.f) {
    // lum = l * scale is monotone in l: the marked pixels are one run of the sorted luminances.
    const size_t first = count_below([&](float l) { return l * scale < lo; });
    const size_t last = count_below([&](float l) { return !(hi < l * scale); });
    n = static_cast<uint32_t>(last - first);
  } else {
    for (float l : grouped_) {
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

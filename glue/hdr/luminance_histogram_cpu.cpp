// tiershade hdr: the exact C twin of the running luminance histogram (see
// luminance_histogram.h): the GPU module's schedule, with every count taken from the
// luminance_compare twin and the prefilter from the luminance_smooth twin.
#include "math/hdr_formats.h"
#include "hdr/luminance_histogram.h"
#include "twins/luminance_smooth.h"

LuminanceHistogramCpu::LuminanceHistogramCpu(const HistogramConfig &c) : cfg_(c) {
  win_ = ae_center_window(c.w, c.h, c.window_x, c.window_y);
  ae_histogram_init(&hist_);
}

void LuminanceHistogramCpu::frame(const float *rgba, float tscale, int64_t frame,
                                  std::vector<HistogramMeasurement> *collected) {
  for (int b = 0; b < AE_BUCKETS; ++b) {
    if (!ae_may_read(&hist_, b, frame)) continue;
    if (collected) collected->push_back({b, hist_.pending_frame[b], pending_count_[b]});
    ae_store(&hist_, b, pending_count_[b]);
  }
  const float *measured = rgba;
  int encoding = cfg_.input_encoding;
  float measured_tscale = tscale;
  if (cfg_.alpha < 1.0) {
    // One smoothing pass over the window; the first frame starts the history (alpha 1).
    const bool first = history_.empty();
    if (first) history_.assign(static_cast<size_t>(cfg_.w) * cfg_.h * 4, 0.f);
    const ls_variant v = {cfg_.input_encoding};
    const float alpha = first ? 1.0f : static_cast<float>(cfg_.alpha);
    for (int y = win_.y0; y < win_.y0 + win_.h; ++y) {
      for (int x = win_.x0; x < win_.x0 + win_.w; ++x) {
        const size_t i = (static_cast<size_t>(y) * cfg_.w + x) * 4;
        ts_vec4f rec[LS_SLOTS];
        rec[LS_SLOT_COLOR] = ts_v4f(rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]);
        rec[LS_SLOT_HISTORY] = ts_v4f(history_[i], history_[i + 1], history_[i + 2], history_[i + 3]);
        rec[LS_SLOT_PARAMS] = ts_v4f(alpha, tscale, 0.f, 0.f);
        const ts_vec4f s = luminance_smooth_f(&v, rec);
        history_[i] = ts_quantize_half(s.x);
        history_[i + 1] = ts_quantize_half(s.y);
        history_[i + 2] = ts_quantize_half(s.z);
        history_[i + 3] = ts_quantize_half(s.w);
      }
    }
    measured = history_.data();
    encoding = 2;
    measured_tscale = 1.0f;
  }
  const int b = ae_next_bucket(&hist_);
  if (b < 0) return;
  pending_count_[b] = ae_exact_count(measured, cfg_.w, cfg_.h, win_, encoding, measured_tscale, b);
  ae_mark_issued(&hist_, b, frame);
}

/* tiershade exposure: the auto-exposure luminance histogram (see auto_exposure.h;
 * fact sheet section 8, "Histogram and bucket layout"). */
#include "exposure/auto_exposure.h"

#include <math.h>
#include <stddef.h>

#include "twins/luminance_compare.h"

void ae_bucket_bounds(int bucket, float *lo, float *hi) {
  if (bucket >= AE_ALL_PIXELS) {
    *lo = 0.0f;
    *hi = 100000.0f;
    return;
  }
  *lo = (float)pow(bucket / 16.0, 1.5);
  *hi = bucket == AE_RANGES - 1 ? 10000.0f : (float)pow((bucket + 1) / 16.0, 1.5);
}

void ae_bucket_span(int bucket, double *lo, double *hi) {
  *lo = pow(bucket / 16.0, 1.5);
  *hi = pow((bucket + 1) / 16.0, 1.5);
}

ae_window ae_center_window(int w, int h, double fx, double fy) {
  ae_window win;
  const int mx = (int)floor(w * (1.0 - fx) * 0.5 + 0.5);
  const int my = (int)floor(h * (1.0 - fy) * 0.5 + 0.5);
  win.x0 = mx;
  win.y0 = my;
  win.w = w - 2 * mx > 0 ? w - 2 * mx : 0;
  win.h = h - 2 * my > 0 ? h - 2 * my : 0;
  return win;
}

uint32_t ae_exact_count(const float *rgba, int w, int h, ae_window win, int input_encoding, float tscale, int bucket) {
  const lc_variant v = {input_encoding};
  float lo, hi;
  ae_bucket_bounds(bucket, &lo, &hi);
  uint32_t n = 0;
  for (int y = win.y0; y < win.y0 + win.h && y < h; ++y) {
    for (int x = win.x0; x < win.x0 + win.w && x < w; ++x) {
      const float *p = rgba + ((size_t)y * (size_t)w + (size_t)x) * 4;
      ts_vec4f rec[LC_SLOTS];
      rec[LC_SLOT_COLOR] = ts_v4f(p[0], p[1], p[2], p[3]);
      rec[LC_SLOT_RANGE] = ts_v4f(lo, hi, tscale, 0.0f);
      if (luminance_compare_f(&v, rec).x == 1.0f) ++n;
    }
  }
  return n;
}

void ae_histogram_init(ae_histogram *h) {
  for (int i = 0; i < AE_BUCKETS; ++i) {
    h->count[i] = 0;
    h->measured_frame[i] = -1;
    h->pending[i] = 0;
    h->pending_frame[i] = -1;
  }
}

int ae_next_bucket(const ae_histogram *h) {
  int best = -1;
  for (int i = 0; i < AE_BUCKETS; ++i) {
    if (h->pending[i]) continue;
    if (best < 0 || h->measured_frame[i] < h->measured_frame[best]) best = i;
  }
  return best;
}

void ae_mark_issued(ae_histogram *h, int bucket, int64_t frame) {
  h->pending[bucket] = 1;
  h->pending_frame[bucket] = frame;
}

int ae_may_read(const ae_histogram *h, int bucket, int64_t frame) {
  return h->pending[bucket] && frame - h->pending_frame[bucket] > AE_READ_DELAY;
}

void ae_store(ae_histogram *h, int bucket, uint32_t count) {
  h->count[bucket] = count;
  h->measured_frame[bucket] = h->pending_frame[bucket];
  h->pending[bucket] = 0;
}

int ae_histogram_complete(const ae_histogram *h) {
  for (int i = 0; i < AE_BUCKETS; ++i)
    if (h->measured_frame[i] < 0) return 0;
  return h->count[AE_ALL_PIXELS] > 0;
}

double ae_fraction(const ae_histogram *h, int bucket) {
  if (!ae_histogram_complete(h)) return 0.0;
  return (double)h->count[bucket] / (double)h->count[AE_ALL_PIXELS];
}

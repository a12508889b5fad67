/* tiershade exposure: the auto-exposure controller (see exposure_control.h;
 * fact sheet section 8, "Target exposure, new algorithm" and "Clamp and time-averaging"). */
#include "exposure/exposure_control.h"

#include <math.h>

void ae_default_settings(ae_settings *s) {
  s->percent_bright = 2.0;
  s->percent_target = 60.0;
  s->min_avg_lum = 3.0;
  s->min_exposure = 0.5;
  s->max_exposure = 2.0;
  s->adapt_rate = 1.0;
  s->accelerate_down = 3.0;
  s->bloom_scale = 1.0;
}

void ae_settings_at(const ae_settings *defaults, const ae_region *regions, int n, const double pos[3],
                    ae_settings *out) {
  *out = *defaults;
  for (int i = 0; i < n; ++i) {
    const ae_region *r = &regions[i];
    int inside = 1;
    for (int k = 0; k < 3; ++k)
      if (!(pos[k] >= r->lo[k] && pos[k] <= r->hi[k])) inside = 0;
    if (!inside) continue;
    *out = *defaults;
    if (r->min_exposure >= 0) out->min_exposure = r->min_exposure;
    if (r->max_exposure >= 0) out->max_exposure = r->max_exposure;
    if (r->bloom_scale >= 0) out->bloom_scale = r->bloom_scale;
  }
}

double ae_location_of_bright_fraction(const ae_histogram *h, double fraction, double sticky_target) {
  if (!ae_histogram_complete(h)) return -1.0;
  double acc = 0.0;
  for (int i = AE_RANGES - 1; i >= 0; --i) {
    const double f = ae_fraction(h, i);
    if (f > 0.0 && acc + f >= fraction) {
      double lo, hi;
      ae_bucket_span(i, &lo, &hi);
      if (sticky_target >= 0.0 && sticky_target >= lo && sticky_target <= hi) return sticky_target;
      const double t = (fraction - acc) / f;
      return hi - t * (hi - lo);
    }
    acc += f;
  }
  return -1.0;
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

double ae_target_scale(const ae_histogram *h, const ae_settings *s, double current_scale) {
  const double target = s->percent_target / 100.0;
  const double lp = ae_location_of_bright_fraction(h, s->percent_bright / 100.0, target);
  if (lp < 0.0) return current_scale;
  /* A histogram whose bright pixels sit at luminance 0 asks for "as bright as allowed":
   * the clamp to the maximum exposure follows. */
  double scalar = target / fmax(lp, 1e-6);
  const double l50 = ae_location_of_bright_fraction(h, 0.5, -1.0);
  if (l50 >= 0.0) {
    const double scalar2 = (s->min_avg_lum / 100.0) / fmax(l50, 1e-6);
    if (scalar2 > scalar) scalar = scalar2;
  }
  return fmax(scalar * current_scale, 0.001);
}

void ae_state_init(ae_state *st, double initial_scale, double initial_bloom_amount) {
  st->scale = initial_scale;
  st->goal = initial_scale;
  st->history_len = 0;
  for (int i = 0; i < AE_HISTORY; ++i) st->history[i] = 0.0;
  st->bloom_amount = initial_bloom_amount;
}

double ae_chase(double scale, double goal, const ae_settings *s, double dt) {
  const double k = clampd(s->adapt_rate * dt * (goal < scale ? s->accelerate_down : 1.0), 0.0, 1.0);
  return scale * pow(goal / scale, k);
}

void ae_update(ae_state *st, const ae_histogram *h, const ae_settings *s, double dt) {
  if (ae_histogram_complete(h)) {
    const double target = clampd(ae_target_scale(h, s, st->scale), s->min_exposure, s->max_exposure);
    /* The history is a shift register, index 0 the oldest. */
    if (st->history_len == AE_HISTORY) {
      for (int i = 1; i < AE_HISTORY; ++i) st->history[i - 1] = st->history[i];
      st->history[AE_HISTORY - 1] = target;
    } else {
      st->history[st->history_len++] = target;
    }
    double goal = target;
    if (st->history_len == AE_HISTORY) {
      double sum = 0.0, wsum = 0.0;
      for (int i = 0; i < AE_HISTORY; ++i) {
        const double w = fabs(i - 5.0) / 5.0;
        sum += w * st->history[i];
        wsum += w;
      }
      goal = sum / wsum;
    }
    st->goal = clampd(goal, s->min_exposure, s->max_exposure);
  } else {
    st->goal = clampd(st->scale, s->min_exposure, s->max_exposure);
  }
  st->scale = ae_chase(st->scale, st->goal, s, dt);
  st->bloom_amount = 0.05 * s->bloom_scale + 0.95 * st->bloom_amount;
}

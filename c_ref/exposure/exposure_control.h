/* tiershade exposure: source's auto-exposure controller, reading the running
 * luminance histogram of c_ref/exposure/auto_exposure.h (fact sheet section 8):
 *   - target (new algorithm): the luminance L_p below which the brightest 2 % of the
 *     pixels lie, interpolated inside its bucket; scale = 0.60 / L_p, "sticky" (no
 *     change) when 0.60 lies in that bucket; brighten to 0.03 / L_50 when that is larger
 *     (the minimum-average-luminance rule); times the current scale (the histogram
 *     measures the tone-mapped frame); floored at 0.001;
 *   - clamp to [min, max] exposure (0.5, 2.0 by default; designers override them per
 *     scene region, as env_tonemap_controller does);
 *   - time averaging over the last 10 targets with the weights |i - 5| / 5;
 *   - the per-frame chase toward the goal, faster downward: NOT IN the SDK (done by the
 *     material system); tiershade moves the scale by a fraction rate * dt of the way in
 *     log space, times 3 when the exposure goes down (mat_hdr_manual_tonemap_rate 1,
 *     mat_accelerate_adjust_exposure_down 3);
 *   - the bloom amount follows b <- 0.05 bloom_scale + 0.95 b per frame.
 * Double precision: this is CPU logic, identical in GL and C runs. */
#ifndef TS_EXPOSURE_CONTROL_H
#define TS_EXPOSURE_CONTROL_H
#include "exposure/auto_exposure.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { AE_HISTORY = 10 };

typedef struct {
  double percent_bright; /* mat_tonemap_percent_bright_pixels, 2.0 (%) */
  double percent_target; /* mat_tonemap_percent_target, 60 (%) */
  double min_avg_lum; /* mat_tonemap_min_avglum, 3.0 (%) */
  double min_exposure; /* mat_autoexposure_min, 0.5 */
  double max_exposure; /* mat_autoexposure_max, 2.0 */
  double adapt_rate; /* mat_hdr_manual_tonemap_rate, 1.0 per second */
  double accelerate_down; /* mat_accelerate_adjust_exposure_down, 3.0 */
  double bloom_scale; /* mat_bloomscale, 1.0 */
} ae_settings;

void ae_default_settings(ae_settings *s);

/* A designer override (env_tonemap_controller): inside the box, these replace the
 * defaults; a negative value keeps the default. The last region containing the camera wins. */
typedef struct {
  double lo[3], hi[3];
  double min_exposure, max_exposure, bloom_scale;
} ae_region;

void ae_settings_at(const ae_settings *defaults, const ae_region *regions, int n, const double pos[3],
                    ae_settings *out);

/* The luminance below which `fraction` of the pixels lie, counted from the bright end
 * and interpolated linearly inside its bucket; when sticky_target >= 0 lies inside that
 * bucket, sticky_target itself. -1 when the histogram is incomplete or holds too few pixels. */
double ae_location_of_bright_fraction(const ae_histogram *h, double fraction, double sticky_target);

/* The new algorithm's target tone-map scale (before clamping and averaging), or
 * current_scale when the histogram cannot say. */
double ae_target_scale(const ae_histogram *h, const ae_settings *s, double current_scale);

typedef struct {
  double scale; /* the tone-map scale in use */
  double goal; /* the averaged, clamped goal */
  double history[AE_HISTORY];
  int history_len;
  double bloom_amount;
} ae_state;

void ae_state_init(ae_state *st, double initial_scale, double initial_bloom_amount);
/* The chase: one frame (dt seconds) of the scale's approach to the goal, in log space,
 * a fraction adapt_rate * dt of the way (times accelerate_down when going down, at most all). */
double ae_chase(double scale, double goal, const ae_settings *s, double dt);
/* One frame: target from the histogram, clamp, history average, chase over dt seconds. */
void ae_update(ae_state *st, const ae_histogram *h, const ae_settings *s, double dt);

#ifdef __cplusplus
}
#endif
#endif

/* tiershade exposure: the luminance histogram of Source's auto exposure
 * (talk: "Auto Exposure": a running luminance histogram of the tone-mapped frame,
 * one bucket updated per frame, more buckets at low luminance; fact sheet section 8):
 *   - the 17-bucket layout: bucket i < 16 covers [(i/16)^1.5, ((i+1)/16)^1.5], the top
 *     bound 1.0 widened to 10000; bucket 16 is [0, 100000], every pixel, used to
 *     normalise the counts;
 *   - the centred window the histogram is measured over (0.9 x 0.85 of the viewport);
 *   - the exact counts of a frame, with the luminance_compare twin per pixel;
 *   - the running histogram: which bucket to measure next (the oldest first, one per
 *     frame) and when a measurement may be read (more than 2 frames after it was queued).
 * The exposure controller that reads the histogram is c_ref/exposure/exposure_control.h. */
#ifndef TS_AUTO_EXPOSURE_H
#define TS_AUTO_EXPOSURE_H
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { AE_BUCKETS = 17, AE_RANGES = 16, AE_ALL_PIXELS = 16, AE_READ_DELAY = 2 };

/* The bounds the bucket test uses (fact sheet section 8). Bucket 15's top is 10000. */
void ae_bucket_bounds(int bucket, float *lo, float *hi);
/* The bounds the controller interpolates in: as above, but bucket 15 ends at 1.0. */
void ae_bucket_span(int bucket, double *lo, double *hi);

typedef struct {
  int x0, y0, w, h; /* pixels, y0 from the bottom row (glScissor / glReadPixels order) */
} ae_window;
/* Centred window covering fx x fy of a w x h viewport (Source: 0.9 x 0.85), rounded to
 * whole pixels: a margin of round(w (1 - fx) / 2) columns on each side, same for rows. */
ae_window ae_center_window(int w, int h, double fx, double fy);

/* Pixels of the window that luminance_compare (INPUT_ENCODING = input_encoding, tone-map
 * scale tscale) marks for `bucket`. rgba: 4 floats per pixel, rows bottom-up, w per row:
 * the texel values the shader reads. */
uint32_t ae_exact_count(const float *rgba, int w, int h, ae_window win, int input_encoding, float tscale, int bucket);

/* The running histogram: the last known count of each bucket and the frame it counted. */
typedef struct {
  uint32_t count[AE_BUCKETS];
  int64_t measured_frame[AE_BUCKETS]; /* -1: never measured */
  int pending[AE_BUCKETS]; /* a measurement is in flight */
  int64_t pending_frame[AE_BUCKETS]; /* the frame it measures */
} ae_histogram;

void ae_histogram_init(ae_histogram *h);
/* The bucket to measure in frame `frame`: not in flight, oldest measurement first (never
 * measured counts as oldest), lowest index on ties; -1 if every bucket is in flight. */
int ae_next_bucket(const ae_histogram *h);
void ae_mark_issued(ae_histogram *h, int bucket, int64_t frame);
/* A measurement queued in frame q may be read in frame f when f - q > AE_READ_DELAY. */
int ae_may_read(const ae_histogram *h, int bucket, int64_t frame);
void ae_store(ae_histogram *h, int bucket, uint32_t count);
/* Every bucket measured at least once, and a non-zero all-pixel count. */
int ae_histogram_complete(const ae_histogram *h);
/* count[bucket] / count[AE_ALL_PIXELS] (0 when the histogram is not complete). */
double ae_fraction(const ae_histogram *h, int bucket);

#ifdef __cplusplus
}
#endif
#endif

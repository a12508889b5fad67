// tiershade hdr: the running luminance histogram of the auto exposure, measured
// one bucket per frame (talk: "Auto Exposure"; fact sheet section 8), on the GPU and
// by its exact C twin.
//
// Each frame: (1) collect the measurements queued more than 2 frames ago; (2) when the
// temporal prefilter is on (alpha < 1), update the smoothed luminance image
// (luminance_smooth.fs); (3) mark the pixels of the window in the range of the next
// bucket (luminance_compare.fs: discard outside) and count them:
//   - GL 3.3: an asynchronous GL_SAMPLES_PASSED occlusion query, read when available;
//   - GLES 3.0: its occlusion queries are boolean (GL_ANY_SAMPLES_PASSED; GL_SAMPLES_PASSED
//     is GL_INVALID_ENUM, checked on Mesa), so the marked window is read into a
//     pixel-pack buffer with a fence, and counted on the CPU once the fence has signalled;
//   - GLES 2.0: no queries, buffers or fences: the marked window is read back at once
//     (a synchronous readback, the one stall of this module) and counted on the CPU.
// The count is used on the same schedule on every API, so that the histogram (and the
// exposure that follows it) is the same everywhere. Each frame ends with a glFlush (what
// a swap does), so a measurement is normally complete long before it is read; a result
// that is not, 3 frames later, is waited for (and counted in late_reads()) rather than
// skipped, which keeps the schedule deterministic.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "exposure/auto_exposure.h"
#include "hdr/gl_passes.h"
#include "base/noncopyable.h"

struct HistogramMeasurement {
  int bucket;
  int64_t frame;  // the frame whose pixels were counted
  uint32_t count;
};

struct HistogramConfig {
  int w = 0, h = 0;  // the measured frame
  int input_encoding = 0;  // 0 linear HDR x tone-map scale (float path), 1 sRGB-encoded RGBA8 (integer path)
  double alpha = 0.0625;  // temporal prefilter weight of the new frame (docs/hdr.md); 1 = none, as Source
  double window_x = 0.9, window_y = 0.85;  // the centred window (mat_exposure_center_region_x/_y)
};

// The exact C twin: the same schedule, counts from the luminance_compare twin, and the
// prefilter from the luminance_smooth twin with fp16 storage.
class LuminanceHistogramCpu {
 public:
  explicit LuminanceHistogramCpu(const HistogramConfig &c);
  // rgba: the frame's texel values (4 floats per pixel, rows bottom-up); tscale: the tone-map
  // scale of the float path (1 for the integer path). Appends the measurements read this frame.
  void frame(const float *rgba, float tscale, int64_t frame, std::vector<HistogramMeasurement> *collected);
  const ae_histogram &histogram() const { return hist_; }
  const ae_window &window() const { return win_; }

 private:
  HistogramConfig cfg_;
  ae_window win_;
  ae_histogram hist_;
  uint32_t pending_count_[AE_BUCKETS] = {0};
  std::vector<float> history_;  // the smoothed luminance image (fp16 values), rgba
};

class LuminanceHistogramGl : NonCopyable {
 public:
  LuminanceHistogramGl(PassRunner &runner, Backend backend, Api api, const HistogramConfig &c);
  ~LuminanceHistogramGl();
  bool init(std::string *err);
  // frame_tex: the frame just rendered (w x h), sampled with texelFetch (NEAREST on GLES 2.0).
  bool frame(GLuint frame_tex, float tscale, int64_t frame, std::vector<HistogramMeasurement> *collected,
             std::string *err);
  const ae_histogram &histogram() const { return hist_; }
  const char *method() const;
  // Reads that found their result not yet available and had to wait (0 means no stall).
  int late_reads() const { return late_reads_; }

 private:
  enum class Method { Query, PixelPack, SyncRead };
  bool collect(int64_t frame, std::vector<HistogramMeasurement> *collected, std::string *err);
  bool measure(GLuint source_tex, float tscale, int bucket, std::string *err);
  uint32_t count_marked(const uint8_t *rgba, size_t pixels) const;

  PassRunner &run_;
  Backend backend_;
  Api api_;
  HistogramConfig cfg_;
  Method method_ = Method::Query;
  ae_window win_{};
  ae_histogram hist_{};
  GlTarget mask_, smooth_[2];
  int smooth_cur_ = 0;  // index of the latest smoothed image
  bool first_done_ = false;  // the first frame starts the smoothed image (alpha 1)
  GLuint compare_prog_ = 0, smooth_prog_ = 0;
  GlSyncFns sync_;
  GLuint queries_[AE_BUCKETS] = {0};
  GLuint pbos_[AE_BUCKETS] = {0};
  GLsync fences_[AE_BUCKETS] = {nullptr};
  uint32_t sync_counts_[AE_BUCKETS] = {0};
  int late_reads_ = 0;
};

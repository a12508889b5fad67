// tiershade hdr: the GPU running luminance histogram (see luminance_histogram.h):
// one bucket per frame, marked by luminance_compare.fs and counted by an occlusion
// query (GL 3.3), a fenced pixel-pack-buffer readback (GLES 3.0) or a synchronous
// readback (GLES 2.0).
#include <cstring>

#include "base/enum_names.h"
#include "gl/errors.h"
#include "hdr/luminance_histogram.h"

LuminanceHistogramGl::LuminanceHistogramGl(PassRunner &runner, Backend backend, Api api, const HistogramConfig &c)
    : run_(runner), backend_(backend), api_(api), cfg_(c) {
  method_ = api == Api::GL33 ? Method::Query : api == Api::GLES3 ? Method::PixelPack : Method::SyncRead;
  win_ = ae_center_window(c.w, c.h, c.window_x, c.window_y);
  ae_histogram_init(&hist_);
}

LuminanceHistogramGl::~LuminanceHistogramGl() {
  const GlFns &g = run_.gl();
  free_target(g, &mask_);
  free_target(g, &smooth_[0]);
  free_target(g, &smooth_[1]);
  for (int b = 0; b < AE_BUCKETS; ++b) {
    if (queries_[b]) g.DeleteQueries(1, &queries_[b]);
    if (pbos_[b]) g.DeleteBuffers(1, &pbos_[b]);
    if (fences_[b]) sync_.DeleteSync(fences_[b]);
  }
}

const char *LuminanceHistogramGl::method() const {
  static const EnumName<Method> kMethodNames[] = {
      {Method::Query, "asynchronous occlusion query (GL_SAMPLES_PASSED)"},
      {Method::PixelPack, "fenced pixel-pack-buffer readback, counted on the CPU"},
      {Method::SyncRead, "synchronous readback, counted on the CPU"}};
  return enum_name(kMethodNames, method_);
}

bool LuminanceHistogramGl::init(std::string *err) {
  const GlFns &g = run_.gl();
  const bool smooth = cfg_.alpha < 1.0;
  const std::string tier = api_ == Api::GLES2 ? "ps20" : "sm3";
  const int encoding = smooth ? 2 : cfg_.input_encoding;
  compare_prog_ = run_.program(api_, "luminance_compare", tier + ":INPUT_ENCODING=" + std::to_string(encoding), err);
  if (!compare_prog_) return false;
  if (smooth) {
    smooth_prog_ =
        run_.program(api_, "luminance_smooth", tier + ":INPUT_ENCODING=" + std::to_string(cfg_.input_encoding), err);
    if (!smooth_prog_) return false;
    if (!make_target(g, TargetFormat::RGBA16F, cfg_.w, cfg_.h, &smooth_[0], err) ||
        !make_target(g, TargetFormat::RGBA16F, cfg_.w, cfg_.h, &smooth_[1], err))
      return false;
    // The history starts at 0, as in the C twin: the first frame (alpha 1) then gives
    // 0 + 1 * (L - 0) = L exactly.
    for (GlTarget *t : {&smooth_[0], &smooth_[1]}) {
      g.BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
      g.ClearColor(0, 0, 0, 0);
      g.Clear(GL_COLOR_BUFFER_BIT);
    }
  }
  if (!make_target(g, TargetFormat::RGBA8, cfg_.w, cfg_.h, &mask_, err)) return false;
  if (method_ == Method::Query) {
    g.GenQueries(AE_BUCKETS, queries_);
  } else if (method_ == Method::PixelPack) {
    if (!load_sync_fns(backend_, &sync_, err)) return false;
    g.GenBuffers(AE_BUCKETS, pbos_);
    for (int b = 0; b < AE_BUCKETS; ++b) {
      g.BindBuffer(GL_PIXEL_PACK_BUFFER, pbos_[b]);
      g.BufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(win_.w) * win_.h * 4, nullptr, GL_STREAM_READ);
    }
    g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  }
  return gl_no_error(g, "setting up the luminance histogram", err);
}

uint32_t LuminanceHistogramGl::count_marked(const uint8_t *rgba, size_t pixels) const {
  uint32_t n = 0;
  for (size_t i = 0; i < pixels; ++i) n += rgba[i * 4] != 0;
  return n;
}

bool LuminanceHistogramGl::collect(int64_t frame, std::vector<HistogramMeasurement> *collected, std::string *err) {
  const GlFns &g = run_.gl();
  for (int b = 0; b < AE_BUCKETS; ++b) {
    if (!ae_may_read(&hist_, b, frame)) continue;
    uint32_t count = 0;
    if (method_ == Method::Query) {
      GLuint avail = 0;
      g.GetQueryObjectuiv(queries_[b], GL_QUERY_RESULT_AVAILABLE, &avail);
      if (!avail) ++late_reads_;  // GL_QUERY_RESULT below waits for it
      g.GetQueryObjectuiv(queries_[b], GL_QUERY_RESULT, &count);
    } else if (method_ == Method::PixelPack) {
      GLint status = 0;
      sync_.GetSynciv(fences_[b], GL_SYNC_STATUS, 1, nullptr, &status);
      if (status != GL_SIGNALED) {
        ++late_reads_;
        if (sync_.ClientWaitSync(fences_[b], GL_SYNC_FLUSH_COMMANDS_BIT, 10000000000ull) == GL_WAIT_FAILED) {
          *err = "glClientWaitSync failed on the histogram's fence";
          return false;
        }
      }
      sync_.DeleteSync(fences_[b]);
      fences_[b] = nullptr;
      const size_t pixels = static_cast<size_t>(win_.w) * win_.h;
      g.BindBuffer(GL_PIXEL_PACK_BUFFER, pbos_[b]);
      const void *p =
          sync_.MapBufferRange(GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(pixels * 4), GL_MAP_READ_BIT);
      if (!p) {
        g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        *err = "glMapBufferRange of the histogram's pixel-pack buffer failed";
        return false;
      }
      count = count_marked(static_cast<const uint8_t *>(p), pixels);
      sync_.UnmapBuffer(GL_PIXEL_PACK_BUFFER);
      g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    } else {
      count = sync_counts_[b];
    }
    if (collected) collected->push_back({b, hist_.pending_frame[b], count});
    ae_store(&hist_, b, count);
  }
  return true;
}

bool LuminanceHistogramGl::measure(GLuint source_tex, float tscale, int bucket, std::string *err) {
  const GlFns &g = run_.gl();
  float lo, hi;
  ae_bucket_bounds(bucket, &lo, &hi);
  const float range[4] = {lo, hi, tscale, 0.f};
  const float size[4] = {static_cast<float>(cfg_.w), static_cast<float>(cfg_.h), 1.0f / static_cast<float>(cfg_.w),
                         1.0f / static_cast<float>(cfg_.h)};
  run_.set_vec4(compare_prog_, "u_range", range);
  run_.set_vec4(compare_prog_, "u_frame_size", size);
  if (method_ != Method::Query) {
    // The readback routes count the marked window: clear it first (discarded pixels keep 0).
    g.BindFramebuffer(GL_FRAMEBUFFER, mask_.fbo);
    g.Enable(GL_SCISSOR_TEST);
    g.Scissor(win_.x0, win_.y0, win_.w, win_.h);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    g.Disable(GL_SCISSOR_TEST);
  }
  if (method_ == Method::Query) g.BeginQuery(GL_SAMPLES_PASSED, queries_[bucket]);
  const bool ok = run_.draw(compare_prog_, mask_, {{"u_frame", source_tex, false}}, &win_, err);
  if (method_ == Method::Query) g.EndQuery(GL_SAMPLES_PASSED);
  if (!ok) return false;
  g.BindFramebuffer(GL_FRAMEBUFFER, mask_.fbo);
  g.PixelStorei(GL_PACK_ALIGNMENT, 4);
  if (method_ == Method::PixelPack) {
    g.BindBuffer(GL_PIXEL_PACK_BUFFER, pbos_[bucket]);
    g.ReadPixels(win_.x0, win_.y0, win_.w, win_.h, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (fences_[bucket]) sync_.DeleteSync(fences_[bucket]);
    fences_[bucket] = sync_.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    g.Flush();
  } else if (method_ == Method::SyncRead) {
    std::vector<uint8_t> px(static_cast<size_t>(win_.w) * win_.h * 4);
    g.ReadPixels(win_.x0, win_.y0, win_.w, win_.h, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    sync_counts_[bucket] = count_marked(px.data(), static_cast<size_t>(win_.w) * win_.h);
  }
  return gl_no_error(g, "measuring histogram bucket " + std::to_string(bucket), err);
}

bool LuminanceHistogramGl::frame(GLuint frame_tex, float tscale, int64_t frame,
                                 std::vector<HistogramMeasurement> *collected, std::string *err) {
  if (!collect(frame, collected, err)) return false;
  GLuint source = frame_tex;
  float measured_tscale = tscale;
  if (cfg_.alpha < 1.0) {
    const int next = 1 - smooth_cur_;
    const float params[4] = {first_done_ ? static_cast<float>(cfg_.alpha) : 1.0f, tscale, 0.f, 0.f};
    const float size[4] = {static_cast<float>(cfg_.w), static_cast<float>(cfg_.h), 1.0f / static_cast<float>(cfg_.w),
                           1.0f / static_cast<float>(cfg_.h)};
    run_.set_vec4(smooth_prog_, "u_params", params);
    run_.set_vec4(smooth_prog_, "u_frame_size", size);
    if (!run_.draw(smooth_prog_, smooth_[next],
                   {{"u_frame", frame_tex, false}, {"u_history", smooth_[smooth_cur_].tex, false}}, &win_, err))
      return false;
    smooth_cur_ = next;
    first_done_ = true;
    source = smooth_[smooth_cur_].tex;
    measured_tscale = 1.0f;
  }
  const int b = ae_next_bucket(&hist_);
  if (b < 0) return true;
  if (!measure(source, measured_tscale, b, err)) return false;
  ae_mark_issued(&hist_, b, frame);
  run_.gl().Flush();  // the end of the frame, as a swap would submit it
  return true;
}

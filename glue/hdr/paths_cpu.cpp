// tiershade hdr: the C twins of the integer and float HDR paths, and the double
// reference of the float path (see hdr_pipeline.h). Each pass shades a row at a time with the
// records the GL pass would read: the fragment position (pixel centre) per pixel, the sizes
// and parameters the GL glue passes as uniforms shared by the row. The float path runs the
// batch twins (c_ref/twins/hdr_post_batch.h: 8 or 4 pixels per SIMD call, the scalar twins' bits);
// the double reference calls its twins per pixel.
#include <cstring>

#include "twins/bloom_blur.h"
#include "twins/bloom_downsample.h"
#include "math/hdr_formats.h"
#include "hdr/paths.h"
#include "twins/hdr_post_batch.h"
#include "twins/hdr_tonemap.h"
#include "twins/model_lighting.h"
#include "base/parallel_rows.h"

namespace {

ts_vec4f size_of(int w, int h) {
  return ts_v4f(static_cast<float>(w), static_cast<float>(h), 1.0f / static_cast<float>(w),
                1.0f / static_cast<float>(h));
}

ts_tex2d tex_of(const std::vector<float> &rgba, int w, int h, bool linear) {
  ts_tex2d t;
  t.w = w;
  t.h = h;
  t.texels = rgba.data();
  t.wrap_s = t.wrap_t = TS_WRAP_CLAMP;
  t.filter = linear ? TS_FILTER_LINEAR : TS_FILTER_NEAREST;
  return t;
}

ts_vec4f centre(int x, int y) { return ts_v4f(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, 0.f, 0.f); }

// Pixel centres of row y, x = 0..w-1.
void centres(int y, int w, std::vector<ts_vec4f> *pos) {
  pos->resize(static_cast<size_t>(w));
  for (int x = 0; x < w; ++x) (*pos)[x] = centre(x, y);
}

// A row of results into an RGBA float image at pixel i: fp16-quantised (GL) or as is (reference).
void store_row(std::vector<float> *img, size_t i, const std::vector<ts_vec4f> &row, bool half) {
  const float *src = &row[0].x;
  float *dst = img->data() + i * 4;
  if (half)
    ts_quantize_half_batch(src, dst, row.size() * 4);
  else
    std::memcpy(dst, src, row.size() * sizeof(ts_vec4f));
}

// The three bloom passes of the float path; `half`: store in fp16 (GL) or float32 (reference).
// down(pos, rec, count, tex, out) and blur(dir, pos, rec, count, tex, out) shade `count` pixels
// of a row: pos[i] is pixel i's centre, rec the slots shared by the row (its position slot unused).
// ds, bx: the intermediate images (kept by the caller across frames; every texel is written).
template <class Down, class Blur>
void bloom_chain(const std::vector<float> &hdr, int w, int h, Down down, Blur blur, bool half, std::vector<float> *out,
                 std::vector<float> &ds, std::vector<float> &bx, int *bw_out, int *bh_out, int threads = 1) {
  const int bw = hdr_bloom_size(w), bh = hdr_bloom_size(h);
  const size_t n = static_cast<size_t>(bw) * bh;
  ds.resize(n * 4);
  bx.resize(n * 4);
  out->resize(n * 4);
  const ts_tex2d src = tex_of(hdr, w, h, true);
  const ts_vec4f drec[BD_SLOTS] = {ts_v4f(0.f, 0.f, 0.f, 0.f), size_of(w, h), ts_v4f(0.3f, 0.59f, 0.11f, 2.2f)};
  const ts_vec4f brec[BB_SLOTS] = {ts_v4f(0.f, 0.f, 0.f, 0.f), size_of(bw, bh), ts_v4f(1.f, 0.f, 0.f, 0.f)};
  // One bw x bh pass into dst: shade(pos, row) shades a row from its pixel centres.
  auto pass = [&](std::vector<float> *dst, const auto &shade) {
    parallel_rows(bh, threads, [&](int y) {
      std::vector<ts_vec4f> pos, row(static_cast<size_t>(bw));
      centres(y, bw, &pos);
      shade(pos.data(), row.data());
      store_row(dst, static_cast<size_t>(y) * bw, row, half);
    });
  };
  pass(&ds, [&](const ts_vec4f *pos, ts_vec4f *row) { down(pos, drec, bw, &src, row); });
  const ts_tex2d tds = tex_of(ds, bw, bh, true);
  pass(&bx, [&](const ts_vec4f *pos, ts_vec4f *row) { blur(0, pos, brec, bw, &tds, row); });
  const ts_tex2d tbx = tex_of(bx, bw, bh, true);
  pass(out, [&](const ts_vec4f *pos, ts_vec4f *row) { blur(1, pos, brec, bw, &tbx, row); });
  *bw_out = bw;
  *bh_out = bh;
}

}  // namespace

void hdr_integer_frame_c(const ShaderFamily &lit, const Variant &v, const FamilyInputs &scene, float tone_map_scale,
                         HdrFrameC *out) {
  FamilyInputs in = scene;
  in.shared.at(ML_SLOT_PARAMS).x = tone_map_scale;
  ImageF img;
  cpu_render_frame(lit, v, in, &img);
  out->w = scene.w;
  out->h = scene.h;
  out->bw = out->bh = 0;
  out->hdr.clear();
  out->bloom.clear();
  out->display.resize(img.rgba.size());
  for (size_t i = 0; i < img.rgba.size(); ++i) out->display[i] = ts_unorm8_from_float(img.rgba[i]);
}

void hdr_float_frame_c(const ShaderFamily &lit, const Variant &v, const FamilyInputs &scene, const HdrSettings &s,
                       HdrFrameC *out) {
  FamilyInputs in = scene;
  in.shared.at(ML_SLOT_PARAMS).x = 1.f;
  ImageF img;
  cpu_render_frame(lit, v, in, &img);
  std::vector<float> hdr(img.rgba.size());
  for (size_t i = 0; i < img.rgba.size(); ++i) hdr[i] = ts_quantize_half(img.rgba[i]);
  hdr_post_float_c(hdr, scene.w, scene.h, s, out);
}

void hdr_post_float_c(const std::vector<float> &hdr, int w, int h, const HdrSettings &s, HdrFrameC *out, int threads,
                      bool keep_hdr) {
  out->w = w;
  out->h = h;
  if (keep_hdr)
    out->hdr = hdr;
  else
    out->hdr.clear();
  const bd_variant dv = {0};
  const bb_variant bxv = {0}, byv = {1};
  if (s.bloom_amount != 0.f) {
    bloom_chain(
        hdr, w, h,
        [&](const ts_vec4f *pos, const ts_vec4f *rec, int count, const ts_tex2d *t, ts_vec4f *o) {
          const bd_batch_input in = {{pos, &rec[BD_SLOT_SIZE], &rec[BD_SLOT_SHAPE]}, {1, 0, 0}};
          bloom_downsample_f_batch(&dv, &in, t, o, count);
        },
        [&](int dir, const ts_vec4f *pos, const ts_vec4f *rec, int count, const ts_tex2d *t, ts_vec4f *o) {
          const bb_batch_input in = {{pos, &rec[BB_SLOT_SIZE], &rec[BB_SLOT_PARAMS]}, {1, 0, 0}};
          bloom_blur_f_batch(dir ? &byv : &bxv, &in, t, o, count);
        },
        true, &out->bloom, out->bloom_down, out->bloom_x, &out->bw, &out->bh, threads);
  } else {  // no bloom asked for: the passes are skipped, the combine reads black (as on GL)
    out->bw = hdr_bloom_size(w);
    out->bh = hdr_bloom_size(h);
    out->bloom.assign(static_cast<size_t>(out->bw) * out->bh * 4, 0.f);
  }
  const ts_tex2d bloom = tex_of(out->bloom, out->bw, out->bh, true);
  const ht_variant tv = {2};
  out->display.resize(static_cast<size_t>(w) * h * 4);
  const ts_vec4f size = size_of(w, h), params = ts_v4f(s.tone_map_scale, s.bloom_amount, s.bloom_exponent, 0.f);
  // Per worker: the row's centres and results (kept across rows); the frame's row is read in place.
  // Each worker keeps the two bloom rows its last row read, filtered horizontally (hdr_tonemap_f_row).
  const size_t workers = static_cast<size_t>(parallel_workers(h, threads));
  std::vector<std::vector<ts_vec4f>> pos_of(workers), row_of(workers);
  std::vector<std::vector<float>> hrows(workers * 2, std::vector<float>(static_cast<size_t>(w) * 3));
  std::vector<ht_bloom_rows> cache(workers);
  for (size_t t = 0; t < workers; ++t) cache[t] = {{-1, -1}, {hrows[2 * t].data(), hrows[2 * t + 1].data()}, w};
  parallel_rows_by_worker(h, threads, [&](int t, int y) {
    const size_t i = static_cast<size_t>(y) * w;
    std::vector<ts_vec4f> &pos = pos_of[static_cast<size_t>(t)], &row = row_of[static_cast<size_t>(t)];
    centres(y, w, &pos);
    row.resize(static_cast<size_t>(w));
    const ts_vec4f *fb = reinterpret_cast<const ts_vec4f *>(&hdr[i * 4]);  // 4 floats a pixel
    const ht_batch_input in = {{pos.data(), fb, &size, &params}, {1, 1, 0, 0}};
    hdr_tonemap_f_row(&tv, &in, &bloom, &cache[static_cast<size_t>(t)], row.data(), w);
    ts_unorm8_from_float_batch(&row[0].x, &out->display[i * 4], row.size() * 4);
  });
}

void hdr_float_frame_reference(const ShaderFamily &lit, const Variant &v_linear, const FamilyInputs &scene,
                               const HdrSettings &s, std::vector<double> *display) {
  FamilyInputs in = scene;
  in.shared.at(ML_SLOT_PARAMS).x = 1.f;
  std::vector<double> lin;
  cpu_render_frame_double(lit, v_linear, in, &lin);
  const int w = scene.w, h = scene.h;
  std::vector<float> hdr(lin.size());
  for (size_t i = 0; i < lin.size(); ++i) hdr[i] = static_cast<float>(lin[i]);
  const bd_variant dv = {0};
  const bb_variant bxv = {0}, byv = {1};
  auto to_f = [](ts_vec4d c) {
    return ts_v4f(static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z), static_cast<float>(c.w));
  };
  std::vector<float> bloom, ds, bx;
  int bw = 0, bh = 0;
  bloom_chain(
      hdr, w, h,
      [&](const ts_vec4f *pos, const ts_vec4f *rec, int count, const ts_tex2d *t, ts_vec4f *o) {
        for (int x = 0; x < count; ++x) {
          const ts_vec4f r[BD_SLOTS] = {pos[x], rec[BD_SLOT_SIZE], rec[BD_SLOT_SHAPE]};
          o[x] = to_f(bloom_downsample_d(&dv, r, t));
        }
      },
      [&](int dir, const ts_vec4f *pos, const ts_vec4f *rec, int count, const ts_tex2d *t, ts_vec4f *o) {
        for (int x = 0; x < count; ++x) {
          const ts_vec4f r[BB_SLOTS] = {pos[x], rec[BB_SLOT_SIZE], rec[BB_SLOT_PARAMS]};
          o[x] = to_f(bloom_blur_d(dir ? &byv : &bxv, r, t));
        }
      },
      false, &bloom, ds, bx, &bw, &bh);
  const ts_tex2d tb = tex_of(bloom, bw, bh, true);
  const ht_variant tv = {2};
  display->assign(static_cast<size_t>(w) * h * 4, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const float *fb = &hdr[i * 4];
      const ts_vec4f rec[HT_SLOTS] = {centre(x, y), ts_v4f(fb[0], fb[1], fb[2], fb[3]), size_of(w, h),
                                      ts_v4f(s.tone_map_scale, s.bloom_amount, s.bloom_exponent, 0.f)};
      const ts_vec4d c = hdr_tonemap_d(&tv, rec, &tb);
      (*display)[i * 4 + 0] = c.x;
      (*display)[i * 4 + 1] = c.y;
      (*display)[i * 4 + 2] = c.z;
      (*display)[i * 4 + 3] = c.w;
    }
}

// tiershade glue: the C twins of the integer and float HDR paths, and the double
// reference of the float path (see hdr_pipeline.h). Each pass calls its family's twin
// per pixel with the record the GL pass would read: the fragment position (pixel
// centre), the sizes and parameters the GL glue passes as uniforms.
#include "bloom_blur.h"
#include "bloom_downsample.h"
#include "hdr_formats.h"
#include "hdr_pipeline.h"
#include "hdr_tonemap.h"
#include "model_lighting.h"
#include "parallel_rows.h"

namespace {

ts_vec4f size_of(int w, int h) {
  return ts_v4f(static_cast<float>(w), static_cast<float>(h), 1.0f / static_cast<float>(w), 1.0f / static_cast<float>(h));
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

void store(std::vector<float> *img, size_t i, ts_vec4f c, bool half) {
  const float v[4] = {c.x, c.y, c.z, c.w};
  for (int k = 0; k < 4; ++k) (*img)[i * 4 + k] = half ? ts_quantize_half(v[k]) : v[k];
}

// The three bloom passes of the float path; `half`: store in fp16 (GL) or float32 (reference).
template <class Down, class Blur>
void bloom_chain(const std::vector<float> &hdr, int w, int h, Down down, Blur blur, bool half, std::vector<float> *out,
                 int *bw_out, int *bh_out, int threads = 1) {
  const int bw = hdr_bloom_size(w), bh = hdr_bloom_size(h);
  const size_t n = static_cast<size_t>(bw) * bh;
  std::vector<float> ds(n * 4), bx(n * 4);
  out->assign(n * 4, 0.f);
  const ts_tex2d src = tex_of(hdr, w, h, true);
  scene_parallel_rows(bh, threads, [&](int y) {
    for (int x = 0; x < bw; ++x) {
      const ts_vec4f rec[BD_SLOTS] = {centre(x, y), size_of(w, h), ts_v4f(0.3f, 0.59f, 0.11f, 2.2f)};
      store(&ds, static_cast<size_t>(y) * bw + x, down(rec, &src), half);
    }
  });
  const ts_tex2d tds = tex_of(ds, bw, bh, true);
  scene_parallel_rows(bh, threads, [&](int y) {
    for (int x = 0; x < bw; ++x) {
      const ts_vec4f rec[BB_SLOTS] = {centre(x, y), size_of(bw, bh), ts_v4f(1.f, 0.f, 0.f, 0.f)};
      store(&bx, static_cast<size_t>(y) * bw + x, blur(0, rec, &tds), half);
    }
  });
  const ts_tex2d tbx = tex_of(bx, bw, bh, true);
  scene_parallel_rows(bh, threads, [&](int y) {
    for (int x = 0; x < bw; ++x) {
      const ts_vec4f rec[BB_SLOTS] = {centre(x, y), size_of(bw, bh), ts_v4f(1.f, 0.f, 0.f, 0.f)};
      store(out, static_cast<size_t>(y) * bw + x, blur(1, rec, &tbx), half);
    }
  });
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

void hdr_post_float_c(const std::vector<float> &hdr, int w, int h, const HdrSettings &s, HdrFrameC *out,
                      int threads) {
  out->w = w;
  out->h = h;
  out->hdr = hdr;
  const bd_variant dv = {0};
  const bb_variant bxv = {0}, byv = {1};
  bloom_chain(
      out->hdr, w, h, [&](const ts_vec4f *rec, const ts_tex2d *t) { return bloom_downsample_f(&dv, rec, t); },
      [&](int dir, const ts_vec4f *rec, const ts_tex2d *t) { return bloom_blur_f(dir ? &byv : &bxv, rec, t); }, true,
      &out->bloom, &out->bw, &out->bh, threads);
  const ts_tex2d bloom = tex_of(out->bloom, out->bw, out->bh, true);
  const ht_variant tv = {2};
  out->display.resize(static_cast<size_t>(w) * h * 4);
  scene_parallel_rows(h, threads, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const float *fb = &out->hdr[i * 4];
      const ts_vec4f rec[HT_SLOTS] = {centre(x, y), ts_v4f(fb[0], fb[1], fb[2], fb[3]), size_of(w, h),
                                      ts_v4f(s.tone_map_scale, s.bloom_amount, s.bloom_exponent, 0.f)};
      const ts_vec4f c = hdr_tonemap_f(&tv, rec, &bloom);
      out->display[i * 4 + 0] = ts_unorm8_from_float(c.x);
      out->display[i * 4 + 1] = ts_unorm8_from_float(c.y);
      out->display[i * 4 + 2] = ts_unorm8_from_float(c.z);
      out->display[i * 4 + 3] = ts_unorm8_from_float(c.w);
    }
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
  std::vector<float> bloom;
  int bw = 0, bh = 0;
  bloom_chain(
      hdr, w, h, [&](const ts_vec4f *rec, const ts_tex2d *t) { return to_f(bloom_downsample_d(&dv, rec, t)); },
      [&](int dir, const ts_vec4f *rec, const ts_tex2d *t) { return to_f(bloom_blur_d(dir ? &byv : &bxv, rec, t)); },
      false, &bloom, &bw, &bh);
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

// tiershade tests: the post-processing fast path against the scalar twins, bit for bit (no tolerance, NaN not
// excepted):
//   * c_ref/twins/hdr_post_batch.c: bloom_downsample (SHAPE 0/1), bloom_blur (DIRECTION 0/1),
//     hdr_tonemap (OUTPUT_MODE 0/1/2) against bloom_downsample_f / bloom_blur_f / hdr_tonemap_f;
//     ts_quantize_half_batch and ts_unorm8_from_float_batch against hdr_formats.c on every
//     sign/exponent/top-11-mantissa-bit pattern (2 random low parts each) and the specials;
//   * c_ref/twins/color_correction_batch.c: all 20 color_correction variants (LUT_ATLAS 0/1,
//     SHADER_TRILINEAR 0/1, NUM_LOOKUPS 0..4) against color_correction_f, on a 3D LUT and its
//     atlas (CLAMP, REPEAT POT and NPOT, NEAREST);
//   * hdr_tonemap_f_row (the tone map a row at a time, bloom rows kept across rows) against
//     hdr_tonemap_f per pixel, rows in three orders;
//   * the glue: hdr_post_float_c and cc_apply_rgba8_c on each instruction set against the
//     same calls with the scalar twins forced (ts_batch_force_isa(TS_BATCH_SCALAR)).
// Records are random with hard values mixed in (NaN, +-Inf, 65504 and beyond, 1e30, float
// denormals, negative colours, coordinates off the texture edges), textures too; each family
// runs on whole records (stride = slot count) and on the renderer's layout (pixel slots
// stride 1, the rest shared, stride 0), in chunks of 1..13 pixels (every tail length). Each
// instruction set the host has (AVX2, SSE2) in each fused-mad mode it can run (fused only
// with FMA, as llvmpipe). The test also shows it can fail: the fused fast path against the
// unfused scalar twin differs on the blur's lerps.
//
// Usage: build/tests/test_fast_path_post   Prints PASS/FAIL lines and "N passed, N failed";
// exit 1 on failure.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "color/correct_rgba8_cpu.h"
#include "twins/color_correction_batch.h"
#include "math/hdr_formats.h"
#include "hdr/paths.h"
#include "twins/hdr_post_batch.h"
#include "unit_check.h"
#include "unit_vec4.h"

namespace {

struct PostRng {
  uint64_t s;
  explicit PostRng(uint64_t seed) : s(seed * 0x9E3779B97F4A7C15ull + 1) {}
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return static_cast<uint32_t>(s >> 11);
  }
  float uni(float lo, float hi) { return lo + (hi - lo) * static_cast<float>(next() % 1000000u) / 1000000.f; }
  bool chance(int percent) { return static_cast<int>(next() % 100u) < percent; }
};

// Hard values: NaN of both signs and payloads, infinities, the fp16 edge, huge, denormals.
float hard(PostRng &r) {
  static const float k[] = {0.f,           -0.f,
                            1.f,           -1.f,
                            0.5f,          65504.f,
                            65520.f,       70000.f,
                            1e30f,         -1e30f,
                            3e38f,         1e-40f,
                            -1e-40f,       1.17549435e-38f,
                            5.9604645e-8f, 2.9802322e-8f,
                            1e-8f,         0.0031308f,
                            0.04045f,      1.f - 5.9604645e-8f,
                            2.f,           255.f};
  const uint32_t n = sizeof k / sizeof k[0] + 4;
  const uint32_t i = r.next() % n;
  if (i < sizeof k / sizeof k[0]) return k[i];
  switch (i - sizeof k / sizeof k[0]) {
    case 0:
      return std::numeric_limits<float>::quiet_NaN();
    case 1:
      return float_of_bits(0xffc01234u);
    case 2:
      return std::numeric_limits<float>::infinity();
    default:
      return -std::numeric_limits<float>::infinity();
  }
}

float maybe_hard(PostRng &r, float v, int percent) { return r.chance(percent) ? hard(r) : v; }

struct Tex2 {
  std::vector<float> texels;
  ts_tex2d t;
  Tex2(PostRng &r, int w, int h, int wrap, int filter, int hard_percent, float hi)
      : texels(static_cast<size_t>(w) * h * 4) {
    for (float &v : texels) v = maybe_hard(r, r.uni(0.f, hi), hard_percent);
    t.w = w;
    t.h = h;
    t.texels = texels.data();
    t.wrap_s = t.wrap_t = wrap;
    t.filter = filter;
  }
};

struct Isa {
  int level;
  const char *name;
};
const Isa kIsas[2] = {{TS_BATCH_AVX2, "avx2"}, {TS_BATCH_SSE2, "sse2"}};

bool have_isa(int level) {
  ts_batch_force_isa(level);
  const bool ok = ts_batch_isa() == level;
  ts_batch_force_isa(-1);
  return ok;
}

// A batch family: slots S, the first P per pixel. In: {slot[S], stride[S]}.
// scalar(rec) -> ts_vec4f; batch(const In *, out, count).
template <class In, int S, class Scalar, class Batch>
void run_family(const std::string &name, int pixel_slots, const std::vector<ts_vec4f> &recs, Scalar scalar, Batch batch,
                const char *mode) {
  const int total = static_cast<int>(recs.size() / S);
  for (int layout = 0; layout < 2; ++layout) {
    std::vector<ts_vec4f> want(static_cast<size_t>(total));
    for (int i = 0; i < total; ++i) {
      ts_vec4f rec[S];
      for (int k = 0; k < S; ++k) rec[k] = recs[static_cast<size_t>(layout && k >= pixel_slots ? 0 : i) * S + k];
      want[i] = scalar(rec);
    }
    for (const Isa &isa : kIsas) {
      if (!have_isa(isa.level)) continue;
      ts_batch_force_isa(isa.level);
      std::vector<ts_vec4f> got(static_cast<size_t>(total), ts_v4f(7.f, 7.f, 7.f, 7.f));
      for (int first = 0, c = 1; first < total; first += c, c = c % 13 + 1) {
        In in;
        for (int k = 0; k < S; ++k) {
          const bool shared = layout && k >= pixel_slots;
          in.slot[k] = &recs[(shared ? 0 : static_cast<size_t>(first) * S) + k];
          in.stride[k] = shared ? 0 : S;
        }
        batch(&in, &got[first], std::min(c, total - first));
      }
      ts_batch_force_isa(-1);
      long bad = 0;
      std::string first_bad;
      for (int i = 0; i < total; ++i)
        if (!same_bits(got[i], want[i]) && bad++ == 0)
          first_bad = "pixel " + std::to_string(i) + ": fast " + show(got[i]) + ", scalar " + show(want[i]);
      check(bad == 0,
            name + " " + isa.name + " " + mode + (layout ? " shared slots" : " records") + ": batch = scalar (" +
                std::to_string(total) + " pixels)",
            std::to_string(bad) + " differ; first " + first_bad);
    }
  }
}

void set_size(std::vector<ts_vec4f> *recs, int slots, int slot, int w, int h, PostRng &r, int hard_percent);

// Bloom/tone-map records: positions around and beyond the tw x th target, the other slots random
// but for slot `size_slot`: the source size sw x sh (set_size: some of its reciprocals hard).
std::vector<ts_vec4f> post_records(PostRng &r, int n, int slots, int tw, int th, int size_slot, int sw, int sh,
                                   int hard_percent) {
  std::vector<ts_vec4f> recs(static_cast<size_t>(n) * slots);
  for (int i = 0; i < n; ++i) {
    ts_vec4f *rec = &recs[static_cast<size_t>(i) * slots];
    const float px = std::floor(r.uni(-3.f, tw + 3.f)) + (r.chance(70) ? 0.5f : r.uni(0.f, 1.f));
    const float py = std::floor(r.uni(-3.f, th + 3.f)) + (r.chance(70) ? 0.5f : r.uni(0.f, 1.f));
    rec[0] = ts_v4f(maybe_hard(r, px, hard_percent), maybe_hard(r, py, hard_percent), 0.f, 0.f);
    for (int k = 1; k < slots; ++k)
      rec[k] = ts_v4f(maybe_hard(r, r.uni(-0.5f, 3.f), hard_percent), maybe_hard(r, r.uni(0.f, 2.f), hard_percent),
                      maybe_hard(r, r.uni(0.f, 4.f), hard_percent), maybe_hard(r, r.uni(0.f, 3.f), hard_percent));
  }
  set_size(&recs, slots, size_slot, sw, sh, r, hard_percent);
  return recs;
}

void set_size(std::vector<ts_vec4f> *recs, int slots, int slot, int w, int h, PostRng &r, int hard_percent) {
  for (size_t i = 0; i < recs->size() / slots; ++i) {
    ts_vec4f &s = (*recs)[i * slots + slot];
    s = ts_v4f(static_cast<float>(w), static_cast<float>(h), 1.f / static_cast<float>(w), 1.f / static_cast<float>(h));
    if (r.chance(hard_percent)) s.z = hard(r);
    if (r.chance(hard_percent)) s.w = hard(r);
  }
}

// run_family for each value 0..values-1 of a family's one combo (variant V{value}); scalar and
// batch take the variant first.
template <class In, int S, class V, class Scalar, class Batch>
void run_combo(const std::string &combo, int values, const std::string &sfx, int pixel_slots,
               const std::vector<ts_vec4f> &recs, Scalar scalar, Batch batch, const char *mode) {
  for (int value = 0; value < values; ++value) {
    const V v = {value};
    run_family<In, S>(
        combo + "=" + std::to_string(value) + sfx, pixel_slots, recs,
        [&](const ts_vec4f *rec) { return scalar(&v, rec); },
        [&](const In *in, ts_vec4f *o, int c) { batch(&v, in, o, c); }, mode);
  }
}

void test_hdr_families(const char *mode) {
  PostRng r(99);
  const int n = 601;
  struct TexCase {
    const char *name;
    int w, h, wrap, filter, hard;
  };
  const TexCase cases[] = {{"37x23 clamp", 37, 23, TS_WRAP_CLAMP, TS_FILTER_LINEAR, 0},
                           {"37x23 clamp hard texels", 37, 23, TS_WRAP_CLAMP, TS_FILTER_LINEAR, 6},
                           {"32x16 repeat", 32, 16, TS_WRAP_REPEAT, TS_FILTER_LINEAR, 3},
                           {"13x9 repeat", 13, 9, TS_WRAP_REPEAT, TS_FILTER_LINEAR, 3},
                           {"11x7 nearest", 11, 7, TS_WRAP_CLAMP, TS_FILTER_NEAREST, 3}};
  for (const TexCase &tc : cases) {
    const Tex2 tex(r, tc.w, tc.h, tc.wrap, tc.filter, tc.hard, 6.f);
    const ts_tex2d *t = &tex.t;
    for (int hp : {0, 8}) {
      const std::string sfx = std::string(" [") + tc.name + (hp ? ", hard records]" : "]");
      // bloom_downsample: a quarter-size target of the texture
      run_combo<bd_batch_input, BD_SLOTS, bd_variant>(
          "bloom_downsample SHAPE", 2, sfx, BD_PIXEL_SLOTS,
          post_records(r, n, BD_SLOTS, (tc.w + 3) / 4, (tc.h + 3) / 4, BD_SLOT_SIZE, tc.w, tc.h, hp),
          [&](const bd_variant *v, const ts_vec4f *rec) { return bloom_downsample_f(v, rec, t); },
          [&](const bd_variant *v, const bd_batch_input *in, ts_vec4f *o, int c) {
            bloom_downsample_f_batch(v, in, t, o, c);
          },
          mode);
      // bloom_blur: a target of the texture's size
      run_combo<bb_batch_input, BB_SLOTS, bb_variant>(
          "bloom_blur DIRECTION", 2, sfx, BB_PIXEL_SLOTS,
          post_records(r, n, BB_SLOTS, tc.w, tc.h, BB_SLOT_SIZE, tc.w, tc.h, hp),
          [&](const bb_variant *v, const ts_vec4f *rec) { return bloom_blur_f(v, rec, t); },
          [&](const bb_variant *v, const bb_batch_input *in, ts_vec4f *o, int c) {
            bloom_blur_f_batch(v, in, t, o, c);
          },
          mode);
      // hdr_tonemap: a full-size target over the (quarter-size) bloom texture
      std::vector<ts_vec4f> rt = post_records(r, n, HT_SLOTS, tc.w * 4, tc.h * 4, HT_SLOT_SIZE, tc.w * 4, tc.h * 4, hp);
      for (int i = 0; i < n; ++i) {  // the frame: HDR colours
        ts_vec4f &f = rt[static_cast<size_t>(i) * HT_SLOTS + HT_SLOT_FRAME];
        f = ts_v4f(maybe_hard(r, r.uni(0.f, 20.f), hp + 2), maybe_hard(r, r.uni(0.f, 2.f), hp + 2),
                   maybe_hard(r, r.uni(0.f, 0.01f), hp + 2), 1.f);
      }
      run_combo<ht_batch_input, HT_SLOTS, ht_variant>(
          "hdr_tonemap OUTPUT_MODE", 3, sfx, HT_PIXEL_SLOTS, rt,
          [&](const ht_variant *v, const ts_vec4f *rec) { return hdr_tonemap_f(v, rec, t); },
          [&](const ht_variant *v, const ht_batch_input *in, ts_vec4f *o, int c) {
            hdr_tonemap_f_batch(v, in, t, o, c);
          },
          mode);
    }
  }
}

// hdr_tonemap_f_row (the glue's tone map: one frame row at a time, the horizontally filtered
// bloom rows kept across rows) against the scalar twin per pixel, in three row orders (top down,
// two interleaved workers' order, bottom up) so rows are reused, replaced and refetched; bloom
// textures of a quarter of the frame (clamp and repeat, hard texels), every output mode.
void test_tonemap_rows(const char *mode) {
  PostRng r(17);
  struct TexCase {
    const char *name;
    int w, h, wrap, hard;
  };
  const TexCase cases[] = {{"21x12 clamp", 21, 12, TS_WRAP_CLAMP, 0},
                           {"21x12 clamp hard texels", 21, 12, TS_WRAP_CLAMP, 6},
                           {"16x8 repeat", 16, 8, TS_WRAP_REPEAT, 3}};
  for (const TexCase &tc : cases) {
    const Tex2 tex(r, tc.w, tc.h, tc.wrap, TS_FILTER_LINEAR, tc.hard, 6.f);
    const int w = tc.w * 4 + 3, h = tc.h * 4 + 2;
    std::vector<ts_vec4f> frame(static_cast<size_t>(w) * h);
    for (ts_vec4f &f : frame)
      f = ts_v4f(maybe_hard(r, r.uni(0.f, 20.f), 3), maybe_hard(r, r.uni(0.f, 2.f), 3),
                 maybe_hard(r, r.uni(0.f, 0.01f), 3), 1.f);
    const ts_vec4f size = ts_v4f(static_cast<float>(w), static_cast<float>(h), 1.f / static_cast<float>(w),
                                 1.f / static_cast<float>(h));
    const ts_vec4f params = ts_v4f(0.8f, 0.6f, 1.7f, 0.f);
    std::vector<int> orders[3];
    for (int y = 0; y < h; ++y) orders[0].push_back(y);
    for (int y = 0; y < h; y += 2) orders[1].push_back(y);
    for (int y = 1; y < h; y += 2) orders[1].push_back(y);
    for (int y = h - 1; y >= 0; --y) orders[2].push_back(y);
    for (int om = 0; om < 3; ++om) {
      const ht_variant v = {om};
      for (int o = 0; o < 3; ++o) {
        std::vector<float> rgb0(static_cast<size_t>(w) * 3), rgb1(rgb0.size());
        ht_bloom_rows rows = {{-1, -1}, {rgb0.data(), rgb1.data()}, w};
        std::vector<ts_vec4f> pos(static_cast<size_t>(w)), got(static_cast<size_t>(w));
        long differ = 0;
        for (int y : orders[o]) {
          for (int x = 0; x < w; ++x) pos[static_cast<size_t>(x)] = ts_v4f(x + 0.5f, y + 0.5f, 0.f, 0.f);
          const ht_batch_input in = {{pos.data(), &frame[static_cast<size_t>(y) * w], &size, &params}, {1, 1, 0, 0}};
          hdr_tonemap_f_row(&v, &in, &tex.t, &rows, got.data(), w);
          for (int x = 0; x < w; ++x) {
            const ts_vec4f rec[HT_SLOTS] = {pos[static_cast<size_t>(x)], frame[static_cast<size_t>(y) * w + x], size,
                                            params};
            differ += !same_bits(got[static_cast<size_t>(x)], hdr_tonemap_f(&v, rec, &tex.t));
          }
        }
        check(differ == 0,
              std::string("hdr_tonemap_f_row OUTPUT_MODE=") + std::to_string(om) + " order " + std::to_string(o) +
                  " [" + tc.name + "] " + mode + " = scalar twin",
              std::to_string(differ) + " pixels differ");
      }
    }
  }
}

// color_correction on a random n^3 LUT (3D and atlas views of the same values).
struct Luts {
  std::vector<std::vector<float>> vol, atlas;
  cc_luts views;
  Luts(PostRng &r, int n, int wrap, int filter, int hard_percent) : vol(CC_MAX_LOOKUPS), atlas(CC_MAX_LOOKUPS) {
    for (int i = 0; i < CC_MAX_LOOKUPS; ++i) {
      vol[i].resize(static_cast<size_t>(n) * n * n * 4);
      for (float &v : vol[i]) v = maybe_hard(r, r.uni(-0.1f, 1.2f), hard_percent);
      atlas[i].resize(vol[i].size());
      for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
          for (int rr = 0; rr < n; ++rr)
            std::memcpy(&atlas[i][(static_cast<size_t>(g) * n * n + static_cast<size_t>(b) * n + rr) * 4],
                        &vol[i][((static_cast<size_t>(b) * n + g) * n + rr) * 4], 16);
      ts_tex3d &v3 = views.volume[i];
      v3.w = v3.h = v3.d = n;
      v3.texels = vol[i].data();
      v3.wrap_s = v3.wrap_t = v3.wrap_r = wrap;
      v3.filter = filter;
      ts_tex2d &a = views.atlas[i];
      a.w = n * n;
      a.h = n;
      a.texels = atlas[i].data();
      a.wrap_s = a.wrap_t = wrap;
      a.filter = filter;
    }
  }
};

void test_color_correction(const char *mode) {
  PostRng r(7);
  struct LutCase {
    const char *name;
    int n, wrap, filter, hard;
  };
  const LutCase cases[] = {{"n=17 clamp", 17, TS_WRAP_CLAMP, TS_FILTER_LINEAR, 0},
                           {"n=6 clamp hard texels", 6, TS_WRAP_CLAMP, TS_FILTER_LINEAR, 5},
                           {"n=8 repeat", 8, TS_WRAP_REPEAT, TS_FILTER_LINEAR, 2},
                           {"n=5 repeat", 5, TS_WRAP_REPEAT, TS_FILTER_LINEAR, 2},
                           {"n=5 nearest", 5, TS_WRAP_CLAMP, TS_FILTER_NEAREST, 2}};
  const int total = 389;
  for (const LutCase &lc : cases) {
    const Luts luts(r, lc.n, lc.wrap, lc.filter, lc.hard);
    for (int hp : {0, 8}) {
      std::vector<ts_vec4f> recs(static_cast<size_t>(total) * CC_SLOTS);
      for (int i = 0; i < total; ++i) {
        ts_vec4f *rec = &recs[static_cast<size_t>(i) * CC_SLOTS];
        // colours: RGBA8 texels mostly, the rest anywhere in [-0.5, 1.5], some hard
        const bool code = r.chance(60);
        float c[4];
        for (float &x : c)
          x = maybe_hard(r, code ? ts_unorm8_to_float(static_cast<uint8_t>(r.next())) : r.uni(-0.5f, 1.5f), hp);
        rec[CC_SLOT_COLOR] = ts_v4f(c[0], c[1], c[2], c[3]);
        rec[CC_SLOT_WEIGHTS] = ts_v4f(maybe_hard(r, r.uni(0.f, 1.f), hp), maybe_hard(r, r.uni(0.f, 1.f), hp),
                                      maybe_hard(r, r.uni(0.f, 1.f), hp), maybe_hard(r, r.uni(0.f, 1.f), hp));
        rec[CC_SLOT_PARAMS] = ts_v4f(maybe_hard(r, r.uni(0.f, 1.f), hp), 0.f, 0.f, 0.f);
        ts_vec4f lut = cc_lut_params(lc.n);
        if (r.chance(hp)) lut.x = hard(r);
        if (r.chance(hp)) lut.y = hard(r);
        if (r.chance(hp)) lut.z = hard(r);
        if (r.chance(hp)) lut.w = hard(r);
        rec[CC_SLOT_LUT] = lut;
      }
      for (int atlas = 0; atlas < 2; ++atlas)
        for (int tri = 0; tri < 2; ++tri)
          for (int num = 0; num <= CC_MAX_LOOKUPS; ++num) {
            const cc_variant v = {atlas, tri, num};
            char name[160];
            snprintf(name, sizeof name, "color_correction LUT_ATLAS=%d SHADER_TRILINEAR=%d NUM_LOOKUPS=%d [%s%s]",
                     atlas, tri, num, lc.name, hp ? ", hard records" : "");
            run_family<cc_batch_input, CC_SLOTS>(
                name, CC_PIXEL_SLOTS, recs,
                [&](const ts_vec4f *rec) { return color_correction_f(&v, rec, &luts.views); },
                [&](const cc_batch_input *in, ts_vec4f *o, int c) {
                  color_correction_f_batch(&v, in, &luts.views, o, c);
                },
                mode);
          }
    }
  }
}

// The storage conversions on every sign/exponent/top-11-mantissa pattern, 2 random low parts.
void test_formats(const char *mode) {
  PostRng r(3);
  std::vector<float> in;
  in.reserve((1u << 21) + 64);
  for (uint32_t hi = 0; hi < (1u << 20); ++hi)
    for (int k = 0; k < 2; ++k) in.push_back(float_of_bits((hi << 12) | (r.next() & 0xfffu)));
  for (int k = 0; k < 61; ++k) in.push_back(hard(r));  // an odd tail
  std::vector<float> hq(in.size()), hq_want(in.size());
  std::vector<uint8_t> u8(in.size()), u8_want(in.size());
  for (size_t i = 0; i < in.size(); ++i) {
    hq_want[i] = ts_quantize_half(in[i]);
    u8_want[i] = ts_unorm8_from_float(in[i]);
  }
  for (const Isa &isa : kIsas) {
    if (!have_isa(isa.level)) continue;
    ts_batch_force_isa(isa.level);
    // chunks of 977 * (1..13) values: every tail length of the 8- and 4-lane loops
    for (size_t first = 0, c = 1, m = 0; first < in.size(); first += m, c = c % 13 + 1) {
      m = std::min(c * 977, in.size() - first);
      ts_quantize_half_batch(&in[first], &hq[first], m);
      ts_unorm8_from_float_batch(&in[first], &u8[first], m);
    }
    ts_batch_force_isa(-1);
    long bad_h = 0, bad_u = 0;
    std::string fh, fu;
    for (size_t i = 0; i < in.size(); ++i) {
      if (std::memcmp(&hq[i], &hq_want[i], 4) && bad_h++ == 0) {
        char b[120];
        uint32_t u;
        std::memcpy(&u, &in[i], 4);
        snprintf(b, sizeof b, "in %a (0x%08x): fast %a, scalar %a", in[i], u, hq[i], hq_want[i]);
        fh = b;
      }
      if (u8[i] != u8_want[i] && bad_u++ == 0) {
        char b[120];
        snprintf(b, sizeof b, "in %a: fast %d, scalar %d", in[i], u8[i], u8_want[i]);
        fu = b;
      }
    }
    const std::string cfg = std::string(isa.name) + " " + mode;
    check(bad_h == 0, "ts_quantize_half_batch " + cfg + " (" + std::to_string(in.size()) + " values)",
          std::to_string(bad_h) + " differ; first " + fh);
    check(bad_u == 0, "ts_unorm8_from_float_batch " + cfg + " (" + std::to_string(in.size()) + " values)",
          std::to_string(bad_u) + " differ; first " + fu);
  }
}

// The glue: the renderer's post chain on each instruction set against the scalar twins.
void test_glue(const char *mode) {
  PostRng r(11);
  const int w = 83, h = 45;
  std::vector<float> hdr(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < hdr.size(); ++i)
    hdr[i] = ts_quantize_half(i % 4 == 3 ? 1.f : maybe_hard(r, r.uni(0.f, 8.f) * r.uni(0.f, 1.f), 2));
  HdrSettings s;
  s.tone_map_scale = 0.7f;
  const Luts luts(r, 9, TS_WRAP_CLAMP, TS_FILTER_LINEAR, 0);
  const ts_vec4f shared[CC_SLOTS] = {ts_v4f(0, 0, 0, 1), ts_v4f(0.4f, 0.35f, 0.1f, 0.05f), ts_v4f(0.1f, 0, 0, 0),
                                     cc_lut_params(9)};
  auto run = [&](HdrFrameC *f, std::vector<uint8_t> *cc3, std::vector<uint8_t> *cca) {
    hdr_post_float_c(hdr, w, h, s, f, 2);
    *cc3 = *cca = f->display;
    cc_apply_rgba8_c(cc_variant{0, 0, 4}, shared, luts.views, w, h, cc3, 2);
    cc_apply_rgba8_c(cc_variant{1, 0, 2}, shared, luts.views, w, h, cca, 2);
  };
  HdrFrameC want;
  std::vector<uint8_t> want3, wanta;
  ts_batch_force_isa(TS_BATCH_SCALAR);
  run(&want, &want3, &wanta);
  for (const Isa &isa : kIsas) {
    if (!have_isa(isa.level)) continue;
    ts_batch_force_isa(isa.level);
    HdrFrameC got;
    std::vector<uint8_t> got3, gota;
    run(&got, &got3, &gota);
    const std::string cfg = std::string(isa.name) + " " + mode;
    check(got.bloom.size() == want.bloom.size() &&
              std::memcmp(got.bloom.data(), want.bloom.data(), want.bloom.size() * 4) == 0,
          "hdr_post_float_c " + cfg + ": bloom = scalar twins' bloom");
    check(got.display == want.display, "hdr_post_float_c " + cfg + ": display = scalar twins' display");
    check(got3 == want3 && gota == wanta, "cc_apply_rgba8_c " + cfg + ": 3D (4 LUTs) and atlas (2 LUTs) = scalar twin");
  }
  ts_batch_force_isa(-1);
}

}  // namespace

int main() {
  ts_math_init();
  const bool host_fma = ts_math_fused() != 0;
  std::vector<int> fused_modes = {0};
  if (host_fma) fused_modes.push_back(1);
  printf("host: %s; fused modes tested: %s\n", host_fma ? "FMA (llvmpipe fuses)" : "no FMA",
         host_fma ? "fused and unfused" : "unfused");
  for (int fused : fused_modes) {
    ts_math_set_fused(fused);
    const char *mode = fused ? "fused" : "unfused";
    for (const Isa &isa : kIsas)
      if (!have_isa(isa.level))
        printf("skip %s %s: not available on this host in this mode (the scalar twin runs instead)\n", isa.name, mode);
    test_hdr_families(mode);
    test_color_correction(mode);
    test_formats(mode);
    test_glue(mode);
    for (const Isa &isa : kIsas) {
      if (!have_isa(isa.level)) continue;
      ts_batch_force_isa(isa.level);
      test_tonemap_rows((std::string(isa.name) + " " + mode).c_str());
    }
    ts_batch_force_isa(-1);
  }
  ts_math_set_fused(host_fma);

  // The comparison discriminates: the fused fast path against the unfused scalar twin differs
  // (the sampler lerps are mads), so the zeros above are measured.
  if (host_fma && have_isa(TS_BATCH_AVX2)) {
    PostRng r(5);
    const Tex2 tex(r, 37, 23, TS_WRAP_CLAMP, TS_FILTER_LINEAR, 0, 6.f);
    std::vector<ts_vec4f> rb = post_records(r, 512, BB_SLOTS, 37, 23, BB_SLOT_SIZE, 37, 23, 0);
    const bb_variant v = {0};
    std::vector<ts_vec4f> got(512);
    const bb_batch_input in = {{&rb[0], &rb[1], &rb[2]}, {BB_SLOTS, BB_SLOTS, BB_SLOTS}};
    ts_math_set_fused(1);
    bloom_blur_f_batch(&v, &in, &tex.t, got.data(), 512);
    ts_math_set_fused(0);
    long differ = 0;
    for (int i = 0; i < 512; ++i)
      differ += !same_bits(got[i], bloom_blur_f(&v, &rb[static_cast<size_t>(i) * BB_SLOTS], &tex.t));
    ts_math_set_fused(host_fma);
    check(differ > 0, "the check discriminates: fused fast path vs unfused scalar twin differ",
          std::to_string(differ) + " pixels differ");
    printf("  (%ld of 512 blur pixels differ between the fused fast path and the unfused twin)\n", differ);
  }

  // The API on an empty batch writes nothing.
  {
    ts_vec4f sentinel = ts_v4f(7, 7, 7, 7);
    const cc_variant v = {0, 0, 1};
    const cc_batch_input in = {{nullptr, nullptr, nullptr, nullptr}, {1, 0, 0, 0}};
    cc_luts luts;
    std::memset(&luts, 0, sizeof luts);
    color_correction_f_batch(&v, &in, &luts, &sentinel, 0);
    check(same_bits(sentinel, ts_v4f(7, 7, 7, 7)), "count 0 writes nothing");
  }
  return finish();
}

// tiershade tests: unit tests for the image files (glue/io/exr, png, radiance_hdr, atomic_file) and the image
// helpers (glue/base/image, image_diff).
//
// Usage: test_image_io <path/to/grace.hdr>
//   Prints "PASS name" or "FAIL name: details" per check (tests/unit/unit_check.h) and exits
//   non-zero if any check failed. All files go to a private mkdtemp() directory that is
//   removed at the end. Every .hdr next to the probe given is also decoded with stb_image's
//   stbi_loadf directly and compared bit for bit.
//
// Covered: EXR float bit-exact round trip (denormals, -0, 65504, 1e30, Inf,
// NaN payloads), EXR file layout (FLOAT/HALF, ZIP, top-down rows), half round
// trip, EXR without alpha / with an offset data window / without RGB, PNG
// encodings (Linear, sRGB, gamma 2.2) and sanitising, PNG orientation and
// other PNG pixel formats, atomic-write failures, truncated and corrupt
// EXR/PNG/HDR input, .tmp. leftovers, write_file_atomic, ulp_distance, diff_image, hstack
// and read_hdr (synthetic files, damaged headers, and the real probes against stb_image).

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <half.h>
#include <png.h>
#include <stb_image.h>

#include <stdlib.h>
#include <unistd.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "unit_check.h"
#include "base/image.h"
#include "base/image_diff.h"
#include "io/exr.h"
#include "io/png.h"
#include "io/radiance_hdr.h"
#include "io/atomic_file.h"
#include "base/srgb.h"

namespace fs = std::filesystem;

namespace {

std::string g_tmp;  // the mkdtemp directory

std::string in_tmp(const std::string &name) { return g_tmp + "/" + name; }


// Deterministic xorshift generator.
uint32_t g_rng = 0x12345678u;
uint32_t rnd() {
  g_rng ^= g_rng << 13;
  g_rng ^= g_rng >> 17;
  g_rng ^= g_rng << 5;
  return g_rng;
}
float rnd_unit() { return (rnd() >> 8) * (1.0f / 16777216.0f); }

ImageF make_image(int w, int h) {
  ImageF img;
  img.w = w;
  img.h = h;
  img.rgba.assign((size_t)4 * w * h, 0.0f);
  return img;
}

float &px(ImageF &img, int x, int y, int c) { return img.rgba[(size_t)4 * (y * img.w + x) + c]; }
float px(const ImageF &img, int x, int y, int c) { return img.rgba[(size_t)4 * (y * img.w + x) + c]; }

// First index where two float buffers differ bitwise, or -1.
long first_bit_mismatch(const std::vector<float> &a, const std::vector<float> &b) {
  if (a.size() != b.size()) return 0;
  for (size_t i = 0; i < a.size(); ++i)
    if (bits_of(a[i]) != bits_of(b[i])) return (long)i;
  return -1;
}

std::string hex(uint32_t u) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", u);
  return buf;
}

// A libpng simplified-API image description of w x h pixels in `format`, for writing test files.
png_image png_image_of(int w, int h, png_uint_32 format) {
  png_image pi;
  std::memset(&pi, 0, sizeof pi);
  pi.version = PNG_IMAGE_VERSION;
  pi.width = (png_uint_32)w;
  pi.height = (png_uint_32)h;
  pi.format = format;
  return pi;
}

bool contains(const std::string &s, const std::string &sub) { return s.find(sub) != std::string::npos; }

std::vector<unsigned char> read_bytes(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  return std::vector<unsigned char>((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string &path, const std::vector<unsigned char> &data, size_t n) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(reinterpret_cast<const char *>(data.data()), (std::streamsize)std::min(n, data.size()));
}

// Names of files anywhere under g_tmp containing ".tmp.".
std::string tmp_leftovers() {
  std::string found;
  for (const auto &e : fs::recursive_directory_iterator(g_tmp))
    if (contains(e.path().filename().string(), ".tmp.")) found += e.path().string() + " ";
  return found;
}

// ------------------------------------------------------------------ EXR ---

void test_exr_float_roundtrip() {
  const int w = 7, h = 5;  // odd, non-square: catches flips and stride bugs
  ImageF img = make_image(w, h);
  const float specials[] = {0.0f,
                            -0.0f,
                            float_of_bits(0x00000001u),  // smallest denormal
                            float_of_bits(0x80000001u),
                            float_of_bits(0x007fffffu),  // largest denormal
                            float_of_bits(0x00400000u),
                            FLT_MIN,
                            65504.0f,
                            -65504.0f,
                            65520.0f,
                            1e30f,
                            -1e30f,
                            FLT_MAX,
                            -FLT_MAX,
                            INFINITY,
                            -INFINITY,
                            float_of_bits(0x7fc00000u),  // quiet NaN
                            float_of_bits(0xffc00001u),  // negative NaN with payload
                            float_of_bits(0x7fa12345u),  // signalling NaN payload
                            1.0f,
                            std::nextafter(1.0f, 2.0f),
                            3.14159265f,
                            1e-30f};
  const size_t ns = sizeof specials / sizeof specials[0];
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = i < ns ? specials[i] : float_of_bits(rnd());

  const std::string path = in_tmp("float.exr");
  std::string err;
  if (!write_exr(path, img, &err)) {
    check(false, "exr_float_write", err);
    return;
  }
  check(true, "exr_float_write");
  ImageF back;
  if (!read_exr(path, &back, &err)) {
    check(false, "exr_float_roundtrip_bitexact", err);
    return;
  }
  const long m = first_bit_mismatch(img.rgba, back.rgba);
  check(back.w == w && back.h == h && m < 0, "exr_float_roundtrip_bitexact",
        "size " + std::to_string(back.w) + "x" + std::to_string(back.h) + ", first mismatch at " + std::to_string(m) +
            (m >= 0 && (size_t)m < back.rgba.size()
                 ? " (" + hex(bits_of(img.rgba[m])) + " vs " + hex(bits_of(back.rgba[m])) + ")"
                 : ""));

  // Inspect the file with OpenEXR directly: FLOAT channels, ZIP, and the
  // first stored row is the image's top row (ImageF row h-1).
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header &hd = in.header();
    bool types_ok = true;
    for (const char *n : {"R", "G", "B", "A"}) {
      const Imf::Channel *ch = hd.channels().findChannel(n);
      types_ok = types_ok && ch && ch->type == Imf::FLOAT;
    }
    check(types_ok && hd.compression() == Imf::ZIP_COMPRESSION, "exr_float_file_layout",
          "expected R,G,B,A FLOAT channels with ZIP compression");
    std::vector<float> r((size_t)w * h);
    Imf::FrameBuffer fb;
    fb.insert("R", Imf::Slice(Imf::FLOAT, (char *)r.data(), sizeof(float), sizeof(float) * w));
    in.setFrameBuffer(fb);
    in.readPixels(0, h - 1);
    bool top_first = true;
    for (int x = 0; x < w; ++x) top_first = top_first && bits_of(r[x]) == bits_of(px(img, x, h - 1, 0));
    check(top_first, "exr_file_rows_top_down", "file row 0 is not ImageF row h-1");
  } catch (const std::exception &e) {
    check(false, "exr_float_file_layout", e.what());
  }
}

void test_exr_half_roundtrip() {
  const int w = 9, h = 4;
  ImageF img = make_image(w, h);
  const float specials[] = {0.0f,     -0.0f,     5.96e-8f, 6.1e-5f, 1e-5f,     -3e-6f,
                            65504.0f, -65504.0f, 1.0f,     0.1f,    1234.567f, 1e-3f};
  const size_t ns = sizeof specials / sizeof specials[0];
  for (size_t i = 0; i < img.rgba.size(); ++i)
    img.rgba[i] = i < ns ? specials[i] : (rnd_unit() * 2.0f - 1.0f) * 2000.0f;

  const std::string path = in_tmp("half.exr");
  std::string err;
  ImageF back;
  if (!write_exr_half(path, img, &err) || !read_exr(path, &back, &err)) {
    check(false, "exr_half_roundtrip", err);
    return;
  }
  bool size_ok = back.w == w && back.h == h;
  std::string detail;
  double worst_rel = 0;
  for (size_t i = 0; size_ok && i < img.rgba.size(); ++i) {
    const float v = img.rgba[i], r = back.rgba[i];
    const float expect = (float)Imath::half(v);
    // Round to nearest half: relative error <= 2^-11, absolute <= 2^-25
    // in the half denormal range.
    const double tol = std::fabs(v) * std::ldexp(1.0, -11) + std::ldexp(1.0, -25);
    if (bits_of(r) != bits_of(expect) || std::fabs((double)r - v) > tol) {
      detail = "index " + std::to_string(i) + ": wrote " + std::to_string(v) + " read " + std::to_string(r);
      break;
    }
    if (std::fabs(v) >= 6.103515625e-5f)  // smallest normal half
      worst_rel = std::max(worst_rel, std::fabs((double)r - v) / std::fabs(v));
  }
  check(size_ok && detail.empty(), "exr_half_roundtrip", size_ok ? detail : std::string("size mismatch"));
  std::printf("  (half round trip: worst relative error in the normal range %.3g)\n", worst_rel);

  try {
    Imf::InputFile in(path.c_str());
    bool types_ok = true;
    for (const char *n : {"R", "G", "B", "A"}) {
      const Imf::Channel *ch = in.header().channels().findChannel(n);
      types_ok = types_ok && ch && ch->type == Imf::HALF;
    }
    check(types_ok, "exr_half_file_layout", "expected R,G,B,A HALF channels");
  } catch (const std::exception &e) {
    check(false, "exr_half_file_layout", e.what());
  }

  // Out-of-range values saturate to Inf in half.
  ImageF big = make_image(1, 1);
  big.rgba = {1e30f, -1e5f, 65504.0f, 1.0f};
  ImageF bb;
  const bool ok = write_exr_half(in_tmp("half_big.exr"), big, &err) && read_exr(in_tmp("half_big.exr"), &bb, &err);
  check(ok && std::isinf(bb.rgba[0]) && bb.rgba[0] > 0 && std::isinf(bb.rgba[1]) && bb.rgba[1] < 0 &&
            bb.rgba[2] == 65504.0f,
        "exr_half_overflow_to_inf", ok ? "expected +Inf, -Inf, 65504" : err);
}

// EXR written by OpenEXR directly: RGB only (no A), data window not at the
// origin.  read_exr must give A = 1 and the right rows.
void test_exr_foreign_files() {
  const int w = 5, h = 3;
  const std::string path = in_tmp("rgb_offset.exr");
  std::vector<float> top_down((size_t)3 * w * h);
  for (size_t i = 0; i < top_down.size(); ++i) top_down[i] = (float)i * 0.5f - 3.0f;
  try {
    const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(20, 20));
    const Imath::Box2i data(Imath::V2i(3, -2), Imath::V2i(3 + w - 1, -2 + h - 1));
    Imf::Header hd(display, data);
    Imf::FrameBuffer fb;
    const char *names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      hd.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &top_down[c], data, 3 * sizeof(float), 3 * sizeof(float) * w));
    }
    Imf::OutputFile out(path.c_str(), hd);
    out.setFrameBuffer(fb);
    out.writePixels(h);
  } catch (const std::exception &e) {
    check(false, "exr_rgb_only_offset_window", std::string("setup: ") + e.what());
    return;
  }
  ImageF img;
  std::string err;
  if (!read_exr(path, &img, &err)) {
    check(false, "exr_rgb_only_offset_window", err);
    return;
  }
  bool ok = img.w == w && img.h == h;
  for (int y = 0; ok && y < h; ++y)
    for (int x = 0; ok && x < w; ++x) {
      const int fy = h - 1 - y;  // file row
      for (int c = 0; c < 3; ++c) ok = ok && px(img, x, y, c) == top_down[3 * (fy * w + x) + c];
      ok = ok && px(img, x, y, 3) == 1.0f;
    }
  check(ok, "exr_rgb_only_offset_window", "pixel values, orientation or A=1 wrong");

  // A file without R, G, B: clear failure naming the file.
  const std::string ypath = in_tmp("luma_only.exr");
  try {
    Imf::Header hd(2, 2);
    hd.channels().insert("Y", Imf::Channel(Imf::FLOAT));
    std::vector<float> yv(4, 0.5f);
    Imf::FrameBuffer fb;
    fb.insert("Y", Imf::Slice(Imf::FLOAT, (char *)yv.data(), sizeof(float), 2 * sizeof(float)));
    Imf::OutputFile out(ypath.c_str(), hd);
    out.setFrameBuffer(fb);
    out.writePixels(2);
  } catch (const std::exception &e) {
    check(false, "exr_no_rgb_fails", std::string("setup: ") + e.what());
    return;
  }
  err.clear();
  const bool read_ok = read_exr(ypath, &img, &err);
  check(!read_ok && contains(err, ypath) && contains(err, "Y"), "exr_no_rgb_fails",
        read_ok ? "read succeeded" : "message: " + err);
}

// ------------------------------------------------------------------ PNG ---

void test_png_encodings() {
  // Encoded-space accuracy: a fine ramp of linear values.
  const int w = 256, h = 4;
  ImageF img = make_image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = (float)(y * w + x) / (float)(w * h - 1);
      px(img, x, y, 0) = v;
      px(img, x, y, 1) = 1.0f - v;
      px(img, x, y, 2) = rnd_unit();
      px(img, x, y, 3) = rnd_unit();
    }
  struct Mode {
    Encode enc;
    const char *name;
    double (*encode)(double);
    double (*decode)(double);
  };
  const Mode modes[] = {
      {Encode::Linear, "linear", [](double v) { return v; }, [](double v) { return v; }},
      {Encode::SRGB, "srgb", srgb_encode<double>, srgb_decode<double>},
      {Encode::Gamma22, "gamma22", [](double v) { return std::pow(v, 1 / 2.2); },
       [](double v) { return std::pow(v, 2.2); }},
  };
  for (const Mode &m : modes) {
    const std::string path = in_tmp(std::string("enc_") + m.name + ".png");
    std::string err;
    ImageF back;
    const std::string name = std::string("png_") + m.name + "_roundtrip_within_1_255";
    if (!write_png(path, img, m.enc, &err) || !read_png(path, &back, m.enc, &err)) {
      check(false, name, err);
      continue;
    }
    double worst_enc = 0, worst_lin = 0, worst_alpha = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i) {
      const double a = img.rgba[i], b = back.rgba[i];
      if (i % 4 == 3) {
        worst_alpha = std::max(worst_alpha, std::fabs(a - b));
      } else {
        worst_enc = std::max(worst_enc, std::fabs(m.encode(a) - m.encode(b)));
        worst_lin = std::max(worst_lin, std::fabs(a - b));
      }
    }
    const bool ok = back.w == w && back.h == h && worst_enc <= 1.0 / 255 + 1e-6 && worst_alpha <= 1.0 / 255 + 1e-6;
    char buf[160];
    std::snprintf(buf, sizeof buf, "worst encoded error %.3f/255, alpha %.3f/255, linear %.3f/255", worst_enc * 255,
                  worst_alpha * 255, worst_lin * 255);
    check(ok, name, buf);
    if (ok) std::printf("  (%s)\n", buf);

    // Exactness: the decoded value of every code re-encodes to that code.
    ImageF codes = make_image(256, 1);
    for (int k = 0; k < 256; ++k)
      for (int c = 0; c < 4; ++c) px(codes, k, 0, c) = (float)(c == 3 ? k / 255.0 : m.decode(k / 255.0));
    ImageF raw;
    bool exact = write_png(path, codes, m.enc, &err) && read_png(path, &raw, Encode::Linear, &err);
    std::string detail = exact ? "" : err;
    for (int k = 0; exact && k < 256; ++k)
      for (int c = 0; exact && c < 4; ++c)
        if (px(raw, k, 0, c) != (float)(k / 255.0)) {
          exact = false;
          detail = "code " + std::to_string(k) + " channel " + std::to_string(c) + " read back as " +
              std::to_string(px(raw, k, 0, c) * 255);
        }
    check(exact, std::string("png_") + m.name + "_code_exact", detail);
  }
}

void test_png_sanitise() {
  ImageF img = make_image(6, 1);
  const float in[6] = {NAN, INFINITY, -INFINITY, 2.0f, -1.0f, 0.5f};
  const float expect[6] = {0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 128.0f / 255.0f};
  for (int x = 0; x < 6; ++x)
    for (int c = 0; c < 4; ++c) px(img, x, 0, c) = in[x];
  std::string err;
  ImageF back;
  bool ok = write_png(in_tmp("sanitise.png"), img, Encode::SRGB, &err) &&
      read_png(in_tmp("sanitise.png"), &back, Encode::Linear, &err);
  std::string detail = ok ? "" : err;
  for (int x = 0; ok && x < 6; ++x) {
    // Colour channels are sRGB-encoded; only 0, 1 and alpha are encoding-free.
    const float a = px(back, x, 0, 3);
    const float r = px(back, x, 0, 0);
    const float er = x == 5 ? (float)((int)(srgb_encode(0.5) * 255 + 0.5) / 255.0) : expect[x];
    if (a != expect[x] || r != er) {
      ok = false;
      detail = "input " + std::to_string(in[x]) + " -> rgb " + std::to_string(r) + " alpha " + std::to_string(a);
    }
  }
  check(ok, "png_nan_inf_clamp", detail);
}

void test_png_rgba8_orientation() {
  const int w = 3, h = 2;
  std::vector<uint8_t> bottom_up((size_t)4 * w * h);
  for (size_t i = 0; i < bottom_up.size(); ++i) bottom_up[i] = (uint8_t)(i * 11 + 7);
  const std::string path = in_tmp("raw8.png");
  std::string err;
  if (!write_png_rgba8(path, w, h, bottom_up, &err)) {
    check(false, "png_rgba8_write", err);
    return;
  }
  check(true, "png_rgba8_write");

  // Independent reader (libpng simplified API): file row 0 = last input row.
  png_image pi;
  std::memset(&pi, 0, sizeof pi);
  pi.version = PNG_IMAGE_VERSION;
  std::vector<uint8_t> top_down((size_t)4 * w * h);
  bool ok = png_image_begin_read_from_file(&pi, path.c_str()) != 0;
  if (ok) {
    pi.format = PNG_FORMAT_RGBA;
    ok = pi.width == (png_uint_32)w && pi.height == (png_uint_32)h &&
        png_image_finish_read(&pi, nullptr, top_down.data(), 0, nullptr) != 0;
  }
  png_image_free(&pi);
  for (int y = 0; ok && y < h; ++y)
    ok = std::memcmp(&top_down[(size_t)4 * w * y], &bottom_up[(size_t)4 * w * (h - 1 - y)], (size_t)4 * w) == 0;
  check(ok, "png_file_rows_top_down", "file rows are not the input rows flipped");

  ImageF back;
  ok = read_png(path, &back, Encode::Linear, &err);
  std::string detail = ok ? "" : err;
  for (size_t i = 0; ok && i < bottom_up.size(); ++i)
    if (back.rgba[i] != (float)(bottom_up[i] / 255.0)) {
      ok = false;
      detail = "byte " + std::to_string(i) + " mismatch";
    }
  check(ok, "png_rgba8_read_back_exact", detail);
}

// Other PNG pixel formats, written with libpng's simplified API.
void test_png_other_formats() {
  std::string err;
  ImageF back;

  // 8-bit grey, no alpha.
  {
    const std::string path = in_tmp("grey.png");
    png_image pi = png_image_of(4, 2, PNG_FORMAT_GRAY);
    const uint8_t g[8] = {0, 10, 20, 30, 200, 210, 220, 255};
    const bool wrote = png_image_write_to_file(&pi, path.c_str(), 0, g, 0, nullptr) != 0;
    png_image_free(&pi);
    bool ok = wrote && read_png(path, &back, Encode::Linear, &err) && back.w == 4 && back.h == 2;
    for (int y = 0; ok && y < 2; ++y)
      for (int x = 0; ok && x < 4; ++x) {
        const float v = g[(1 - y) * 4 + x] / 255.0f;
        ok = px(back, x, y, 0) == v && px(back, x, y, 1) == v && px(back, x, y, 2) == v && px(back, x, y, 3) == 1.0f;
      }
    check(ok, "png_read_grey", wrote ? err : "setup failed");
  }
  // Palette with transparency (tRNS).
  {
    const std::string path = in_tmp("palette.png");
    png_image pi = png_image_of(3, 1, PNG_FORMAT_RGBA_COLORMAP);
    pi.colormap_entries = 3;
    const uint8_t cmap[12] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0};
    const uint8_t idx[3] = {2, 0, 1};
    const bool wrote = png_image_write_to_file(&pi, path.c_str(), 0, idx, 0, cmap) != 0;
    png_image_free(&pi);
    bool ok = wrote && read_png(path, &back, Encode::Linear, &err) && back.w == 3 && back.h == 1;
    for (int x = 0; ok && x < 3; ++x)
      for (int c = 0; ok && c < 4; ++c) {
        const uint8_t code = cmap[4 * idx[x] + c];
        // Fully transparent entries may have their colour dropped.
        if (cmap[4 * idx[x] + 3] == 0 && c < 3) continue;
        ok = px(back, x, 0, c) == code / 255.0f;
      }
    check(ok, "png_read_palette_trns", wrote ? err : "setup failed");
  }
  // 16-bit linear RGB.
  {
    const std::string path = in_tmp("rgb16.png");
    png_image pi = png_image_of(2, 1, PNG_FORMAT_LINEAR_RGB);
    const uint16_t v[6] = {0, 1, 65535, 12345, 54321, 32768};
    const bool wrote = png_image_write_to_file(&pi, path.c_str(), 0, v, 0, nullptr) != 0;
    png_image_free(&pi);
    bool ok = wrote && read_png(path, &back, Encode::Linear, &err) && back.w == 2 && back.h == 1;
    for (int x = 0; ok && x < 2; ++x) {
      for (int c = 0; c < 3; ++c) ok = ok && px(back, x, 0, c) == (float)(v[3 * x + c] / 65535.0);
      ok = ok && px(back, x, 0, 3) == 1.0f;
    }
    check(ok, "png_read_16bit", wrote ? err : "setup failed");
  }
}

// ------------------------------------------------------------- failures ---

void test_write_failures() {
  ImageF img = make_image(4, 4);
  for (float &v : img.rgba) v = rnd_unit();
  std::vector<uint8_t> bytes(4 * 4 * 4, 100);

  // Directory does not exist.
  const std::string missing_dir = in_tmp("no_such_dir");
  struct Case {
    const char *name;
    std::string path;
  };
  const Case cases[] = {{"exr", missing_dir + "/sub/out.exr"},
                        {"exr_half", missing_dir + "/sub/out_half.exr"},
                        {"png", missing_dir + "/sub/out.png"},
                        {"png_rgba8", missing_dir + "/sub/out8.png"}};
  for (const Case &c : cases) {
    std::string err;
    bool ok;
    const std::string n = c.name;
    if (n == "exr")
      ok = write_exr(c.path, img, &err);
    else if (n == "exr_half")
      ok = write_exr_half(c.path, img, &err);
    else if (n == "png")
      ok = write_png(c.path, img, Encode::SRGB, &err);
    else
      ok = write_png_rgba8(c.path, 4, 4, bytes, &err);
    const bool pass = !ok && contains(err, c.path) && !fs::exists(c.path) && !fs::exists(missing_dir);
    check(pass, std::string("write_") + c.name + "_missing_dir_fails", ok ? "write succeeded" : "message: " + err);
    if (pass && n == "exr") std::printf("  (message: %s)\n", err.c_str());
  }

  // The target is an existing directory: the temporary file gets written,
  // rename() fails, and the temporary must be removed.
  const std::string dir_target = in_tmp("is_a_dir");
  fs::create_directory(dir_target);
  {
    std::string e1, e2, e3;
    const bool a = write_exr(dir_target, img, &e1);
    const bool b = write_png(dir_target, img, Encode::Linear, &e2);
    const bool c = write_png_rgba8(dir_target, 4, 4, bytes, &e3);
    const std::string left = tmp_leftovers();
    check(!a && !b && !c && contains(e1, dir_target) && contains(e2, dir_target) && contains(e3, dir_target) &&
              left.empty() && fs::is_directory(dir_target),
          "write_rename_failure_cleans_up",
          "results " + std::to_string(a) + std::to_string(b) + std::to_string(c) + "; " + e1 + " | " + e2 + " | " + e3 +
              " | leftovers: " + left);
  }

  // Malformed images are refused without creating anything.
  {
    ImageF bad = make_image(4, 4);
    bad.rgba.pop_back();
    std::string e1, e2, e3;
    const std::string p1 = in_tmp("bad.exr"), p2 = in_tmp("bad.png"), p3 = in_tmp("bad8.png");
    const bool a = write_exr(p1, bad, &e1);
    const bool b = write_png(p2, bad, Encode::SRGB, &e2);
    const bool c = write_png_rgba8(p3, 5, 4, bytes, &e3);
    check(!a && !b && !c && contains(e1, p1) && contains(e2, p2) && contains(e3, p3) && !fs::exists(p1) &&
              !fs::exists(p2) && !fs::exists(p3),
          "write_malformed_image_fails", e1 + " | " + e2 + " | " + e3);
  }

  // write_file_atomic: the bytes, the reasons the callers print, nothing left behind.
  {
    const std::string p = in_tmp("atomic.txt"), nodir = missing_dir + "/x.txt";
    std::string e1, e2, e3;
    const bool w1 = write_file_atomic(p, "old", &e1) && write_file_atomic(p, std::string("new\0bytes", 9), &e1);
    const std::vector<unsigned char> got = read_bytes(p);
    check(w1 && std::string(got.begin(), got.end()) == std::string("new\0bytes", 9), "write_file_atomic_replaces", e1);
    check(!write_file_atomic(nodir, "x", &e2) && e2 == nodir + ": cannot write (No such file or directory)" &&
              !fs::exists(nodir),
          "write_file_atomic_missing_dir_message", e2);
    check(!write_file_atomic(dir_target, "x", &e3) && e3.rfind(dir_target + ": cannot replace (", 0) == 0 &&
              fs::is_directory(dir_target) && tmp_leftovers().empty(),
          "write_file_atomic_rename_failure_cleans_up", e3);
  }

  // A successful write replaces an existing file.
  {
    const std::string p = in_tmp("replace.png");
    write_bytes(p, std::vector<unsigned char>(1000, 'x'), 1000);
    std::string err;
    ImageF back;
    const bool ok = write_png(p, img, Encode::Linear, &err) && read_png(p, &back, Encode::Linear, &err);
    check(ok && back.w == 4, "write_replaces_existing_file", err);
  }
}

// Reads must fail (not crash) on every damaged file, naming the file.
template <typename Reader>
void expect_read_failure(const std::string &name, const std::string &path, Reader read) {
  ImageF img;
  std::string err;
  const bool ok = read(path, &img, &err);
  check(!ok && contains(err, path), name, ok ? "read succeeded" : "message: " + err);
}

void test_read_failures(const std::string &probe) {
  auto rexr = [](const std::string &p, ImageF *o, std::string *e) { return read_exr(p, o, e); };
  auto rpng = [](const std::string &p, ImageF *o, std::string *e) { return read_png(p, o, Encode::SRGB, e); };
  auto rhdr = [](const std::string &p, ImageF *o, std::string *e) { return read_hdr(p, o, e); };

  expect_read_failure("read_exr_missing_file", in_tmp("absent.exr"), rexr);
  expect_read_failure("read_png_missing_file", in_tmp("absent.png"), rpng);
  expect_read_failure("read_hdr_missing_file", in_tmp("absent.hdr"), rhdr);

  // A reasonably large, poorly compressible EXR and PNG to damage.
  ImageF img = make_image(64, 48);
  for (float &v : img.rgba) v = rnd_unit() * 10.0f;
  std::string err;
  const std::string exr = in_tmp("good.exr"), png = in_tmp("good.png");
  if (!write_exr(exr, img, &err) || !write_png(png, img, Encode::SRGB, &err)) {
    check(false, "read_failures_setup", err);
    return;
  }
  const std::vector<unsigned char> exr_bytes = read_bytes(exr), png_bytes = read_bytes(png);

  for (size_t n : {(size_t)0, (size_t)3, (size_t)40, (size_t)300, exr_bytes.size() / 2, exr_bytes.size() - 1}) {
    const std::string p = in_tmp("trunc_" + std::to_string(n) + ".exr");
    write_bytes(p, exr_bytes, n);
    expect_read_failure("read_exr_truncated_" + std::to_string(n), p, rexr);
  }
  for (size_t n : {(size_t)0, (size_t)8, (size_t)40, png_bytes.size() / 2, png_bytes.size() - 1}) {
    const std::string p = in_tmp("trunc_" + std::to_string(n) + ".png");
    write_bytes(p, png_bytes, n);
    expect_read_failure("read_png_truncated_" + std::to_string(n), p, rpng);
  }

  // Garbage after a valid magic number, and pure garbage.
  {
    std::vector<unsigned char> g(4096);
    for (auto &b : g) b = (unsigned char)rnd();
    write_bytes(in_tmp("garbage.bin"), g, g.size());
    expect_read_failure("read_exr_garbage", in_tmp("garbage.bin"), rexr);
    expect_read_failure("read_png_garbage", in_tmp("garbage.bin"), rpng);
    expect_read_failure("read_hdr_garbage", in_tmp("garbage.bin"), rhdr);
    std::vector<unsigned char> ge = g;
    std::memcpy(ge.data(), exr_bytes.data(), 8);  // magic + version
    write_bytes(in_tmp("garbage.exr"), ge, ge.size());
    expect_read_failure("read_exr_garbage_after_magic", in_tmp("garbage.exr"), rexr);
    std::vector<unsigned char> gp = g;
    std::memcpy(gp.data(), png_bytes.data(), 8);  // signature
    write_bytes(in_tmp("garbage.png"), gp, gp.size());
    expect_read_failure("read_png_garbage_after_signature", in_tmp("garbage.png"), rpng);
  }

  // Corrupted PNG pixel data: the chunk CRC catches it.
  {
    std::vector<unsigned char> c = png_bytes;
    for (size_t i = c.size() / 2; i < c.size() / 2 + 16; ++i) c[i] ^= 0x5a;
    write_bytes(in_tmp("corrupt.png"), c, c.size());
    expect_read_failure("read_png_corrupt_data", in_tmp("corrupt.png"), rpng);
  }

  // Corrupted EXR bytes past the header: must not crash; if it fails the
  // message must name the file (a bit flip in raw data may go unnoticed).
  {
    int clean = 0, total = 0;
    std::string bad_msg;
    for (int trial = 0; trial < 24; ++trial) {
      std::vector<unsigned char> c = exr_bytes;
      const size_t start = 400 + rnd() % (c.size() - 450);
      for (size_t i = start; i < start + 1 + rnd() % 32 && i < c.size(); ++i) c[i] = (unsigned char)rnd();
      const std::string p = in_tmp("corrupt.exr");
      write_bytes(p, c, c.size());
      ImageF out;
      std::string e;
      ++total;
      if (read_exr(p, &out, &e) || contains(e, p))
        ++clean;
      else
        bad_msg = e;
    }
    check(clean == total, "read_exr_corrupt_data_no_crash", "message without path: " + bad_msg);
  }

  // Truncated real probe.
  const std::vector<unsigned char> hdr_bytes = read_bytes(probe);
  if (!hdr_bytes.empty()) {
    for (size_t n : {(size_t)10, (size_t)60, hdr_bytes.size() / 2, hdr_bytes.size() - 1}) {
      const std::string p = in_tmp("trunc_" + std::to_string(n) + ".hdr");
      write_bytes(p, hdr_bytes, n);
      expect_read_failure("read_hdr_truncated_" + std::to_string(n), p, rhdr);
    }
  }
}

// ---------------------------------------------------------------- diffs ---

void test_ulp_distance() {
  const float one_up = std::nextafter(1.0f, 2.0f);
  const float tiny = float_of_bits(1), ntiny = float_of_bits(0x80000001u);
  const float qnan = float_of_bits(0x7fc00000u), nan2 = float_of_bits(0x7fc00001u);
  struct Case {
    const char *name;
    float a, b;
    uint32_t expect;
  } cases[] = {
      {"equal", 1.5f, 1.5f, 0},
      {"adjacent", 1.0f, one_up, 1},
      {"adjacent_reversed", one_up, 1.0f, 1},
      {"adjacent_negative", -1.0f, -one_up, 1},
      {"pos_neg_zero", 0.0f, -0.0f, 0},
      {"zero_to_min_denormal", 0.0f, tiny, 1},
      {"neg_zero_to_min_denormal", -0.0f, tiny, 1},
      {"min_denormal_pair", ntiny, tiny, 2},
      {"across_zero", -1.0f, 1.0f, 2 * 0x3f800000u},
      {"one_to_two", 1.0f, 2.0f, 1u << 23},
      {"flt_max_to_inf", FLT_MAX, INFINITY, 1},
      {"inf_to_neg_inf", INFINITY, -INFINITY, 2 * 0x7f800000u},
      {"same_nan", qnan, qnan, 0},
      {"different_nans", qnan, nan2, UINT32_MAX},
      {"nan_vs_number", qnan, 1.0f, UINT32_MAX},
  };
  for (const Case &c : cases) {
    const uint32_t d = ulp_distance(c.a, c.b);
    check(d == c.expect, std::string("ulp_distance_") + c.name,
          "got " + std::to_string(d) + ", expected " + std::to_string(c.expect));
  }
}

bool colour_is(const ImageF &img, int x, int y, float r, float g, float b) {
  return std::fabs(px(img, x, y, 0) - r) < 1e-6f && std::fabs(px(img, x, y, 1) - g) < 1e-6f &&
      std::fabs(px(img, x, y, 2) - b) < 1e-6f && px(img, x, y, 3) == 1.0f;
}

void test_diff_image() {
  ImageF a = make_image(4, 3);
  for (float &v : a.rgba) v = 0.25f + rnd_unit();
  ImageF b = a;

  // identical
  DiffStats st;
  ImageF d = diff_image(a, b, &st);
  bool black = d.w == 4 && d.h == 3;
  for (int y = 0; black && y < 3; ++y)
    for (int x = 0; black && x < 4; ++x) black = colour_is(d, x, y, 0, 0, 0);
  check(black && st.pixels == 12 && st.mismatched_pixels == 0 && st.max_ulp == 0 && st.max_abs == 0 &&
            st.worst_x == -1 && st.worst_y == -1,
        "diff_identical", "expected all black and zero stats");

  // (1,0): 1 ULP; (2,2): 1.0 vs 2.0 (2^23 ULP); (0,2): same NaN in both.
  px(b, 1, 0, 1) = std::nextafter(px(a, 1, 0, 1), 10.0f);
  px(a, 2, 2, 2) = 1.0f;
  px(b, 2, 2, 2) = 2.0f;
  px(a, 0, 2, 0) = px(b, 0, 2, 0) = float_of_bits(0x7fc00000u);
  d = diff_image(a, b, &st);
  check(st.pixels == 12 && st.mismatched_pixels == 2 && st.max_ulp == (1u << 23) && st.max_abs == 1.0 &&
            st.worst_x == 2 && st.worst_y == 2,
        "diff_stats_finite",
        "mismatched " + std::to_string(st.mismatched_pixels) + " max_ulp " + std::to_string(st.max_ulp) + " max_abs " +
            std::to_string(st.max_abs) + " worst (" + std::to_string(st.worst_x) + "," + std::to_string(st.worst_y) +
            ")");
  check(colour_is(d, 0, 0, 0, 0, 0) && colour_is(d, 1, 0, 0, 0, 0.5f) && colour_is(d, 2, 2, 1, 0, 0) &&
            colour_is(d, 0, 2, 0, 0, 0),
        "diff_colours_ramp", "expected black / dark blue / red / black(equal NaN)");

  // Add a NaN mismatch at (3,1) and an Inf mismatch at (0,1).
  px(b, 3, 1, 0) = NAN;
  px(b, 0, 1, 3) = INFINITY;
  d = diff_image(a, b, &st);
  check(
      st.mismatched_pixels == 4 && st.max_ulp == UINT32_MAX && st.worst_x == 3 && st.worst_y == 1 && st.max_abs == 1.0,
      "diff_stats_nonfinite",
      "mismatched " + std::to_string(st.mismatched_pixels) + " max_ulp " + std::to_string(st.max_ulp) + " worst (" +
          std::to_string(st.worst_x) + "," + std::to_string(st.worst_y) + ") max_abs " + std::to_string(st.max_abs));
  check(colour_is(d, 3, 1, 1, 0, 1) && colour_is(d, 0, 1, 1, 0, 1), "diff_colours_magenta",
        "NaN/Inf mismatches should be magenta");

  // Size mismatch.
  ImageF c = make_image(3, 3);
  d = diff_image(a, c, &st);
  check(d.w == 0 && d.h == 0 && d.rgba.empty() && st.pixels == 0, "diff_size_mismatch_empty",
        "expected an empty image");
}

void test_hstack() {
  ImageF a = make_image(2, 3), b = make_image(3, 3);
  for (float &v : a.rgba) v = 1.0f;
  for (float &v : b.rgba) v = 2.0f;
  ImageF s = hstack({&a, &b}, 1, 0.25f);
  bool ok = s.w == 6 && s.h == 3 && s.rgba.size() == 4u * 6 * 3;
  for (int y = 0; ok && y < 3; ++y)
    for (int x = 0; ok && x < 6; ++x)
      for (int c = 0; ok && c < 4; ++c) {
        const float e = x < 2 ? 1.0f : x == 2 ? (c == 3 ? 1.0f : 0.25f) : 2.0f;
        ok = px(s, x, y, c) == e;
      }
  check(ok, "hstack_layout", "wrong size or pixels");
  ImageF tall = make_image(2, 4);
  check(hstack({&a, &tall}, 1, 0).w == 0, "hstack_height_mismatch_empty");
  check(hstack({}, 1, 0).w == 0 && hstack({&a, nullptr}, 0, 0).w == 0 && hstack({&a}, -1, 0).w == 0,
        "hstack_bad_input_empty");
  ImageF one = hstack({&a}, 5, 0);
  check(one.w == 2 && one.h == 3 && first_bit_mismatch(one.rgba, a.rgba) < 0, "hstack_single");
}

// ------------------------------------------------------------------ HDR ---

std::vector<unsigned char> hdr_file(const std::string &res, const std::vector<unsigned char> &pix) {
  const std::string head = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n" + res + "\n";
  std::vector<unsigned char> f(head.begin(), head.end());
  f.insert(f.end(), pix.begin(), pix.end());
  return f;
}

bool pixel_is(const ImageF &img, int x, int y, float r, float g, float b) {
  return px(img, x, y, 0) == r && px(img, x, y, 1) == g && px(img, x, y, 2) == b && px(img, x, y, 3) == 1.0f;
}

void test_hdr_synthetic() {
  std::string err;
  ImageF img;

  auto rhdr = [](const std::string &p, ImageF *o, std::string *e) { return read_hdr(p, o, e); };
  // Flat pixels, top-down (-Y).
  {
    const auto f = hdr_file("-Y 2 +X 3", {128, 64,  32,  129, 0, 0, 0, 0,   255, 1,   128, 136,  // top
                                          128, 128, 128, 128, 1, 2, 1, 137, 200, 100, 50,  130});
    write_bytes(in_tmp("flat.hdr"), f, f.size());
    const bool ok = read_hdr(in_tmp("flat.hdr"), &img, &err) && img.w == 3 && img.h == 2 &&
        pixel_is(img, 0, 1, 1.0f, 0.5f, 0.25f) && pixel_is(img, 1, 1, 0, 0, 0) &&
        pixel_is(img, 2, 1, 255.0f, 1.0f, 128.0f) && pixel_is(img, 0, 0, 0.5f, 0.5f, 0.5f) &&
        pixel_is(img, 1, 0, 2.0f, 4.0f, 2.0f) && pixel_is(img, 2, 0, 3.125f, 1.5625f, 0.78125f);
    check(ok, "read_hdr_flat", err.empty() ? "wrong pixels" : err);
    // The same with an old-style run (1,1,1,n repeats the previous pixel): refused, as
    // stb_image would read it as a colour.
    auto old = f;
    old[old.size() - 7] = 1;
    write_bytes(in_tmp("old_rle.hdr"), old, old.size());
    ImageF o;
    std::string e;
    check(!read_hdr(in_tmp("old_rle.hdr"), &o, &e) && contains(e, "old-style"), "read_hdr_old_rle_refused",
          "message: " + e);
  }
  // Refused before decoding: a directory, no FORMAT line, an absurd size, and a size the
  // data cannot hold (a header claiming 11585 x 11585 with no pixels must not allocate 2 GB).
  {
    fs::create_directory(in_tmp("dir.hdr"));
    expect_read_failure("read_hdr_directory_refused", in_tmp("dir.hdr"), rhdr);
    std::string e;
    ImageF o;
    read_hdr(in_tmp("dir.hdr"), &o, &e);
    check(contains(e, "not a regular file"), "read_hdr_directory_message", e);
    const std::string nf = "#?RADIANCE\nEXPOSURE=1\n\n-Y 1 +X 1\n\x80\x80\x80\x81";
    write_bytes(in_tmp("noformat.hdr"), std::vector<unsigned char>(nf.begin(), nf.end()), nf.size());
    expect_read_failure("read_hdr_no_format_refused", in_tmp("noformat.hdr"), rhdr);
    const auto huge = hdr_file("-Y 100000 +X 100000", {2, 2, 1, 0});
    write_bytes(in_tmp("huge.hdr"), huge, huge.size());
    e.clear();
    check(!read_hdr(in_tmp("huge.hdr"), &o, &e) && contains(e, "bad image size"), "read_hdr_huge_size_refused", e);
    for (const char *mode : {"rle", "flat"}) {
      const bool rle = mode[0] == 'r';
      const auto empty =
          hdr_file("-Y 11585 +X 11585",
                   rle ? std::vector<unsigned char>{2, 2, 45, 65, 255, 0} : std::vector<unsigned char>{128, 0, 0, 129});
      const std::string p = in_tmp(std::string("claims_") + mode + ".hdr");
      write_bytes(p, empty, empty.size());
      e.clear();
      const bool ok = read_hdr(p, &o, &e);
      check(!ok && contains(e, p) && contains(e, "truncated"), std::string("read_hdr_size_without_data_") + mode,
            ok ? "read succeeded" : e);
    }
  }
  // Run-length data that ends early or makes no progress (zero counts, which stb_image skips
  // forever at the end of a buffer) is an error, not a hang or a black tail.
  {
    std::vector<unsigned char> z = {2, 2, 0, 8};
    z.insert(z.end(), 64, 0);
    const auto f = hdr_file("-Y 1 +X 8", z);
    write_bytes(in_tmp("zero_counts.hdr"), f, f.size());
    std::string e;
    ImageF o;
    check(!read_hdr(in_tmp("zero_counts.hdr"), &o, &e) && contains(e, "truncated"), "read_hdr_zero_counts_end", e);
    const std::vector<unsigned char> line = {2, 2, 0, 8, 136, 128, 136, 128, 136, 128, 136, 129};
    std::vector<unsigned char> two = line;
    two.insert(two.end(), line.begin(), line.end());
    const auto g = hdr_file("-Y 3 +X 8", two);  // the third scanline is missing
    write_bytes(in_tmp("rle_short.hdr"), g, g.size());
    e.clear();
    check(!read_hdr(in_tmp("rle_short.hdr"), &o, &e) && contains(e, "truncated"), "read_hdr_missing_scanline", e);
    const auto full = hdr_file("-Y 2 +X 8", two);
    write_bytes(in_tmp("rle_two.hdr"), full, full.size());
    e.clear();
    bool ok = read_hdr(in_tmp("rle_two.hdr"), &o, &e) && o.w == 8 && o.h == 2;
    for (int i = 0; ok && i < 16; ++i) ok = pixel_is(o, i % 8, i / 8, 1.0f, 1.0f, 1.0f);
    check(ok, "read_hdr_rle_two_scanlines", e.empty() ? "wrong pixels" : e);
  }
  // New-style RLE, bottom-up (+Y).
  {
    const auto f = hdr_file("+Y 1 +X 8", {2,   2,  0,   8,  136, 128,  // R: run of 8
                                          8,   0,  1,   2,  3,   4,   5, 6, 7,  // G: 8 literals
                                          132, 10, 132, 20,  // B: two runs
                                          136, 129});  // E: run of 8
    write_bytes(in_tmp("rle.hdr"), f, f.size());
    bool ok = read_hdr(in_tmp("rle.hdr"), &img, &err) && img.w == 8 && img.h == 1;
    for (int x = 0; ok && x < 8; ++x) ok = pixel_is(img, x, 0, 1.0f, x / 128.0f, (x < 4 ? 10 : 20) / 128.0f);
    check(ok, "read_hdr_new_rle", err.empty() ? "wrong pixels" : err);

    auto bad = f;
    bad[bad.size() - 2] = 137;  // exponent run of 9 overflows the scanline
    write_bytes(in_tmp("rle_bad.hdr"), bad, bad.size());
    expect_read_failure("read_hdr_corrupt_rle", in_tmp("rle_bad.hdr"), rhdr);
  }
  // +Y orientation: first scanline is the bottom row.
  {
    const auto f = hdr_file("+Y 2 +X 1", {128, 0, 0, 129, 0, 128, 0, 129});
    write_bytes(in_tmp("up.hdr"), f, f.size());
    const bool ok = read_hdr(in_tmp("up.hdr"), &img, &err) && img.w == 1 && img.h == 2 &&
        pixel_is(img, 0, 0, 1, 0, 0) && pixel_is(img, 0, 1, 0, 1, 0);
    check(ok, "read_hdr_plus_y_orientation", err.empty() ? "wrong pixels" : err);
  }
  // Unsupported format.
  {
    std::string head = "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n";
    std::vector<unsigned char> f(head.begin(), head.end());
    f.insert(f.end(), {1, 2, 3, 4});
    write_bytes(in_tmp("xyze.hdr"), f, f.size());
    expect_read_failure("read_hdr_xyze_rejected", in_tmp("xyze.hdr"), rhdr);
  }
}

// read_hdr against stbi_loadf itself on the probe and every other .hdr next to it: the same
// size and the same bits on every channel (read_hdr's rows are bottom-up, stb's top-down).
void test_hdr_probe(const char *path) {
  if (!path) {
    check(false, "read_hdr_probe", "no probe path given (usage: test_image_io <grace.hdr>)");
    return;
  }
  std::vector<std::string> probes = {path};
  std::error_code ec;
  for (const auto &e : fs::directory_iterator(fs::path(path).parent_path(), ec))
    if (e.path().extension() == ".hdr" && !fs::equivalent(e.path(), path, ec)) probes.push_back(e.path().string());
  for (const std::string &p : probes) {
    const std::string name = "read_hdr_equals_stbi_loadf_" + fs::path(p).stem().string();
    ImageF img;
    std::string err;
    if (!read_hdr(p, &img, &err)) {
      check(false, name, err);
      continue;
    }
    int w = 0, h = 0, n = 0;
    float *ref = stbi_loadf(p.c_str(), &w, &h, &n, 4);
    if (!ref) {
      check(false, name, std::string("stbi_loadf: ") + stbi_failure_reason());
      continue;
    }
    long differ = 0, channels = 0;
    float maxv = 0;
    if (w == img.w && h == img.h)
      for (int y = 0; y < h; ++y)
        for (int i = 0; i < 4 * w; ++i, ++channels) {
          const float a = img.rgba[(size_t)4 * w * (h - 1 - y) + i], b = ref[(size_t)4 * w * y + i];
          differ += bits_of(a) != bits_of(b);
          if (i % 4 != 3) maxv = std::max(maxv, a);
        }
    stbi_image_free(ref);
    char buf[200];
    std::snprintf(buf, sizeof buf, "%dx%d (stb %dx%d), %ld of %ld channels differ, max %g", img.w, img.h, w, h, differ,
                  channels, (double)maxv);
    check(w == img.w && h == img.h && channels > 0 && differ == 0 && maxv > 0, name, buf);
    std::printf("  (%s: %s)\n", p.c_str(), buf);
  }
}

}  // namespace

int main(int argc, char **argv) {
  const fs::path base = fs::temp_directory_path() / "tiershade_image_io_XXXXXX";
  std::string templ = base.string();
  if (!mkdtemp(&templ[0])) {
    std::printf("FAIL setup: mkdtemp(%s): %s\n", templ.c_str(), std::strerror(errno));
    return 1;
  }
  g_tmp = templ;

  test_exr_float_roundtrip();
  test_exr_half_roundtrip();
  test_exr_foreign_files();
  test_png_encodings();
  test_png_sanitise();
  test_png_rgba8_orientation();
  test_png_other_formats();
  test_write_failures();
  test_read_failures(argc > 1 ? argv[1] : "");
  test_ulp_distance();
  test_diff_image();
  test_hstack();
  test_hdr_synthetic();
  test_hdr_probe(argc > 1 ? argv[1] : nullptr);

  const std::string left = tmp_leftovers();
  check(left.empty(), "no_tmp_leftovers", left);

  std::error_code ec;
  fs::remove_all(g_tmp, ec);
  check(!ec && !fs::exists(g_tmp), "temp_dir_removed", ec.message());

  return finish();
}

// tiershade io: PNG files (io/png.h), through libpng's classic API.
//   * libpng reports errors with longjmp. All setjmp() calls live in small C-style functions
//     (png_write_c / png_read_c) that own no C++ objects, so a longjmp never skips a
//     destructor. Pixel memory for reading is malloc'd into a caller-owned struct and freed
//     on the error path.
//   * Writes go through an AtomicFile (io/atomic_file.h).
#include "io/png.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "base/srgb.h"
#include "io/atomic_file.h"
#include "io/io_error.h"
#include "io/memory_limit.h"

namespace {

// Error context shared with the libpng callbacks.
struct PngCtx {
  char msg[256];
};

void png_error_cb(png_structp png, png_const_charp msg) {
  PngCtx *ctx = static_cast<PngCtx *>(png_get_error_ptr(png));
  if (ctx) std::snprintf(ctx->msg, sizeof ctx->msg, "%s", msg ? msg : "libpng error");
  png_longjmp(png, 1);
}

void png_warning_cb(png_structp, png_const_charp) {}

// Read callback with a clearer message than libpng's "Read Error".
void png_read_cb(png_structp png, png_bytep data, size_t length) {
  FILE *fp = static_cast<FILE *>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, fp) != length)
    png_error(png, std::feof(fp) ? "unexpected end of file (truncated?)" : "read error");
}

// PNG bytes in memory (a glTF texture), read through png_read_mem_cb.
struct PngMem {
  const unsigned char *data;
  size_t size, at;
};

void png_read_mem_cb(png_structp png, png_bytep data, size_t length) {
  PngMem *m = static_cast<PngMem *>(png_get_io_ptr(png));
  if (length > m->size - m->at) png_error(png, "unexpected end of data (truncated?)");
  std::memcpy(data, m->data + m->at, length);
  m->at += length;
}

bool out_of_memory(PngCtx *ctx) {
  std::snprintf(ctx->msg, sizeof ctx->msg, "out of memory");
  return false;
}

enum PngChunk { kChunkNone, kChunkSRGB, kChunkGamma22 };

// Writes an 8-bit RGBA PNG from top-down row pointers.  C-style on purpose:
// no C++ object may be live in a frame that png_longjmp() unwinds.
bool png_write_c(FILE *fp, int w, int h, png_bytep *rows, PngChunk chunk, PngCtx *ctx) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, ctx, png_error_cb, png_warning_cb);
  if (!png) return out_of_memory(ctx);
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return out_of_memory(ctx);
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, fp);
  png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (chunk == kChunkSRGB)
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  else if (chunk == kChunkGamma22)
    png_set_gAMA_fixed(png, info, 45455);  // file gamma 1/2.2 in units of 1e-5
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// Result of png_read_c: RGBA, top-down, 8 or 16 bits per sample (16-bit
// samples big-endian as stored).  pixels/rows are malloc'd; caller frees.
struct PngRaw {
  png_uint_32 w, h;
  int depth;
  unsigned char *pixels;
  png_bytep *rows;
};

// Decodes any PNG to RGBA 8/16-bit, after its 8-byte signature (checked by the caller), through
// read_fn on io. 16-bit samples stay big-endian as stored unless swap16 (then host order, little-
// endian here). C-style for the same reason as above.
bool png_read_c(png_rw_ptr read_fn, void *io, bool swap16, PngRaw *raw, PngCtx *ctx) {
  raw->pixels = nullptr;
  raw->rows = nullptr;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, ctx, png_error_cb, png_warning_cb);
  if (!png) return out_of_memory(ctx);
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return out_of_memory(ctx);
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    std::free(raw->pixels);
    std::free(raw->rows);
    raw->pixels = nullptr;
    raw->rows = nullptr;
    return false;
  }
  png_set_read_fn(png, io, read_fn);
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);

  raw->w = png_get_image_width(png, info);
  raw->h = png_get_image_height(png, info);
  if ((long long)raw->w * (long long)raw->h > kMaxImagePixels) png_error(png, "image too large");
  {  // libpng's rows (up to 8 bytes a pixel) and the float image (16): checked before either is allocated
    char msg[200];
    const double need = 24.0 * raw->w * raw->h;
    if (need > memory_limit_mib() * 1048576.0) {
      std::snprintf(msg, sizeof msg, "a %u x %u image needs %.0f MiB, over the memory limit of %lld MiB (raise it with --max-memory MIB)",
                    (unsigned)raw->w, (unsigned)raw->h, std::ceil(need / 1048576.0), memory_limit_mib());
      png_error(png, msg);
    }
  }

  const int color_type = png_get_color_type(png, info);
  const int bit_depth = png_get_bit_depth(png, info);
  const bool has_trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (has_trns) png_set_tRNS_to_alpha(png);
  if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
  if (!(color_type & PNG_COLOR_MASK_ALPHA) && !has_trns) png_set_add_alpha(png, 0xffff, PNG_FILLER_AFTER);
  if (swap16 && bit_depth == 16) png_set_swap(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);

  raw->depth = png_get_bit_depth(png, info);
  const size_t rowbytes = png_get_rowbytes(png, info);
  if (png_get_channels(png, info) != 4 || (raw->depth != 8 && raw->depth != 16) ||
      rowbytes != (size_t)raw->w * 4 * (size_t)(raw->depth / 8))
    png_error(png, "unsupported pixel layout after conversion");

  raw->pixels = static_cast<unsigned char *>(std::malloc(rowbytes * raw->h));
  raw->rows = static_cast<png_bytep *>(std::malloc(sizeof(png_bytep) * raw->h));
  if (!raw->pixels || !raw->rows) png_error(png, "out of memory");
  for (png_uint_32 y = 0; y < raw->h; ++y) raw->rows[y] = raw->pixels + rowbytes * y;
  png_read_image(png, raw->rows);
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

// The Encode curve (encode) or its inverse, evaluated in double; v in [0,1].
double transfer(double v, Encode enc, bool encode) {
  switch (enc) {
    case Encode::SRGB:
      return encode ? srgb_encode(v) : srgb_decode(v);
    case Encode::Gamma22:
      return std::pow(v, encode ? 1.0 / 2.2 : 2.2);
    case Encode::Linear:
      break;
  }
  return v;
}

// Float -> 8-bit code: NaN -> 0, clamp to [0,1] (so -Inf -> 0, +Inf -> 1),
// encode, round to nearest.
uint8_t quantize(float f, Encode enc) {
  double v = std::isnan(f) ? 0.0 : std::min(1.0, std::max(0.0, (double)f));
  v = std::min(1.0, std::max(0.0, transfer(v, enc, true)));
  return (uint8_t)(v * 255.0 + 0.5);
}

// Writes top-down 8-bit RGBA rows atomically.
bool write_png_rows(const char *fn, const std::string &path, int w, int h, png_bytep *rows, PngChunk chunk,
                    std::string *err) {
  std::string why;
  AtomicFile file(path);
  if (!file.open(&why)) return io_error(err, fn, path, why);
  PngCtx ctx;
  ctx.msg[0] = '\0';
  if (!png_write_c(file.fp(), w, h, rows, chunk, &ctx))
    return io_error(err, fn, path, std::string("libpng: ") + ctx.msg);
  if (!file.commit(&why)) return io_error(err, fn, path, why);
  return true;
}

}  // namespace

bool write_png(const std::string &path, const ImageF &img, Encode enc, std::string *err) {
  static const char fn[] = "write_png";
  std::string why;
  if (!image_ok(img, &why)) return io_error(err, fn, path, why);
  const int w = img.w, h = img.h;
  std::vector<unsigned char> bytes((size_t)4 * w * h);
  std::vector<png_bytep> rows(h);
  for (int y = 0; y < h; ++y) {
    const float *src = &img.rgba[(size_t)4 * w * y];
    unsigned char *dst = &bytes[(size_t)4 * w * (h - 1 - y)];  // file is top-down
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) dst[4 * x + c] = quantize(src[4 * x + c], enc);
      dst[4 * x + 3] = quantize(src[4 * x + 3], Encode::Linear);
    }
  }
  for (int y = 0; y < h; ++y) rows[y] = &bytes[(size_t)4 * w * y];
  const PngChunk chunk = enc == Encode::SRGB ? kChunkSRGB : enc == Encode::Gamma22 ? kChunkGamma22 : kChunkNone;
  return write_png_rows(fn, path, w, h, rows.data(), chunk, err);
}

bool write_png_rgba8(const std::string &path, int w, int h, const std::vector<uint8_t> &rgba_bottom_up,
                     std::string *err) {
  static const char fn[] = "write_png_rgba8";
  if (w <= 0 || h <= 0 || (long long)w * h > kMaxImagePixels)
    return io_error(err, fn, path, "invalid image size " + std::to_string(w) + "x" + std::to_string(h));
  if (rgba_bottom_up.size() != (size_t)4 * w * h)
    return io_error(err, fn, path,
                    "pixel buffer holds " + std::to_string(rgba_bottom_up.size()) + " bytes, expected " +
                        std::to_string((size_t)4 * w * h));
  // libpng copies each row before filtering, so it never writes through
  // these pointers; the const_cast only satisfies its non-const signature.
  std::vector<png_bytep> rows(h);
  for (int y = 0; y < h; ++y) rows[y] = const_cast<png_bytep>(&rgba_bottom_up[(size_t)4 * w * (h - 1 - y)]);
  return write_png_rows(fn, path, w, h, rows.data(), kChunkNone, err);
}

bool read_png(const std::string &path, ImageF *out, Encode decode, std::string *err) {
  static const char fn[] = "read_png";
  std::string why;
  if (!regular_file_within(path, 1LL << 30, nullptr, &why)) return io_error(err, fn, path, why);
  FILE *fp = std::fopen(path.c_str(), "rb");
  if (!fp) return io_error(err, fn, path, std::string("cannot open: ") + std::strerror(errno));
  PngCtx ctx;
  ctx.msg[0] = '\0';
  PngRaw raw;
  unsigned char sig[8];
  if (std::fread(sig, 1, 8, fp) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
    std::fclose(fp);
    return io_error(err, fn, path, "not a PNG file (bad signature)");
  }
  const bool ok = png_read_c(png_read_cb, fp, false, &raw, &ctx);
  std::fclose(fp);
  if (!ok) return io_error(err, fn, path, ctx.msg);

  const int w = (int)raw.w, h = (int)raw.h;
  const bool wide = raw.depth == 16;
  const double maxcode = wide ? 65535.0 : 255.0;
  float lut[256];  // 8-bit decode table for colour channels
  for (int i = 0; i < 256; ++i) lut[i] = (float)transfer(i / 255.0, decode, false);

  ImageF img;
  img.w = w;
  img.h = h;
  img.rgba.resize((size_t)4 * w * h);
  for (int y = 0; y < h; ++y) {
    const unsigned char *src = raw.rows[h - 1 - y];  // file is top-down
    float *dst = &img.rgba[(size_t)4 * w * y];
    for (int i = 0; i < 4 * w; ++i) {
      const bool alpha = (i & 3) == 3;
      if (wide) {
        const double v = ((src[2 * i] << 8) | src[2 * i + 1]) / maxcode;
        dst[i] = (float)(alpha ? v : transfer(v, decode, false));
      } else {
        dst[i] = alpha ? (float)(src[i] / maxcode) : lut[src[i]];
      }
    }
  }
  std::free(raw.pixels);
  std::free(raw.rows);
  *out = std::move(img);
  return true;
}

bool is_png(const unsigned char *bytes, size_t size) { return size >= 8 && png_sig_cmp(bytes, 0, 8) == 0; }

bool decode_png_rgba(const unsigned char *bytes, size_t size, std::vector<unsigned char> *out, int *w, int *h, int *bits,
                     std::string *why) {
  if (!is_png(bytes, size)) {
    *why = "not a PNG file (bad signature)";
    return false;
  }
  PngMem mem{bytes, size, 8};
  PngCtx ctx;
  ctx.msg[0] = '\0';
  PngRaw raw;
  if (!png_read_c(png_read_mem_cb, &mem, true, &raw, &ctx)) {
    *why = ctx.msg[0] ? ctx.msg : "libpng error";
    return false;
  }
  const size_t n = static_cast<size_t>(raw.w) * raw.h * 4 * (raw.depth / 8);
  out->assign(raw.pixels, raw.pixels + n);  // rows are contiguous, top-down
  *w = static_cast<int>(raw.w);
  *h = static_cast<int>(raw.h);
  *bits = raw.depth;
  std::free(raw.pixels);
  std::free(raw.rows);
  return true;
}

// tiershade io: openEXR files (io/exr.h): written through the OpenEXR 3 C++ API, read through its
// C core (openexr.h) within the memory limit.
//   * Output goes through FileOStream (an Imf::OStream over FILE*) into an AtomicFile, so
//     write errors are seen even when OpenEXR swallows them (it writes the line-offset table
//     from ~OutputFile, which cannot throw).
//   * Nothing here throws: every library exception becomes a message that names the file.
#include "io/exr.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <half.h>
#include <openexr.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/io_error.h"
#include "io/memory_limit.h"

namespace {

// Imf::OStream over a stdio FILE, remembering the first error.
class FileOStream : public Imf::OStream {
 public:
  FileOStream(FILE *fp, const std::string &name) : Imf::OStream(name.c_str()), fp_(fp) {}

  void write(const char c[], int n) override {
    if (n > 0 && std::fwrite(c, 1, (size_t)n, fp_) != (size_t)n) fail("write failed");
  }
  uint64_t tellp() override {
    const off_t p = ftello(fp_);
    if (p < 0) fail("tell failed");
    return (uint64_t)p;
  }
  void seekp(uint64_t pos) override {
    if (fseeko(fp_, (off_t)pos, SEEK_SET) != 0) fail("seek failed");
  }

  bool failed() const { return failed_; }
  const std::string &reason() const { return reason_; }

 private:
  [[noreturn]] void fail(const char *what) {
    const int e = errno;
    if (!failed_) {
      failed_ = true;
      reason_ = std::string(what) + ": " + std::strerror(e ? e : EIO);
    }
    throw std::runtime_error(reason_);
  }

  FILE *fp_;
  bool failed_ = false;
  std::string reason_;
};

// Writes img (bottom-up) as a top-down RGBA EXR of the given channel type.
bool write_exr_any(const char *fn, const std::string &path, const ImageF &img, Imf::PixelType type, std::string *err) {
  std::string why;
  if (!image_ok(img, &why)) return io_error(err, fn, path, why);
  const int w = img.w, h = img.h;

  // Flipped to file order (top row first) and converted to the channel type a block of kRows
  // rows at a time (OpenEXR takes a new frame buffer between writePixels calls): a frame's copy
  // would be as large as the frame (127 MiB at 3840x2160), the block is a few MiB at most.
  const int kRows = 64;
  const size_t elem = type == Imf::FLOAT ? sizeof(float) : sizeof(Imath::half);
  const size_t row_bytes = (size_t)4 * w * elem;
  std::vector<char> block(row_bytes * (size_t)std::min(kRows, h));

  AtomicFile file(path);
  if (!file.open(&why)) return io_error(err, fn, path, why);
  FileOStream os(file.fp(), file.tmp_path());
  try {
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    static const char *const names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) header.channels().insert(names[c], Imf::Channel(type));
    Imf::OutputFile out(os, header);
    for (int y0 = 0; y0 < h; y0 += kRows) {
      const int rows = std::min(kRows, h - y0);
      for (int r = 0; r < rows; ++r) {
        const float *src = &img.rgba[(size_t)4 * w * (h - 1 - (y0 + r))];
        char *dst = &block[row_bytes * r];
        if (type == Imf::FLOAT) {
          std::memcpy(dst, src, row_bytes);
        } else {
          Imath::half *hd = reinterpret_cast<Imath::half *>(dst);
          for (int i = 0; i < 4 * w; ++i) hd[i] = Imath::half(src[i]);
        }
      }
      // The slices address file row y at base + y * yStride: the block's first row is row y0.
      char *base = reinterpret_cast<char *>(reinterpret_cast<uintptr_t>(block.data()) - (uintptr_t)y0 * row_bytes);
      Imf::FrameBuffer fb;
      for (int c = 0; c < 4; ++c) fb.insert(names[c], Imf::Slice(type, base + c * elem, 4 * elem, row_bytes));
      out.setFrameBuffer(fb);
      out.writePixels(rows);
    }
  } catch (const std::exception &e) {
    return io_error(err, fn, path, os.failed() ? os.reason() : std::string(e.what()));
  }
  if (os.failed()) return io_error(err, fn, path, os.reason());  // an error OpenEXR swallowed in ~OutputFile
  if (!file.commit(&why)) return io_error(err, fn, path, why);
  return true;
}

// ------------------------------------------------------------------------------ reading ---
// Reading goes through OpenEXR's C core (openexr.h), not the C++ InputFile: InputFile allocates
// from the header before anything can be checked (an unknown attribute's declared size, 1.8 GB
// from a 444-byte file; line buffers of width x lines a chunk), whereas the core checks each
// attribute's size against the file's and makes every allocation through the context's
// alloc_fn. core_alloc counts those allocations against a budget (the memory limit minus what
// read_exr allocates itself, io/memory_limit.h), so no header can make it take more.

struct CoreBudget {
  double left = 0;       // bytes the core may still allocate
  double refused = 0;    // the first allocation refused, 0 if none
  std::string message;   // the core's last error message
};
thread_local CoreBudget *t_budget = nullptr;  // the read_exr running on this thread (the core has no threads)

constexpr size_t kAllocHead = 16;  // the size of each block, ahead of it (keeps malloc's 16-byte alignment)

void *core_alloc(size_t n) {
  CoreBudget *b = t_budget;
  if (n > SIZE_MAX - kAllocHead) return nullptr;
  if (b && static_cast<double>(n) > b->left) {
    if (b->refused == 0) b->refused = static_cast<double>(n);
    return nullptr;
  }
  unsigned char *p = static_cast<unsigned char *>(std::malloc(n + kAllocHead));
  if (!p) return nullptr;
  const size_t counted = b ? n : 0;
  std::memcpy(p, &counted, sizeof counted);
  if (b) b->left -= static_cast<double>(n);
  return p + kAllocHead;
}

void core_free(void *q) {
  if (!q) return;
  unsigned char *p = static_cast<unsigned char *>(q) - kAllocHead;
  size_t counted;
  std::memcpy(&counted, p, sizeof counted);
  if (t_budget) t_budget->left += static_cast<double>(counted);
  std::free(p);
}

void core_error(exr_const_context_t, exr_result_t, const char *msg) {
  if (t_budget && msg) t_budget->message = msg;
}

// One read: the budget installed for this thread, the context and the decoder, released in order.
struct CoreRead {
  CoreBudget budget;
  CoreBudget *prev;
  exr_context_t ctx = nullptr;
  exr_decode_pipeline_t dec{};  // EXR_DECODE_PIPELINE_INITIALIZER: all zero
  bool dec_live = false;
  CoreRead() : prev(t_budget) { t_budget = &budget; }
  ~CoreRead() {
    if (dec_live) exr_decoding_destroy(ctx, &dec);
    exr_finish(&ctx);
    t_budget = prev;
  }
  CoreRead(const CoreRead &) = delete;
  CoreRead &operator=(const CoreRead &) = delete;

  // "what: reason": the refused allocation against the limit, else the core's message.
  std::string why(exr_result_t rc, const std::string &what) const {
    std::string r;
    if (budget.refused > 0)
      return what + ": OpenEXR asked for a buffer of " + std::to_string(static_cast<long long>(budget.refused)) +
          " bytes, over what the memory limit of " + std::to_string(memory_limit_mib()) +
          " MiB leaves it (raise it with --max-memory MIB)";
    r = budget.message.empty() ? exr_get_default_error_message(rc) : budget.message;
    return what + " (" + r + ")";
  }
};

int rgba_index(const char *name) {
  static const char *const names[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c)
    if (name && std::strcmp(name, names[c]) == 0) return c;
  return -1;
}

// Sample i of a channel decoded in its own type (native byte order) as a float, converted as the
// C++ library converts to FLOAT (half: Imath's table; uint: float(u); float: the same bits).
float sample_as_float(const unsigned char *p, uint16_t type, size_t i) {
  if (type == EXR_PIXEL_HALF) {
    uint16_t bits;
    std::memcpy(&bits, p + 2 * i, 2);
    Imath::half h;
    h.setBits(bits);
    return static_cast<float>(h);
  }
  if (type == EXR_PIXEL_UINT) {
    uint32_t u;
    std::memcpy(&u, p + 4 * i, 4);
    return static_cast<float>(u);
  }
  float f;
  std::memcpy(&f, p + 4 * i, 4);
  return f;
}

// Decodes one chunk (a block of scanlines or a tile, at (x0, y0) from the data window's corner,
// rows counted from the top) into img (bottom-up), the R, G, B, A channels only.
exr_result_t decode_chunk(CoreRead &r, const exr_chunk_info_t &ci, long long x0, long long y0, std::vector<unsigned char> &scratch,
                          ImageF *img, std::string *why) {
  exr_result_t rc = r.dec_live ? exr_decoding_update(r.ctx, 0, &ci, &r.dec) : exr_decoding_initialize(r.ctx, 0, &ci, &r.dec);
  if (rc != EXR_ERR_SUCCESS) return rc;
  r.dec_live = true;
  if (x0 < 0 || y0 < 0 || ci.width < 1 || ci.height < 1 || x0 + ci.width > img->w || y0 + ci.height > img->h) {
    *why = "chunk " + std::to_string(ci.idx) + " lies outside the data window";
    return EXR_ERR_CORRUPT_CHUNK;
  }
  size_t off = 0, at[4] = {0, 0, 0, 0};
  int chan[4] = {-1, -1, -1, -1};
  for (int i = 0; i < r.dec.channel_count; ++i) {
    exr_coding_channel_info_t &c = r.dec.channels[i];
    const int k = rgba_index(c.channel_name);
    c.decode_to_ptr = nullptr;
    if (k < 0) continue;  // other channels are skipped by the unpacker
    if (c.width != ci.width || c.height != ci.height) {
      *why = "chunk " + std::to_string(ci.idx) + ": channel " + c.channel_name + " has another size than its chunk";
      return EXR_ERR_CORRUPT_CHUNK;
    }
    const size_t need = static_cast<size_t>(c.bytes_per_element) * static_cast<size_t>(c.width) * static_cast<size_t>(c.height);
    if (off + need > scratch.size()) {
      *why = "chunk " + std::to_string(ci.idx) + " is larger than the file's largest chunk";
      return EXR_ERR_CORRUPT_CHUNK;
    }
    c.user_bytes_per_element = c.bytes_per_element;  // decoded in its own type, converted below
    c.user_data_type = c.data_type;
    c.user_pixel_stride = c.bytes_per_element;
    c.user_line_stride = c.bytes_per_element * c.width;
    c.decode_to_ptr = scratch.data() + off;
    chan[k] = i;
    at[k] = off;
    off += need;
  }
  if ((rc = exr_decoding_choose_default_routines(r.ctx, 0, &r.dec)) != EXR_ERR_SUCCESS) return rc;
  if ((rc = exr_decoding_run(r.ctx, 0, &r.dec)) != EXR_ERR_SUCCESS) return rc;
  const size_t w = static_cast<size_t>(img->w);
  for (int k = 0; k < 4; ++k) {
    if (chan[k] < 0) continue;
    const uint16_t type = r.dec.channels[chan[k]].data_type;
    const unsigned char *src = scratch.data() + at[k];
    for (int y = 0; y < ci.height; ++y) {
      float *row = &img->rgba[4 * w * static_cast<size_t>(img->h - 1 - (y0 + y))];  // file row y0+y, top-down
      for (int x = 0; x < ci.width; ++x)
        row[4 * static_cast<size_t>(x0 + x) + k] = sample_as_float(src, type, static_cast<size_t>(y) * ci.width + x);
    }
  }
  return EXR_ERR_SUCCESS;
}
// OpenEXR 3.1's C core has no DWAA/DWAB decoder, and its tiled B44/B44A results differ from the
// C++ library's at partial tiles (tests/unit/test_exr_core.cpp): those files are decoded by the
// C++ InputFile as before, but only after the core has read and checked their whole header
// within the budget (so InputFile's own copy of the attributes is within it too) and their line
// buffers (a chunk's unpacked size, a few times) were checked against the memory limit.
// InputFile reads every attribute of every header before anything can be checked, and allocates
// each one's declared size (an opaque attribute of 1.6 GB from a 446-byte file the core had
// accepted: tests/fuzz/regressions/probe/probe_oom-*). So the headers are walked here as InputFile
// walks them (OpenEXR file layout: magic, version and flags, then per header `name\0 type\0 int32
// size, value`, ended by an empty name; a multi-part file's headers end with an empty header), and
// any attribute whose declared size is negative or runs past the end of the file is refused.
// A name from the file as it can be printed: other bytes than printable ASCII as \xNN.
std::string printable(const std::string &s) {
  std::string o;
  for (unsigned char c : s) {
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      o.push_back(static_cast<char>(c));
    } else {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", c);
      o += b;
    }
  }
  return o;
}

bool inputfile_headers_fit(const std::string &path, std::string *why) {
  FILE *f = std::fopen(path.c_str(), "rb");
  if (!f) {
    *why = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  std::fseek(f, 0, SEEK_END);
  const long long file_size = std::ftell(f);
  std::fseek(f, 0, SEEK_SET);
  long long pos = 0;
  auto get = [&](void *dst, size_t n) {
    const bool ok = std::fread(dst, 1, n, f) == n;
    pos += static_cast<long long>(n);
    return ok;
  };
  // A name or type: at most 255 bytes with the long-names flag (31 without), then a NUL.
  auto get_str = [&](std::string *s, size_t max) {
    s->clear();
    for (;;) {
      const int c = std::fgetc(f);
      if (c == EOF) return false;
      ++pos;
      if (c == 0) return true;
      if (s->size() >= max) return false;
      s->push_back(static_cast<char>(c));
    }
  };
  unsigned char head[8];
  bool ok = get(head, 8);
  const unsigned flags = ok ? static_cast<unsigned>(head[5]) : 0;  // version bits 8..15
  const size_t max_name = (flags & 0x04) ? 255 : 31;               // 0x400: long names
  const bool multipart = (flags & 0x10) != 0;                      // 0x1000: multi-part
  for (int part = 0; ok; ++part) {
    std::string name, type;
    bool first = true;
    for (;;) {
      const long long at = pos;
      if (!get_str(&name, max_name)) {
        ok = false;
        *why = "header " + std::to_string(part) + ": bad attribute name at byte " + std::to_string(at);
        break;
      }
      if (name.empty()) break;  // end of this header (or, first in a multi-part file, of all)
      first = false;
      unsigned char sz[4];
      if (!get_str(&type, max_name) || !get(sz, 4)) {
        ok = false;
        *why = "header " + std::to_string(part) + ": attribute '" + printable(name) + "' at byte " + std::to_string(at) + " is cut short";
        break;
      }
      const int32_t size = static_cast<int32_t>(static_cast<uint32_t>(sz[0]) | static_cast<uint32_t>(sz[1]) << 8 |
                                                static_cast<uint32_t>(sz[2]) << 16 | static_cast<uint32_t>(sz[3]) << 24);
      if (size < 0 || size > file_size - pos) {
        ok = false;
        *why = "header " + std::to_string(part) + ": attribute '" + printable(name) + "' (" + printable(type) + ") at byte " + std::to_string(at) +
            " declares " + std::to_string(size) + " bytes, past the end of the file (" + std::to_string(file_size) + " bytes)";
        break;
      }
      std::fseek(f, size, SEEK_CUR);
      pos += size;
    }
    if (!ok || !multipart || (first && part > 0)) break;
  }
  std::fclose(f);
  return ok;
}

bool read_with_inputfile(const char *fn, const std::string &path, const exr_attr_box2i_t &core_dw, const bool present[4],
                         ImageF *img, std::string *err) {
  std::string why;
  if (!inputfile_headers_fit(path, &why)) return io_error(err, fn, path, why);
  try {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    if (dw.min.x != core_dw.min.x || dw.min.y != core_dw.min.y || dw.max.x != core_dw.max.x || dw.max.y != core_dw.max.y)
      return io_error(err, fn, path, "the header reads differently with OpenEXR's C++ library (data window)");
    if (!in.isComplete()) return io_error(err, fn, path, "file is incomplete (truncated?)");
    const size_t w = static_cast<size_t>(img->w), h = static_cast<size_t>(img->h);
    std::vector<float> buf(4 * w * h, 1.0f);  // top-down, then flipped
    static const char *const names[4] = {"R", "G", "B", "A"};
    Imf::FrameBuffer fb;
    for (int c = 0; c < 4; ++c)
      if (present[c]) {
        const Imf::Channel *ch = in.header().channels().findChannel(names[c]);
        if (!ch || ch->xSampling != 1 || ch->ySampling != 1)
          return io_error(err, fn, path, "the header reads differently with OpenEXR's C++ library (channels)");
        fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &buf[c], dw, 4 * sizeof(float), 4 * sizeof(float) * w));
      }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    for (size_t y = 0; y < h; ++y) std::memcpy(&img->rgba[4 * w * (h - 1 - y)], &buf[4 * w * y], sizeof(float) * 4 * w);
    return true;
  } catch (const std::exception &e) {
    return io_error(err, fn, path, e.what());
  } catch (...) {
    return io_error(err, fn, path, "unknown error");
  }
}

}  // namespace

bool write_exr(const std::string &path, const ImageF &img, std::string *err) {
  return write_exr_any("write_exr", path, img, Imf::FLOAT, err);
}

bool write_exr_half(const std::string &path, const ImageF &img, std::string *err) {
  return write_exr_any("write_exr_half", path, img, Imf::HALF, err);
}

bool read_exr(const std::string &path, ImageF *out, std::string *err) {
  static const char fn[] = "read_exr";
  std::string why;
  if (!regular_file_within(path, 1LL << 31, nullptr, &why)) return io_error(err, fn, path, why);
  const double limit = static_cast<double>(memory_limit_mib()) * 1048576.0;
  CoreRead r;
  r.budget.left = limit;
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = core_error;
  init.alloc_fn = core_alloc;
  init.free_fn = core_free;
  init.max_image_width = init.max_image_height = static_cast<int>(kMaxImagePixels);
  init.max_tile_width = init.max_tile_height = 65536;
  init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;  // a broken offset table is an error
  exr_result_t rc = exr_start_read(&r.ctx, path.c_str(), &init);
  if (rc != EXR_ERR_SUCCESS) return io_error(err, fn, path, r.why(rc, "bad header"));

  exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
  exr_attr_box2i_t dw;
  const exr_attr_chlist_t *chans = nullptr;
  uint64_t chunk_bytes = 0;
  if ((rc = exr_get_storage(r.ctx, 0, &storage)) != EXR_ERR_SUCCESS || (rc = exr_get_data_window(r.ctx, 0, &dw)) != EXR_ERR_SUCCESS ||
      (rc = exr_get_channels(r.ctx, 0, &chans)) != EXR_ERR_SUCCESS || (rc = exr_get_chunk_unpacked_size(r.ctx, 0, &chunk_bytes)) != EXR_ERR_SUCCESS)
    return io_error(err, fn, path, r.why(rc, "bad header"));
  if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
    return io_error(err, fn, path, "deep data (unsupported: a flat scanline or tiled image is needed)");
  const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
  const long long h = static_cast<long long>(dw.max.y) - dw.min.y + 1;
  if (w <= 0 || h <= 0 || w * h > kMaxImagePixels) return io_error(err, fn, path, "bad or too large data window");
  const std::string dims = std::to_string(w) + " x " + std::to_string(h);
  // The image and its flipped copy were 16 bytes a pixel each with the C++ reader: 32 kept as the
  // stated limit (docs/reliability.md); then a chunk's decoded channels (our copy) and the core's.
  if (!memory_fits(32.0 * w * h, "a " + dims + " image", &why) ||
      !memory_fits(16.0 * w * h + 2.0 * static_cast<double>(chunk_bytes), "a " + dims + " image with its chunks of " + std::to_string(chunk_bytes) + " bytes", &why))
    return io_error(err, fn, path, why);

  bool present[4] = {false, false, false, false};
  std::string found;
  for (int i = 0; i < chans->num_channels; ++i) {
    const exr_attr_chlist_entry_t &c = chans->entries[i];
    found += std::string(found.empty() ? "" : ", ") + c.name.str;
    const int k = rgba_index(c.name.str);
    if (k < 0) continue;
    present[k] = true;
    if (c.x_sampling != 1 || c.y_sampling != 1)
      return io_error(err, fn, path, std::string("channel ") + c.name.str + " is subsampled (unsupported)");
  }
  if (!present[0] || !present[1] || !present[2])
    return io_error(err, fn, path, "no R, G, B channels (channels: " + (found.empty() ? "none" : found) + ")");

  ImageF img;
  img.w = static_cast<int>(w);
  img.h = static_cast<int>(h);
  img.rgba.assign(static_cast<size_t>(4 * w * h), 1.0f);  // a missing A reads as 1
  exr_compression_t comp = EXR_COMPRESSION_NONE;
  if ((rc = exr_get_compression(r.ctx, 0, &comp)) != EXR_ERR_SUCCESS) return io_error(err, fn, path, r.why(rc, "bad header"));
  if (comp == EXR_COMPRESSION_DWAA || comp == EXR_COMPRESSION_DWAB ||
      (storage == EXR_STORAGE_TILED && (comp == EXR_COMPRESSION_B44 || comp == EXR_COMPRESSION_B44A))) {
    // InputFile: the top-down copy (16 bytes a pixel) and its line buffers and decompressor's
    // (a chunk's unpacked size, four times)
    if (!memory_fits(32.0 * w * h + 4.0 * static_cast<double>(chunk_bytes), "a " + dims + " image with its chunks of " + std::to_string(chunk_bytes) + " bytes", &why))
      return io_error(err, fn, path, why);
    if (!read_with_inputfile(fn, path, dw, present, &img, err)) return false;
    *out = std::move(img);
    return true;
  }
  std::vector<unsigned char> scratch(chunk_bytes);
  r.budget.left = limit - 16.0 * w * h - static_cast<double>(chunk_bytes);
  exr_chunk_info_t ci;
  if (storage == EXR_STORAGE_SCANLINE) {
    int32_t lines = 0;
    if ((rc = exr_get_scanlines_per_chunk(r.ctx, 0, &lines)) != EXR_ERR_SUCCESS || lines < 1)
      return io_error(err, fn, path, r.why(rc ? rc : EXR_ERR_INVALID_ATTR, "bad header"));
    for (long long y = dw.min.y; y <= dw.max.y; y += lines) {
      if ((rc = exr_read_scanline_chunk_info(r.ctx, 0, static_cast<int>(y), &ci)) != EXR_ERR_SUCCESS)
        return io_error(err, fn, path, r.why(rc, "file is incomplete or corrupt at line " + std::to_string(y)));
      why.clear();
      if ((rc = decode_chunk(r, ci, 0, static_cast<long long>(ci.start_y) - dw.min.y, scratch, &img, &why)) != EXR_ERR_SUCCESS)
        return io_error(err, fn, path, why.empty() ? r.why(rc, "cannot decode the lines from " + std::to_string(ci.start_y)) : why);
    }
  } else {
    int32_t tw = 0, th = 0;
    if ((rc = exr_get_tile_sizes(r.ctx, 0, 0, 0, &tw, &th)) != EXR_ERR_SUCCESS || tw < 1 || th < 1)
      return io_error(err, fn, path, r.why(rc ? rc : EXR_ERR_INVALID_ATTR, "bad tile description"));
    for (long long ty = 0; ty * th < h; ++ty)
      for (long long tx = 0; tx * tw < w; ++tx) {
        const std::string tile = "tile (" + std::to_string(tx) + ", " + std::to_string(ty) + ")";
        if ((rc = exr_read_tile_chunk_info(r.ctx, 0, static_cast<int>(tx), static_cast<int>(ty), 0, 0, &ci)) != EXR_ERR_SUCCESS)
          return io_error(err, fn, path, r.why(rc, "file is incomplete or corrupt at " + tile));
        why.clear();
        if ((rc = decode_chunk(r, ci, tx * tw, ty * th, scratch, &img, &why)) != EXR_ERR_SUCCESS)
          return io_error(err, fn, path, why.empty() ? r.why(rc, "cannot decode " + tile) : why);
      }
  }
  *out = std::move(img);
  return true;
}

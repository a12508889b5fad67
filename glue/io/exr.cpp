// tiershade io: openEXR files (io/exr.h), through the OpenEXR 3 C++ API.
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
  const size_t n = (size_t)4 * w * h;

  // Flip to file order (top row first) and convert to the channel type.
  std::vector<float> fbuf;
  std::vector<Imath::half> hbuf;
  char *base;
  size_t elem;
  if (type == Imf::FLOAT) {
    fbuf.resize(n);
    for (int y = 0; y < h; ++y)
      std::memcpy(&fbuf[(size_t)4 * w * (h - 1 - y)], &img.rgba[(size_t)4 * w * y], sizeof(float) * 4 * w);
    base = reinterpret_cast<char *>(fbuf.data());
    elem = sizeof(float);
  } else {
    hbuf.resize(n);
    for (int y = 0; y < h; ++y) {
      const float *src = &img.rgba[(size_t)4 * w * y];
      Imath::half *dst = &hbuf[(size_t)4 * w * (h - 1 - y)];
      for (int i = 0; i < 4 * w; ++i) dst[i] = Imath::half(src[i]);
    }
    base = reinterpret_cast<char *>(hbuf.data());
    elem = sizeof(Imath::half);
  }

  AtomicFile file(path);
  if (!file.open(&why)) return io_error(err, fn, path, why);
  FileOStream os(file.fp(), file.tmp_path());
  try {
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    static const char *const names[4] = {"R", "G", "B", "A"};
    Imf::FrameBuffer fb;
    for (int c = 0; c < 4; ++c) {
      header.channels().insert(names[c], Imf::Channel(type));
      fb.insert(names[c], Imf::Slice(type, base + c * elem, 4 * elem, 4 * elem * (size_t)w));
    }
    Imf::OutputFile out(os, header);
    out.setFrameBuffer(fb);
    out.writePixels(h);
  } catch (const std::exception &e) {
    return io_error(err, fn, path, os.failed() ? os.reason() : std::string(e.what()));
  }
  if (os.failed()) return io_error(err, fn, path, os.reason());  // an error OpenEXR swallowed in ~OutputFile
  if (!file.commit(&why)) return io_error(err, fn, path, why);
  return true;
}

// OpenEXR allocates from the header in InputFile's constructor (line buffers of width x lines a
// chunk x channels, tile buffers), before the data window can be checked: the header's
// attributes (OpenEXR file layout: magic, version, then name\0 type\0 int32 size value, up to an
// empty name) are read here first and those sizes checked against the memory limit.
bool exr_header_fits(const std::string &path, std::string *why) {
  FILE *f = std::fopen(path.c_str(), "rb");
  if (!f) {
    *why = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  std::vector<unsigned char> b(1 << 16);
  b.resize(std::fread(b.data(), 1, b.size(), f));
  long long file_size = static_cast<long long>(b.size());
  if (std::fseek(f, 0, SEEK_END) == 0) file_size = ftello(f);
  std::fclose(f);
  auto le = [&](size_t p) -> long long {
    return p + 4 <= b.size() ? static_cast<int32_t>(b[p] | b[p + 1] << 8 | b[p + 2] << 16 | static_cast<uint32_t>(b[p + 3]) << 24) : 0;
  };
  long long w = 0, h = 0, tx = 0, ty = 0, channels = 0;
  size_t p = 8;
  while (p < b.size() && b[p] != 0) {
    const size_t n0 = p;
    while (p < b.size() && b[p]) ++p;
    if (p >= b.size()) break;
    const std::string name(b.begin() + n0, b.begin() + p);
    const size_t t0 = ++p;
    while (p < b.size() && b[p]) ++p;
    if (p + 5 > b.size()) break;  // OpenEXR reports a truncated header
    const std::string type(b.begin() + t0, b.begin() + p);
    ++p;
    const long long size = le(p);
    p += 4;
    if (size < 0 || static_cast<long long>(p) + size > file_size) {  // OpenEXR would allocate it first
      *why = "header attribute '" + name + "' claims " + std::to_string(size) + " bytes, more than the file holds";
      return false;
    }
    if (p + size > b.size()) break;  // a header beyond what was read: OpenEXR checks the rest
    if (name == "dataWindow" && type == "box2i" && size == 16) {
      w = le(p + 8) - le(p) + 1;
      h = le(p + 12) - le(p + 4) + 1;
    } else if (name == "tiles" && type == "tiledesc" && size >= 8) {
      tx = static_cast<uint32_t>(le(p));
      ty = static_cast<uint32_t>(le(p + 4));
    } else if (name == "channels" && type == "chlist") {
      for (size_t q = p; q < p + size && b[q];) {
        while (q < p + size && b[q]) ++q;
        q += 17;
        ++channels;
      }
    }
    p += size;
  }
  if (w <= 0 || h <= 0) return true;  // OpenEXR reports it
  const double px = static_cast<double>(w) * h, ch = static_cast<double>(std::max(1LL, channels));
  const std::string dims = std::to_string(w) + " x " + std::to_string(h);
  if (px > static_cast<double>(kMaxImagePixels)) {
    *why = "data window " + dims + " is more than " + std::to_string(kMaxImagePixels) + " pixels";
    return false;
  }
  // Lines are decoded up to 256 at a time (DWAB), 4 bytes a channel sample at most.
  return memory_fits(32.0 * px, "a " + dims + " image", why) &&
      memory_fits(4.0 * ch * static_cast<double>(w) * 256, "a " + dims + " image of " + std::to_string(channels) + " channels", why) &&
      memory_fits(4.0 * ch * static_cast<double>(tx) * static_cast<double>(ty), "tiles of " + std::to_string(tx) + " x " + std::to_string(ty), why);
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
  if (!regular_file_within(path, 1LL << 31, nullptr, &why) || !exr_header_fits(path, &why))
    return io_error(err, fn, path, why);
  {  // OpenEXR's C core reads the header first: it checks every attribute against the file
     // (the C++ InputFile allocates an attribute's claimed size before reading it)
    exr_context_t ctx = nullptr;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = [](exr_const_context_t, exr_result_t, const char *) {};
    const exr_result_t r = exr_start_read(&ctx, path.c_str(), &init);
    exr_finish(&ctx);
    if (r != EXR_ERR_SUCCESS) return io_error(err, fn, path, std::string("bad header (") + exr_get_default_error_message(r) + ")");
  }
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header &header = in.header();
    const Imath::Box2i dw = header.dataWindow();
    const long long w = (long long)dw.max.x - dw.min.x + 1;
    const long long h = (long long)dw.max.y - dw.min.y + 1;
    if (w <= 0 || h <= 0 || w * h > kMaxImagePixels) return io_error(err, fn, path, "bad or too large data window");
    // The float buffer read and ImageF's flipped copy: 16 bytes per pixel each.
    if (!memory_fits(32.0 * w * h, "a " + std::to_string(w) + " x " + std::to_string(h) + " image", &why))
      return io_error(err, fn, path, why);
    static const char *const names[4] = {"R", "G", "B", "A"};
    bool present[4];
    for (int c = 0; c < 4; ++c) {
      const Imf::Channel *ch = header.channels().findChannel(names[c]);
      present[c] = ch != nullptr;
      if (ch && (ch->xSampling != 1 || ch->ySampling != 1))
        return io_error(err, fn, path, std::string("channel ") + names[c] + " is subsampled (unsupported)");
    }
    if (!present[0] || !present[1] || !present[2]) {
      std::string found;
      for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
        found += std::string(found.empty() ? "" : ", ") + it.name();
      return io_error(err, fn, path, "no R, G, B channels (channels: " + (found.empty() ? "none" : found) + ")");
    }
    if (!in.isComplete()) return io_error(err, fn, path, "file is incomplete (truncated?)");

    // Read top-down, then flip to ImageF's bottom-up order.
    std::vector<float> buf((size_t)4 * w * h, 1.0f);
    Imf::FrameBuffer fb;
    for (int c = 0; c < 4; ++c)
      if (present[c])
        fb.insert(names[c],
                  Imf::Slice::Make(Imf::FLOAT, &buf[c], dw, 4 * sizeof(float), 4 * sizeof(float) * (size_t)w));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);

    ImageF img;
    img.w = (int)w;
    img.h = (int)h;
    img.rgba.resize(buf.size());
    for (long long y = 0; y < h; ++y)
      std::memcpy(&img.rgba[(size_t)(4 * w * (h - 1 - y))], &buf[(size_t)(4 * w * y)], sizeof(float) * 4 * (size_t)w);
    *out = std::move(img);
    return true;
  } catch (const std::exception &e) {
    return io_error(err, fn, path, e.what());
  } catch (...) {
    return io_error(err, fn, path, "unknown error");
  }
}

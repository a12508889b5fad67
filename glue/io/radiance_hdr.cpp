// tiershade io: the Radiance .hdr reader (io/radiance_hdr.h). The header is parsed here so that
// its sizes are checked before stb_image allocates; the pixels are decoded by stbi_loadf
// (stb_image.h, "HDR (radiance rgbE format)") through read callbacks over the file in memory.
// The callbacks serve 0xFF bytes past the end and record it: stb's run-length decoder then
// always ends (a zero count makes no progress), and a truncated file is reported.
// Format facts: Greg Ward, "Real Pixels" (Graphics Gems II, 1991) and the Radiance file
// format notes (new-style scanline: 2, 2, width >> 8, width & 255, then four run-length coded
// planes; a count byte above 128 is a run of count - 128).
#include "io/radiance_hdr.h"

#include <stb_image.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <vector>

#include "io/io_error.h"
#include "io/memory_limit.h"

namespace {

constexpr long long kMaxFileBytes = 1LL << 30;
const char kTruncated[] = "unexpected end of file in pixel data (truncated?)";

// Reads a whole regular file into memory.
bool slurp(const std::string &path, std::vector<unsigned char> *data, std::string *why) {
  long long size = 0;
  if (!regular_file_within(path, kMaxFileBytes, &size, why)) return false;
  if (!memory_fits(static_cast<double>(size), "the file", why)) return false;
  FILE *fp = std::fopen(path.c_str(), "rb");
  if (!fp) {
    *why = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  data->resize(static_cast<size_t>(size));
  const size_t n = data->empty() ? 0 : std::fread(data->data(), 1, data->size(), fp);
  const bool bad = std::ferror(fp) != 0;
  const int e = errno;
  std::fclose(fp);
  if (bad || n != data->size()) {
    *why = std::string("read error: ") + std::strerror(bad ? e : EIO);
    return false;
  }
  return true;
}

// Reads one header line starting at *pos (without the '\n' and trailing blanks); false at EOF.
bool next_line(const std::vector<unsigned char> &d, size_t *pos, std::string *line) {
  if (*pos >= d.size()) return false;
  size_t end = *pos;
  while (end < d.size() && d[end] != '\n') ++end;
  if (end >= d.size()) return false;  // header lines must be terminated
  line->assign(reinterpret_cast<const char *>(&d[*pos]), end - *pos);
  while (!line->empty() && (line->back() == '\r' || line->back() == ' ' || line->back() == '\t')) line->pop_back();
  *pos = end + 1;
  return true;
}

struct Header {
  int w = 0, h = 0;
  bool top_down = true;  // -Y: the first scanline is the top row
  size_t data = 0;  // offset of the first scanline
};

bool parse_header(const std::vector<unsigned char> &d, Header *hd, std::string *why) {
  size_t pos = 0;
  std::string line;
  if (!next_line(d, &pos, &line) || (line != "#?RADIANCE" && line != "#?RGBE")) {
    *why = "not a Radiance HDR file (missing #?RADIANCE or #?RGBE signature)";
    return false;
  }
  bool format = false;
  for (;;) {  // header variables up to the blank line
    if (!next_line(d, &pos, &line)) {
      *why = "truncated header";
      return false;
    }
    if (line.empty()) break;
    if (line.compare(0, 7, "FORMAT=") == 0) {
      if (line != "FORMAT=32-bit_rle_rgbe") {
        *why = "unsupported " + line + " (only 32-bit_rle_rgbe)";
        return false;
      }
      format = true;
    }
  }
  if (!format) {
    *why = "no FORMAT=32-bit_rle_rgbe line in the header";
    return false;
  }
  if (!next_line(d, &pos, &line)) {
    *why = "missing resolution line";
    return false;
  }
  char ya[3] = {0}, xa[3] = {0};
  int consumed = 0;
  if (std::sscanf(line.c_str(), "%2s %d %2s %d%n", ya, &hd->h, xa, &hd->w, &consumed) != 4 ||
      static_cast<size_t>(consumed) != line.size()) {
    *why = "bad resolution line '" + line + "'";
    return false;
  }
  hd->top_down = std::strcmp(ya, "-Y") == 0;
  if ((!hd->top_down && std::strcmp(ya, "+Y") != 0) || std::strcmp(xa, "+X") != 0) {
    *why = "unsupported orientation '" + line + "' (need -Y/+Y h +X w)";
    return false;
  }
  if (hd->w <= 0 || hd->h <= 0 || static_cast<long long>(hd->w) * hd->h > kMaxImagePixels) {
    *why = "bad image size in '" + line + "'";
    return false;
  }
  hd->data = pos;
  return true;
}

// Checks the pixel data against the header before stb allocates w * h * 16 bytes. stb reads
// flat pixels when w < 8 or w >= 32768 or the first scanline has no new-style marker.
bool check_pixel_data(const std::vector<unsigned char> &d, const Header &hd, std::string *why) {
  const size_t avail = d.size() - hd.data;
  const long long pixels = static_cast<long long>(hd.w) * hd.h;
  const unsigned char *p = d.data() + hd.data;
  if (avail < 4) {
    *why = kTruncated;
    return false;
  }
  const bool rle = hd.w >= 8 && hd.w < 32768 && p[0] == 2 && p[1] == 2 && !(p[2] & 0x80);
  if (rle) {
    // Each of a scanline's four planes takes at least 2 bytes per 127 pixels (one run).
    const long long per_line = 4 + 4 * 2 * ((hd.w + 126LL) / 127);
    if (static_cast<long long>(avail) < per_line * hd.h) {
      *why = kTruncated;
      return false;
    }
    return true;
  }
  const long long have = std::min(pixels, static_cast<long long>(avail / 4));
  for (long long i = 0; i < have; ++i)
    if (i % hd.w != 0 && p[4 * i] == 1 && p[4 * i + 1] == 1 && p[4 * i + 2] == 1) {
      *why = "old-style run-length pixels (1,1,1,n) at scanline " + std::to_string(i / hd.w) + " are not supported";
      return false;
    }
  if (static_cast<long long>(avail) < 4 * pixels) {
    *why = kTruncated;
    return false;
  }
  return true;
}

// stb_image read callbacks over the file in memory, behind a header of our own: stb reads
// "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y h +X w\n" (the header parse_header read, in the one
// form stb takes), then the file's pixel data. stb's header parse then ends where ours did: on a
// header it parsed differently (a blank line holding a space, which stb does not take for the end
// of the header), it read the pixel data, and the fill past the end, as header lines forever
// (tests/fuzz/regressions/hdr/hdr_timeout-*).
struct Source {
  std::string head;          // the header stb reads
  const unsigned char *data;  // the file's pixel data
  size_t size, pos = 0;      // pos: in head, then data (head.size() + offset)
  int lookahead = 0;  // the size of stb's buffer refills (its first request)
  bool overrun = false;
  size_t total() const { return head.size() + size; }
};

int source_read(void *user, char *out, int n) {
  Source *s = static_cast<Source *>(user);
  if (s->lookahead == 0) s->lookahead = n;
  const size_t want = static_cast<size_t>(std::max(n, 0));
  const size_t k = std::min(want, s->total() - s->pos);
  const size_t from_head = s->pos < s->head.size() ? std::min(k, s->head.size() - s->pos) : 0;
  if (from_head) std::memcpy(out, s->head.data() + s->pos, from_head);
  if (k > from_head) std::memcpy(out + from_head, s->data + (s->pos + from_head - s->head.size()), k - from_head);
  s->pos += k;
  // A short refill near the end is normal; a read stb needs in full, or any read at the end,
  // asks for bytes the file does not have. The fill is 0xFF: a run-length count of 0 would make
  // stb's scanline decoder loop without advancing, 0xFF ends it ("bad RLE data").
  if (k < want && (k == 0 || n != s->lookahead)) {
    std::memset(out + k, 0xFF, want - k);
    s->overrun = true;
    return n;
  }
  return static_cast<int>(k);
}

void source_skip(void *user, int n) {
  Source *s = static_cast<Source *>(user);
  const long long p = static_cast<long long>(s->pos) + n;
  s->pos = static_cast<size_t>(std::min(std::max(p, 0LL), static_cast<long long>(s->total())));
}

int source_eof(void *user) {
  const Source *s = static_cast<const Source *>(user);
  return s->pos >= s->total();
}

std::string stb_reason() {
  const char *r = stbi_failure_reason();
  const std::string why = r ? r : "unknown error";
  if (why == "corrupt" || why == "bad RLE data in HDR") return "corrupt pixel data (run overflows scanline)";
  if (why == "invalid decoded scanline length" || why == "corrupt HDR")
    return "corrupt pixel data (scanline length mismatch)";
  if (why == "outofmem" || why == "Out of memory") return "out of memory";
  return "stb_image: " + why;
}

bool read_hdr_impl(const std::string &path, ImageF *out, std::string *why) {
  std::vector<unsigned char> d;
  Header hd;
  if (!slurp(path, &d, why) || !parse_header(d, &hd, why) || !check_pixel_data(d, hd, why)) return false;
  // stb's float image and ImageF's copy: 16 bytes per pixel each, besides the file.
  const double pixels = static_cast<double>(hd.w) * hd.h;
  if (!memory_fits(static_cast<double>(d.size()) + 32.0 * pixels,
                   "a " + std::to_string(hd.w) + " x " + std::to_string(hd.h) + " image", why))
    return false;
  // stb reads only "-Y h +X w": for "+Y" it decodes the same scanlines, stored bottom row first.
  Source src{"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(hd.h) + " +X " + std::to_string(hd.w) + "\n",
             d.data() + hd.data, d.size() - hd.data};
  const stbi_io_callbacks io = {source_read, source_skip, source_eof};
  int w = 0, h = 0, comp = 0;
  float *pix = stbi_loadf_from_callbacks(&io, &src, &w, &h, &comp, 4);
  if (!pix) {
    *why = src.overrun ? kTruncated : stb_reason();
    return false;
  }
  if (src.overrun || w != hd.w || h != hd.h) {
    stbi_image_free(pix);
    *why = src.overrun ? kTruncated : "stb_image read another size than the header's";
    return false;
  }
  ImageF img;
  img.w = w;
  img.h = h;
  const size_t row = static_cast<size_t>(4) * w;
  try {
    img.rgba.resize(row * h);
  } catch (const std::exception &) {
    stbi_image_free(pix);
    throw;
  }
  for (int i = 0; i < h; ++i) {
    const int y = hd.top_down ? h - 1 - i : i;  // ImageF row 0 = bottom
    std::memcpy(&img.rgba[row * y], pix + row * i, sizeof(float) * row);
  }
  stbi_image_free(pix);
  *out = std::move(img);
  return true;
}

}  // namespace

bool read_hdr(const std::string &path, ImageF *out, std::string *err) {
  std::string why;
  try {
    if (read_hdr_impl(path, out, &why)) return true;
  } catch (const std::exception &e) {  // std::bad_alloc
    why = e.what();
  }
  return io_error(err, "read_hdr", path, why);
}

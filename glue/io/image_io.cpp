// ============================================================================
// tiershade — glue/io/image_io.cpp
//
// Implementation of glue/io/image_io.h: OpenEXR (via the OpenEXR 3 C++ API),
// PNG (via libpng's classic API), a self-contained Radiance RGBE reader, ULP
// diffing and a horizontal montage.
//
// Build: g++ -std=c++17 $(pkg-config --cflags OpenEXR libpng) -c image_io.cpp
// Link : $(pkg-config --libs OpenEXR libpng)
//
// Design notes
//   * Atomic writes: AtomicFile writes "<path>.tmp.<pid>", then fflush +
//     fsync + fclose (all checked) + rename().  Its destructor unlinks the
//     temporary file unless commit() succeeded, so every early return and
//     every exception path cleans up.
//   * OpenEXR output goes through FileOStream (an Imf::OStream over FILE*)
//     so write errors are seen even when OpenEXR swallows them (it writes the
//     line-offset table from ~OutputFile, which cannot throw).
//   * libpng reports errors with longjmp.  All setjmp() calls live in small
//     C-style functions (png_write_c / png_read_c) that own no C++ objects,
//     so a longjmp never skips a destructor.  Pixel memory for reading is
//     malloc'd into a caller-owned struct and freed on the error path.
//   * Nothing here throws: every library exception is caught and turned into
//     an error message that names the file.
// ============================================================================
#include "io/image_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <half.h>
#include <png.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <system_error>

namespace {

// Largest image any reader accepts (pixels).  Protects against absurd sizes
// in corrupt headers: 2^27 pixels = 2 GiB of RGBA float.
constexpr long long kMaxPixels = 1LL << 27;

// ------------------------------------------------------------ utilities ---

void set_err(std::string *err, const std::string &msg)
{
    if (err) *err = msg;
}

std::string errno_text(int e)
{
    return std::generic_category().message(e);
}

// "fn: 'path': reason" — the common shape of every error message.
std::string fail_msg(const char *fn, const std::string &path, const std::string &reason)
{
    return std::string(fn) + ": '" + path + "': " + reason;
}

// Checks that an ImageF is self-consistent; on failure explains why.
bool image_ok(const ImageF &img, std::string *why)
{
    if (img.w <= 0 || img.h <= 0) {
        *why = "invalid image size " + std::to_string(img.w) + "x" + std::to_string(img.h);
        return false;
    }
    if ((long long)img.w * img.h > kMaxPixels) {
        *why = "image too large";
        return false;
    }
    const size_t need = (size_t)4 * (size_t)img.w * (size_t)img.h;
    if (img.rgba.size() != need) {
        *why = "pixel buffer holds " + std::to_string(img.rgba.size()) + " floats, expected " +
               std::to_string(need);
        return false;
    }
    return true;
}

uint32_t float_bits(float f)
{
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

bool bits_nan(uint32_t u) { return (u & 0x7fffffffu) > 0x7f800000u; }
bool bits_finite(uint32_t u) { return (u & 0x7f800000u) != 0x7f800000u; }

// --------------------------------------------------------- atomic files ---

// A file written under a temporary name and renamed into place on commit().
class AtomicFile {
public:
    explicit AtomicFile(const std::string &path)
        : path_(path), tmp_(path + ".tmp." + std::to_string((long)getpid()))
    {
    }
    ~AtomicFile()
    {
        if (fp_) std::fclose(fp_);
        if (created_ && !committed_) ::unlink(tmp_.c_str());
    }
    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &operator=(const AtomicFile &) = delete;

    const std::string &tmp_path() const { return tmp_; }
    FILE *fp() const { return fp_; }

    bool open(std::string *why)
    {
        fp_ = std::fopen(tmp_.c_str(), "wb");
        if (!fp_) {
            *why = "cannot create temporary file '" + tmp_ + "': " + errno_text(errno);
            return false;
        }
        created_ = true;
        return true;
    }

    // Flushes, syncs and closes the temporary file, then renames it to path.
    bool commit(std::string *why)
    {
        FILE *fp = fp_;
        fp_ = nullptr;
        bool ok = true;
        int e = 0;
        if (std::fflush(fp) != 0 || std::ferror(fp)) {
            ok = false;
            e = errno;
        }
        if (ok && ::fsync(fileno(fp)) != 0) {
            ok = false;
            e = errno;
        }
        if (std::fclose(fp) != 0 && ok) {
            ok = false;
            e = errno;
        }
        if (!ok) {
            *why = "error writing temporary file '" + tmp_ + "': " + errno_text(e ? e : EIO);
            return false;
        }
        if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
            *why = "cannot rename '" + tmp_ + "' into place: " + errno_text(errno);
            return false;
        }
        committed_ = true;
        return true;
    }

private:
    std::string path_, tmp_;
    FILE *fp_ = nullptr;
    bool created_ = false, committed_ = false;
};

// Reads a whole (regular) file into memory.
bool slurp(const std::string &path, std::vector<unsigned char> *data, std::string *why)
{
    FILE *fp = std::fopen(path.c_str(), "rb");
    if (!fp) {
        *why = "cannot open: " + errno_text(errno);
        return false;
    }
    data->clear();
    unsigned char buf[1 << 16];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, fp)) > 0) {
        if (data->size() + n > ((size_t)1 << 30)) {
            std::fclose(fp);
            *why = "file too large";
            return false;
        }
        data->insert(data->end(), buf, buf + n);
    }
    const bool bad = std::ferror(fp) != 0;
    const int e = errno;
    std::fclose(fp);
    if (bad) {
        *why = "read error: " + errno_text(e);
        return false;
    }
    return true;
}

// -------------------------------------------------------------- OpenEXR ---

// Imf::OStream over a stdio FILE, remembering the first error.
class FileOStream : public Imf::OStream {
public:
    FileOStream(FILE *fp, const std::string &name) : Imf::OStream(name.c_str()), fp_(fp) {}

    void write(const char c[], int n) override
    {
        if (n > 0 && std::fwrite(c, 1, (size_t)n, fp_) != (size_t)n) fail("write failed");
    }
    uint64_t tellp() override
    {
        const off_t p = ftello(fp_);
        if (p < 0) fail("tell failed");
        return (uint64_t)p;
    }
    void seekp(uint64_t pos) override
    {
        if (fseeko(fp_, (off_t)pos, SEEK_SET) != 0) fail("seek failed");
    }

    bool failed() const { return failed_; }
    const std::string &reason() const { return reason_; }

private:
    [[noreturn]] void fail(const char *what)
    {
        const int e = errno;
        if (!failed_) {
            failed_ = true;
            reason_ = std::string(what) + ": " + errno_text(e ? e : EIO);
        }
        throw std::runtime_error(reason_);
    }

    FILE *fp_;
    bool failed_ = false;
    std::string reason_;
};

// Writes img (bottom-up) as a top-down RGBA EXR of the given channel type.
bool write_exr_any(const char *fn, const std::string &path, const ImageF &img,
                   Imf::PixelType type, std::string *err)
{
    std::string why;
    if (!image_ok(img, &why)) {
        set_err(err, fail_msg(fn, path, why));
        return false;
    }
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
            std::memcpy(&fbuf[(size_t)4 * w * (h - 1 - y)], &img.rgba[(size_t)4 * w * y],
                        sizeof(float) * 4 * w);
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
    if (!file.open(&why)) {
        set_err(err, fail_msg(fn, path, why));
        return false;
    }
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
        set_err(err, fail_msg(fn, path, os.failed() ? os.reason() : std::string(e.what())));
        return false;
    }
    if (os.failed()) {  // an error OpenEXR swallowed in ~OutputFile
        set_err(err, fail_msg(fn, path, os.reason()));
        return false;
    }
    if (!file.commit(&why)) {
        set_err(err, fail_msg(fn, path, why));
        return false;
    }
    return true;
}

// ------------------------------------------------------------------ PNG ---

// Error context shared with the libpng callbacks.
struct PngCtx {
    char msg[256];
};

void png_error_cb(png_structp png, png_const_charp msg)
{
    PngCtx *ctx = static_cast<PngCtx *>(png_get_error_ptr(png));
    if (ctx) std::snprintf(ctx->msg, sizeof ctx->msg, "%s", msg ? msg : "libpng error");
    png_longjmp(png, 1);
}

void png_warning_cb(png_structp, png_const_charp) {}

// Read callback with a clearer message than libpng's "Read Error".
void png_read_cb(png_structp png, png_bytep data, size_t length)
{
    FILE *fp = static_cast<FILE *>(png_get_io_ptr(png));
    if (std::fread(data, 1, length, fp) != length)
        png_error(png, std::feof(fp) ? "unexpected end of file (truncated?)" : "read error");
}

enum PngChunk { kChunkNone, kChunkSRGB, kChunkGamma22 };

// Writes an 8-bit RGBA PNG from top-down row pointers.  C-style on purpose:
// no C++ object may be live in a frame that png_longjmp() unwinds.
bool png_write_c(FILE *fp, int w, int h, png_bytep *rows, PngChunk chunk, PngCtx *ctx)
{
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, ctx, png_error_cb, png_warning_cb);
    if (!png) {
        std::snprintf(ctx->msg, sizeof ctx->msg, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        std::snprintf(ctx->msg, sizeof ctx->msg, "out of memory");
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
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

// Decodes any PNG to RGBA 8/16-bit.  C-style for the same reason as above.
bool png_read_c(FILE *fp, PngRaw *raw, PngCtx *ctx)
{
    raw->pixels = nullptr;
    raw->rows = nullptr;
    unsigned char sig[8];
    if (std::fread(sig, 1, 8, fp) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        std::snprintf(ctx->msg, sizeof ctx->msg, "not a PNG file (bad signature)");
        return false;
    }
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, ctx, png_error_cb, png_warning_cb);
    if (!png) {
        std::snprintf(ctx->msg, sizeof ctx->msg, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        std::snprintf(ctx->msg, sizeof ctx->msg, "out of memory");
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::free(raw->pixels);
        std::free(raw->rows);
        raw->pixels = nullptr;
        raw->rows = nullptr;
        return false;
    }
    png_set_read_fn(png, fp, png_read_cb);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);

    raw->w = png_get_image_width(png, info);
    raw->h = png_get_image_height(png, info);
    if ((long long)raw->w * (long long)raw->h > kMaxPixels) png_error(png, "image too large");

    const int color_type = png_get_color_type(png, info);
    const int bit_depth = png_get_bit_depth(png, info);
    const bool has_trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (has_trns) png_set_tRNS_to_alpha(png);
    if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    if (!(color_type & PNG_COLOR_MASK_ALPHA) && !has_trns)
        png_set_add_alpha(png, 0xffff, PNG_FILLER_AFTER);
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

// Transfer functions, evaluated in double.  Inputs are in [0,1].
double srgb_encode(double v)
{
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}
double srgb_decode(double v)
{
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double encode_value(double v, Encode enc)
{
    switch (enc) {
    case Encode::SRGB: return srgb_encode(v);
    case Encode::Gamma22: return std::pow(v, 1.0 / 2.2);
    case Encode::Linear: break;
    }
    return v;
}
double decode_value(double v, Encode enc)
{
    switch (enc) {
    case Encode::SRGB: return srgb_decode(v);
    case Encode::Gamma22: return std::pow(v, 2.2);
    case Encode::Linear: break;
    }
    return v;
}

// Float -> 8-bit code: NaN -> 0, clamp to [0,1] (so -Inf -> 0, +Inf -> 1),
// encode, round to nearest.
uint8_t quantize(float f, Encode enc)
{
    double v = std::isnan(f) ? 0.0 : std::min(1.0, std::max(0.0, (double)f));
    v = std::min(1.0, std::max(0.0, encode_value(v, enc)));
    return (uint8_t)(v * 255.0 + 0.5);
}

// Writes top-down 8-bit RGBA rows atomically.
bool write_png_rows(const char *fn, const std::string &path, int w, int h, png_bytep *rows,
                    PngChunk chunk, std::string *err)
{
    std::string why;
    AtomicFile file(path);
    if (!file.open(&why)) {
        set_err(err, fail_msg(fn, path, why));
        return false;
    }
    PngCtx ctx;
    ctx.msg[0] = '\0';
    if (!png_write_c(file.fp(), w, h, rows, chunk, &ctx)) {
        set_err(err, fail_msg(fn, path, std::string("libpng: ") + ctx.msg));
        return false;
    }
    if (!file.commit(&why)) {
        set_err(err, fail_msg(fn, path, why));
        return false;
    }
    return true;
}

// ------------------------------------------------------------- Radiance ---

// Reads one header line starting at pos (without the '\n'); false at EOF.
bool next_line(const std::vector<unsigned char> &d, size_t *pos, std::string *line)
{
    if (*pos >= d.size()) return false;
    size_t end = *pos;
    while (end < d.size() && d[end] != '\n') ++end;
    if (end >= d.size()) return false;  // header lines must be terminated
    line->assign(reinterpret_cast<const char *>(&d[*pos]), end - *pos);
    while (!line->empty() && (line->back() == '\r' || line->back() == ' ' || line->back() == '\t'))
        line->pop_back();
    *pos = end + 1;
    return true;
}

// Decodes one RGBE scanline of w pixels into scan[4*w].
bool hdr_scanline(const std::vector<unsigned char> &d, size_t *pos, int w, unsigned char *scan,
                  std::string *why)
{
    const size_t size = d.size();
    size_t p = *pos;
    static const char kTruncated[] = "unexpected end of file in pixel data (truncated?)";

    // New-style RLE: marker 2,2,hi,lo then four run-length coded planes.
    if (w >= 8 && w <= 0x7fff && p + 4 <= size && d[p] == 2 && d[p + 1] == 2 &&
        !(d[p + 2] & 0x80)) {
        if (((int)d[p + 2] << 8 | d[p + 3]) != w) {
            *why = "corrupt pixel data (scanline length mismatch)";
            return false;
        }
        p += 4;
        for (int c = 0; c < 4; ++c) {
            int x = 0;
            while (x < w) {
                if (p >= size) {
                    *why = kTruncated;
                    return false;
                }
                int count = d[p++];
                if (count > 128) {  // run of one value
                    count -= 128;
                    if (x + count > w) {
                        *why = "corrupt pixel data (run overflows scanline)";
                        return false;
                    }
                    if (p >= size) {
                        *why = kTruncated;
                        return false;
                    }
                    const unsigned char v = d[p++];
                    for (int i = 0; i < count; ++i) scan[4 * (x++) + c] = v;
                } else {  // literal bytes
                    if (count == 0 || x + count > w) {
                        *why = "corrupt pixel data (bad literal count)";
                        return false;
                    }
                    if (p + (size_t)count > size) {
                        *why = kTruncated;
                        return false;
                    }
                    for (int i = 0; i < count; ++i) scan[4 * (x++) + c] = d[p++];
                }
            }
        }
        *pos = p;
        return true;
    }

    // Flat pixels, possibly with old-style runs (1,1,1,n repeats the previous
    // pixel n << shift times; consecutive run pixels shift by 8 more bits).
    int x = 0, shift = 0;
    while (x < w) {
        if (p + 4 > size) {
            *why = kTruncated;
            return false;
        }
        const unsigned char *q = &d[p];
        p += 4;
        if (q[0] == 1 && q[1] == 1 && q[2] == 1) {
            if (x == 0 || shift > 16) {
                *why = "corrupt pixel data (bad old-style run)";
                return false;
            }
            const long count = (long)q[3] << shift;
            if (x + count > w) {
                *why = "corrupt pixel data (run overflows scanline)";
                return false;
            }
            for (long i = 0; i < count; ++i, ++x) std::memcpy(&scan[4 * x], &scan[4 * (x - 1)], 4);
            shift += 8;
        } else {
            std::memcpy(&scan[4 * x], q, 4);
            ++x;
            shift = 0;
        }
    }
    *pos = p;
    return true;
}

bool read_hdr_impl(const std::string &path, ImageF *out, std::string *why)
{
    std::vector<unsigned char> d;
    if (!slurp(path, &d, why)) return false;

    size_t pos = 0;
    std::string line;
    if (!next_line(d, &pos, &line) || line.compare(0, 2, "#?") != 0) {
        *why = "not a Radiance HDR file (missing #? signature)";
        return false;
    }
    for (;;) {  // header variables up to the blank line
        if (!next_line(d, &pos, &line)) {
            *why = "truncated header";
            return false;
        }
        if (line.empty()) break;
        if (line.compare(0, 7, "FORMAT=") == 0 && line != "FORMAT=32-bit_rle_rgbe") {
            *why = "unsupported " + line + " (only 32-bit_rle_rgbe)";
            return false;
        }
    }
    if (!next_line(d, &pos, &line)) {
        *why = "missing resolution line";
        return false;
    }
    char ya[3] = {0}, xa[3] = {0};
    int h = 0, w = 0, consumed = 0;
    if (std::sscanf(line.c_str(), "%2s %d %2s %d%n", ya, &h, xa, &w, &consumed) != 4 ||
        (size_t)consumed != line.size()) {
        *why = "bad resolution line '" + line + "'";
        return false;
    }
    const bool top_down = std::strcmp(ya, "-Y") == 0;
    if ((!top_down && std::strcmp(ya, "+Y") != 0) || std::strcmp(xa, "+X") != 0) {
        *why = "unsupported orientation '" + line + "' (need -Y/+Y h +X w)";
        return false;
    }
    if (w <= 0 || h <= 0 || (long long)w * h > kMaxPixels) {
        *why = "bad image size in '" + line + "'";
        return false;
    }

    ImageF img;
    img.w = w;
    img.h = h;
    img.rgba.resize((size_t)4 * w * h);
    std::vector<unsigned char> scan((size_t)4 * w);
    for (int i = 0; i < h; ++i) {
        if (!hdr_scanline(d, &pos, w, scan.data(), why)) {
            *why += " at scanline " + std::to_string(i);
            return false;
        }
        const int row = top_down ? h - 1 - i : i;  // ImageF row 0 = bottom
        float *dst = &img.rgba[(size_t)4 * w * row];
        for (int x = 0; x < w; ++x) {
            const unsigned char *e = &scan[4 * x];
            // m * 2^(e-136) is exact in float for every 8-bit m and e in 1..255.
            const float scale = e[3] ? std::ldexp(1.0f, (int)e[3] - 136) : 0.0f;
            dst[4 * x + 0] = e[0] * scale;
            dst[4 * x + 1] = e[1] * scale;
            dst[4 * x + 2] = e[2] * scale;
            dst[4 * x + 3] = 1.0f;
        }
    }
    *out = std::move(img);
    return true;
}

// ----------------------------------------------------------- diff ramp ---

// Piecewise-linear ramp: dark blue, blue, cyan, green, yellow, red.
void ramp_colour(float t, float rgb[3])
{
    static const float stops[6][3] = {{0, 0, 0.5f}, {0, 0, 1}, {0, 1, 1},
                                      {0, 1, 0},    {1, 1, 0}, {1, 0, 0}};
    t = std::min(1.0f, std::max(0.0f, t)) * 5.0f;
    const int i = std::min(4, (int)t);
    const float f = t - (float)i;
    for (int c = 0; c < 3; ++c) rgb[c] = stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f;
}

}  // namespace

// ==================================================================== API ===

bool write_exr(const std::string &path, const ImageF &img, std::string *err)
{
    return write_exr_any("write_exr", path, img, Imf::FLOAT, err);
}

bool write_exr_half(const std::string &path, const ImageF &img, std::string *err)
{
    return write_exr_any("write_exr_half", path, img, Imf::HALF, err);
}

bool read_exr(const std::string &path, ImageF *out, std::string *err)
{
    static const char fn[] = "read_exr";
    try {
        Imf::InputFile in(path.c_str());
        const Imf::Header &header = in.header();
        const Imath::Box2i dw = header.dataWindow();
        const long long w = (long long)dw.max.x - dw.min.x + 1;
        const long long h = (long long)dw.max.y - dw.min.y + 1;
        if (w <= 0 || h <= 0 || w * h > kMaxPixels) {
            set_err(err, fail_msg(fn, path, "bad or too large data window"));
            return false;
        }
        static const char *const names[4] = {"R", "G", "B", "A"};
        bool present[4];
        for (int c = 0; c < 4; ++c) {
            const Imf::Channel *ch = header.channels().findChannel(names[c]);
            present[c] = ch != nullptr;
            if (ch && (ch->xSampling != 1 || ch->ySampling != 1)) {
                set_err(err, fail_msg(fn, path, std::string("channel ") + names[c] +
                                                    " is subsampled (unsupported)"));
                return false;
            }
        }
        if (!present[0] || !present[1] || !present[2]) {
            std::string found;
            for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
                found += std::string(found.empty() ? "" : ", ") + it.name();
            set_err(err, fail_msg(fn, path, "no R, G, B channels (channels: " +
                                                (found.empty() ? "none" : found) + ")"));
            return false;
        }
        if (!in.isComplete()) {
            set_err(err, fail_msg(fn, path, "file is incomplete (truncated?)"));
            return false;
        }

        // Read top-down, then flip to ImageF's bottom-up order.
        std::vector<float> buf((size_t)4 * w * h, 1.0f);
        Imf::FrameBuffer fb;
        for (int c = 0; c < 4; ++c)
            if (present[c])
                fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &buf[c], dw, 4 * sizeof(float),
                                                     4 * sizeof(float) * (size_t)w));
        in.setFrameBuffer(fb);
        in.readPixels(dw.min.y, dw.max.y);

        ImageF img;
        img.w = (int)w;
        img.h = (int)h;
        img.rgba.resize(buf.size());
        for (long long y = 0; y < h; ++y)
            std::memcpy(&img.rgba[(size_t)(4 * w * (h - 1 - y))], &buf[(size_t)(4 * w * y)],
                        sizeof(float) * 4 * (size_t)w);
        *out = std::move(img);
        return true;
    } catch (const std::exception &e) {
        set_err(err, fail_msg(fn, path, e.what()));
    } catch (...) {
        set_err(err, fail_msg(fn, path, "unknown error"));
    }
    return false;
}

bool write_png(const std::string &path, const ImageF &img, Encode enc, std::string *err)
{
    static const char fn[] = "write_png";
    std::string why;
    if (!image_ok(img, &why)) {
        set_err(err, fail_msg(fn, path, why));
        return false;
    }
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
    const PngChunk chunk = enc == Encode::SRGB      ? kChunkSRGB
                           : enc == Encode::Gamma22 ? kChunkGamma22
                                                    : kChunkNone;
    return write_png_rows(fn, path, w, h, rows.data(), chunk, err);
}

bool write_png_rgba8(const std::string &path, int w, int h,
                     const std::vector<uint8_t> &rgba_bottom_up, std::string *err)
{
    static const char fn[] = "write_png_rgba8";
    if (w <= 0 || h <= 0 || (long long)w * h > kMaxPixels) {
        set_err(err, fail_msg(fn, path, "invalid image size " + std::to_string(w) + "x" +
                                            std::to_string(h)));
        return false;
    }
    if (rgba_bottom_up.size() != (size_t)4 * w * h) {
        set_err(err, fail_msg(fn, path, "pixel buffer holds " +
                                            std::to_string(rgba_bottom_up.size()) +
                                            " bytes, expected " + std::to_string((size_t)4 * w * h)));
        return false;
    }
    // libpng copies each row before filtering, so it never writes through
    // these pointers; the const_cast only satisfies its non-const signature.
    std::vector<png_bytep> rows(h);
    for (int y = 0; y < h; ++y)
        rows[y] = const_cast<png_bytep>(&rgba_bottom_up[(size_t)4 * w * (h - 1 - y)]);
    return write_png_rows(fn, path, w, h, rows.data(), kChunkNone, err);
}

bool read_png(const std::string &path, ImageF *out, Encode decode, std::string *err)
{
    static const char fn[] = "read_png";
    FILE *fp = std::fopen(path.c_str(), "rb");
    if (!fp) {
        set_err(err, fail_msg(fn, path, "cannot open: " + errno_text(errno)));
        return false;
    }
    PngCtx ctx;
    ctx.msg[0] = '\0';
    PngRaw raw;
    const bool ok = png_read_c(fp, &raw, &ctx);
    std::fclose(fp);
    if (!ok) {
        set_err(err, fail_msg(fn, path, ctx.msg));
        return false;
    }

    const int w = (int)raw.w, h = (int)raw.h;
    const bool wide = raw.depth == 16;
    const double maxcode = wide ? 65535.0 : 255.0;
    float lut[256];  // 8-bit decode table for colour channels
    for (int i = 0; i < 256; ++i) lut[i] = (float)decode_value(i / 255.0, decode);

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
                dst[i] = (float)(alpha ? v : decode_value(v, decode));
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

uint32_t ulp_distance(float a, float b)
{
    const uint32_t ua = float_bits(a), ub = float_bits(b);
    if (ua == ub) return 0;
    if (bits_nan(ua) || bits_nan(ub)) return UINT32_MAX;
    // Ordered position: sign-magnitude to a signed line on which +0 and -0
    // coincide at 0.
    auto position = [](uint32_t u) -> int64_t {
        const int64_t mag = (int64_t)(u & 0x7fffffffu);
        return (u & 0x80000000u) ? -mag : mag;
    };
    const int64_t d = position(ua) - position(ub);
    const uint64_t ad = (uint64_t)(d < 0 ? -d : d);  // at most 2 * 0x7f800000
    return ad > UINT32_MAX ? UINT32_MAX : (uint32_t)ad;
}

ImageF diff_image(const ImageF &a, const ImageF &b, DiffStats *stats)
{
    DiffStats st;
    ImageF out;
    std::string why;
    if (!image_ok(a, &why) || !image_ok(b, &why) || a.w != b.w || a.h != b.h) {
        if (stats) *stats = st;
        return out;
    }
    out.w = a.w;
    out.h = a.h;
    out.rgba.assign(a.rgba.size(), 0.0f);
    st.pixels = (long)a.w * a.h;
    for (int y = 0; y < a.h; ++y) {
        for (int x = 0; x < a.w; ++x) {
            const size_t i = (size_t)4 * ((size_t)y * a.w + x);
            uint32_t worst = 0;
            bool nonfinite = false;
            for (int c = 0; c < 4; ++c) {
                const float fa = a.rgba[i + c], fb = b.rgba[i + c];
                const uint32_t ua = float_bits(fa), ub = float_bits(fb);
                if (ua == ub) continue;
                worst = std::max(worst, ulp_distance(fa, fb));
                if (bits_finite(ua) && bits_finite(ub))
                    st.max_abs = std::max(st.max_abs, std::fabs((double)fa - (double)fb));
                else
                    nonfinite = true;
            }
            float *o = &out.rgba[i];
            o[3] = 1.0f;
            if (worst == 0 && !nonfinite) continue;  // bit-identical: black
            ++st.mismatched_pixels;
            if (worst > st.max_ulp) {
                st.max_ulp = worst;
                st.worst_x = x;
                st.worst_y = y;
            }
            if (nonfinite) {
                o[0] = 1.0f;
                o[1] = 0.0f;
                o[2] = 1.0f;
            } else {
                ramp_colour((float)(std::log2((double)worst) / 20.0), o);
            }
        }
    }
    if (stats) *stats = st;
    return out;
}

bool read_hdr(const std::string &path, ImageF *out, std::string *err)
{
    std::string why;
    try {
        if (read_hdr_impl(path, out, &why)) return true;
    } catch (const std::exception &e) {  // e.g. std::bad_alloc
        why = e.what();
    }
    set_err(err, fail_msg("read_hdr", path, why));
    return false;
}

ImageF hstack(const std::vector<const ImageF *> &imgs, int gap_px, float gap_value)
{
    ImageF out;
    if (imgs.empty() || gap_px < 0) return out;
    std::string why;
    long long total = 0;
    for (const ImageF *im : imgs) {
        if (!im || !image_ok(*im, &why) || im->h != imgs[0]->h) return out;
        total += im->w;
    }
    total += (long long)gap_px * (long long)(imgs.size() - 1);
    const int h = imgs[0]->h;
    if (total > INT32_MAX || total * h > kMaxPixels) return out;

    out.w = (int)total;
    out.h = h;
    out.rgba.resize((size_t)4 * out.w * h);
    for (size_t p = 0; p < out.rgba.size(); p += 4) {
        out.rgba[p + 0] = out.rgba[p + 1] = out.rgba[p + 2] = gap_value;
        out.rgba[p + 3] = 1.0f;
    }
    int x0 = 0;
    for (const ImageF *im : imgs) {
        for (int y = 0; y < h; ++y)
            std::memcpy(&out.rgba[(size_t)4 * ((size_t)y * out.w + x0)],
                        &im->rgba[(size_t)4 * (size_t)y * im->w], sizeof(float) * 4 * im->w);
        x0 += im->w + gap_px;
    }
    return out;
}

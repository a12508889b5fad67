// tiershade io: 8-bit PNG image files. Writers write atomically (io/atomic_file.h); readers and
// writers flip between the file's top-down rows and ImageF's bottom-up rows (base/image.h).
// Failures fill *err (may be null) with "<function>: '<path>': <reason>"; nothing throws.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/image.h"

// Transfer function applied to colour channels (alpha is always linear).
//   Linear  : stored code = value             (no colour chunk written)
//   SRGB    : IEC 61966-2-1 piecewise curve   (sRGB chunk written; base/srgb.h)
//   Gamma22 : stored code = value^(1/2.2)     (gAMA 1/2.2 chunk written)
enum class Encode { Linear, SRGB, Gamma22 };

// 8-bit RGBA. Each channel is sanitised first (NaN -> 0, -Inf -> 0, +Inf -> 1, then clamped
// to [0,1]), encoded in double, and rounded to the nearest code.
bool write_png(const std::string &path, const ImageF &img, Encode enc, std::string *err);

// Writes raw 8-bit RGBA (4*w*h bytes, rows bottom-up as glReadPixels gives them) unchanged.
// No colour chunk is written.
bool write_png_rgba8(const std::string &path, int w, int h, const std::vector<uint8_t> &rgba_bottom_up,
                     std::string *err);

// Reads any PNG (grey, grey+alpha, palette, RGB, RGBA; 1..16 bits). Stored codes are
// normalised to [0,1] and decoded with `decode` (the inverse of the Encode curve, applied to
// colour channels only); file colour chunks are ignored. Images without alpha read as A = 1
// (tRNS is honoured).
bool read_png(const std::string &path, ImageF *out, Encode decode, std::string *err);

// True when bytes start with the PNG signature.
bool is_png(const unsigned char *bytes, size_t size);

// Decodes PNG bytes in memory (a glTF texture) to 8- or 16-bit RGBA (*bits), top-down rows,
// 16-bit samples in little-endian order: what stb_image's stbi_load(_16)_from_memory with 4
// channels gives (palette and grey expanded, tRNS as alpha, other alpha 1, colour chunks
// ignored). The header's size is checked against kMaxImagePixels and the memory limit (24 bytes
// a pixel: these rows and the caller's float copy) before any pixel memory is allocated, and
// libpng inflates no more than the rows hold (a zip-bomb IDAT cannot grow a buffer). False with
// *why (libpng's reason) otherwise.
bool decode_png_rgba(const unsigned char *bytes, size_t size, std::vector<unsigned char> *out, int *w, int *h, int *bits,
                     std::string *why);

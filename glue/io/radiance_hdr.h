// tiershade io: radiance .hdr (RGBE) light probes, decoded by stb_image's stbi_loadf after
// this reader has checked the file. Failures fill *err (may be null) with
// "read_hdr: '<path>': <reason>"; nothing throws.
#pragma once
#include <string>

#include "base/image.h"

// Reads a Radiance .hdr: signature #?RADIANCE or #?RGBE, FORMAT=32-bit_rle_rgbe, resolution
// "-Y h +X w" or "+Y h +X w", flat or new-style run-length scanlines. Values are stb_image's:
// mantissa * 2^(e - 136), e == 0 -> 0; the EXPOSURE header is ignored; alpha is 1. Rows are
// bottom-up (base/image.h).
// Refused before anything is decoded: files that are not regular files, a malformed header,
// w * h above kMaxImagePixels, pixel data too short for the size the header claims (so a
// corrupt header cannot make stb allocate gigabytes), and old-style run-length pixels
// (1,1,1,n; Radiance before 2.0), which stb_image would read as colours. A file that ends
// inside its pixel data is an error, not a partly black image.
bool read_hdr(const std::string &path, ImageF *out, std::string *err);

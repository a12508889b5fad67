// tiershade io: openEXR image files. Writers write atomically (io/atomic_file.h); readers and
// writers flip between the file's top-down rows and ImageF's bottom-up rows (base/image.h).
// Failures fill *err (may be null) with "<function>: '<path>': <reason>"; nothing throws.
#pragma once
#include <string>

#include "base/image.h"

// RGBA FLOAT (32-bit) channels, ZIP compression. Lossless: every bit of every value
// (denormals, -0, Inf, NaN payloads) survives a write_exr/read_exr trip.
bool write_exr(const std::string &path, const ImageF &img, std::string *err);

// RGBA HALF channels, ZIP compression. Values are rounded to the nearest half
// (round-to-nearest-even); magnitudes above 65504 become +-Inf.
bool write_exr_half(const std::string &path, const ImageF &img, std::string *err);

// Reads part 0 (level 0 if tiled) of a flat scanline or tiled EXR that has R, G and B channels
// (HALF, FLOAT or UINT; full resolution), through OpenEXR's C core with every allocation within
// the memory limit (io/memory_limit.h; docs/reliability.md). A missing A channel reads as 1.
// Missing, truncated, corrupt or over-limit files fail with a message naming the file.
bool read_exr(const std::string &path, ImageF *out, std::string *err);

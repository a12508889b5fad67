// ============================================================================
// tiershade — glue/io/image_io.h
//
// Image file I/O and image comparison helpers for the tiershade renderers
// (GLSL on Mesa llvmpipe and the bit-exact C reference).
//
//   * OpenEXR  : RGBA 32-bit float (bit-exact) and RGBA half writers, reader.
//   * PNG      : 8-bit RGBA writer with Linear / sRGB / gamma 2.2 encoding,
//                raw RGBA8 writer, reader with matching decoding.
//   * Radiance : .hdr (RGBE) reader for the light probes.
//   * Diffing  : per-channel ULP distance and a false-colour difference image.
//   * hstack   : side-by-side montage of equal-height images.
//
// Conventions
//   * ImageF rows are bottom-up, exactly as glReadPixels returns them:
//     row 0 is the BOTTOM row.  Files are always stored top-down, so every
//     writer flips and every reader flips back.  pixel (x, y) is at
//     rgba[4 * (y * w + x) + c].
//   * Every writer writes "<path>.tmp.<pid>" and rename()s it over <path>
//     only after everything was written and flushed, so a failed write never
//     leaves a partial or stale temporary file behind.
//   * Functions returning bool report failure with a message in *err (err may
//     be null) that names the file concerned and the reason.  Nothing throws.
// ============================================================================
#ifndef TIERSHADE_GLUE_IMAGE_IO_H
#define TIERSHADE_GLUE_IMAGE_IO_H

#include <cstdint>
#include <string>
#include <vector>

// A float RGBA image, row 0 = bottom row as OpenGL reads it back
// (glReadPixels); writers flip so files are top-down.
struct ImageF {
    int w = 0, h = 0;
    std::vector<float> rgba;  // 4 * w * h floats, RGBA interleaved, bottom-up rows
};

// ---------------------------------------------------------------- OpenEXR ---

// RGBA FLOAT (32-bit) channels, ZIP compression.  Lossless: every bit of every
// value (denormals, -0, Inf, NaN payloads) survives a write_exr/read_exr trip.
bool write_exr(const std::string &path, const ImageF &img, std::string *err);

// RGBA HALF channels, ZIP compression.  Values are rounded to the nearest
// half (round-to-nearest-even); magnitudes above 65504 become +-Inf.
bool write_exr_half(const std::string &path, const ImageF &img, std::string *err);

// Reads any scanline or tiled single-part EXR that has R, G and B channels
// (HALF, FLOAT or UINT; full resolution).  A missing A channel reads as 1.
// Missing, truncated or corrupt files fail with a message naming the file.
bool read_exr(const std::string &path, ImageF *out, std::string *err);

// -------------------------------------------------------------------- PNG ---

// Transfer function applied to colour channels (alpha is always linear).
//   Linear  : stored code = value             (no colour chunk written)
//   SRGB    : IEC 61966-2-1 piecewise curve   (sRGB chunk written)
//   Gamma22 : stored code = value^(1/2.2)     (gAMA 1/2.2 chunk written)
enum class Encode { Linear, SRGB, Gamma22 };

// 8-bit RGBA.  Each channel is sanitised first (NaN -> 0, -Inf -> 0,
// +Inf -> 1, then clamped to [0,1]), encoded, and rounded to the nearest code.
bool write_png(const std::string &path, const ImageF &img, Encode enc, std::string *err);

// Writes raw 8-bit RGBA (4*w*h bytes, rows bottom-up as glReadPixels gives
// them) unchanged.  No colour chunk is written.
bool write_png_rgba8(const std::string &path, int w, int h,
                     const std::vector<uint8_t> &rgba_bottom_up, std::string *err);

// Reads any PNG (grey, grey+alpha, palette, RGB, RGBA; 1..16 bits).  Stored
// codes are normalised to [0,1] and decoded with `decode` (the inverse of the
// Encode curve, applied to colour channels only); file colour chunks are
// ignored.  Images without alpha read as A = 1 (tRNS is honoured).
bool read_png(const std::string &path, ImageF *out, Encode decode, std::string *err);

// ---------------------------------------------------------------- Diffing ---

// ULP distance between two floats: the difference of their positions in the
// ordered sequence of float values.  Conventions:
//   * bit-identical values (including identical NaNs) are 0 apart;
//   * +0 and -0 are 0 apart (they share one position), so the smallest
//     positive and negative denormals are 2 apart;
//   * +-Inf sit one step beyond +-FLT_MAX;
//   * a NaN against anything not bit-identical to it is UINT32_MAX.
uint32_t ulp_distance(float a, float b);

struct DiffStats {
    long pixels = 0;             // w * h compared
    long mismatched_pixels = 0;  // pixels where any channel is not bit-identical
    uint32_t max_ulp = 0;        // largest ulp_distance over all channels
    double max_abs = 0;          // largest |a - b| over channel pairs that are both finite
    int worst_x = -1, worst_y = -1;  // first pixel reaching max_ulp (ImageF coords,
                                     // y = 0 bottom); -1 when the images are bit-identical
};

// False-colour visualisation of a vs b, same size, RGBA in [0,1] (write it
// with Encode::Linear).  Per pixel, with d = largest channel ulp_distance:
//   * all four channels bit-identical (even if NaN/Inf)  -> black
//   * otherwise a NaN or Inf in either input            -> magenta (1,0,1)
//   * otherwise a log2 ramp: 1 ULP dark blue (0,0,0.5) -> blue -> cyan ->
//     green -> yellow -> red (1,0,0) at >= 2^20 ULP.
// Alpha is 1.  On a size mismatch (or a malformed image) the result is an
// empty image and *stats is reset to its defaults.  stats may be null.
ImageF diff_image(const ImageF &a, const ImageF &b, DiffStats *stats);

// -------------------------------------------------------------- Radiance ---

// Reads a Radiance .hdr (FORMAT=32-bit_rle_rgbe; flat, old-style RLE or
// new-style RLE scanlines; "-Y h +X w" or "+Y h +X w" orientation).
// Conversion follows stb_image / Probulator: value = mantissa * 2^(e - 136),
// e == 0 -> 0; the EXPOSURE header is ignored.  Alpha is 1.
bool read_hdr(const std::string &path, ImageF *out, std::string *err);

// ---------------------------------------------------------------- Montage ---

// Places the images left to right with gap_px columns between neighbours; the
// gap pixels are (gap_value, gap_value, gap_value, 1).  All images must be
// non-null, well-formed and of equal height, and gap_px >= 0; otherwise (or
// for an empty list) the result is an empty image.
ImageF hstack(const std::vector<const ImageF *> &imgs, int gap_px, float gap_value);

#endif  // TIERSHADE_GLUE_IMAGE_IO_H

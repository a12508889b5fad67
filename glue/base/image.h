// tiershade base: imageF, the float RGBA image that renderers, diffs and image files share,
// its consistency check, and the side-by-side montage of images.
#pragma once
#include <string>
#include <vector>

// A float RGBA image. Rows are bottom-up, exactly as glReadPixels returns them: row 0 is the
// BOTTOM row, and pixel (x, y) is at rgba[4 * (y * w + x) + c]. Image files are top-down, so
// every writer flips and every reader flips back (io/exr.h, io/png.h, io/radiance_hdr.h).
struct ImageF {
  int w = 0, h = 0;
  std::vector<float> rgba;  // 4 * w * h floats, RGBA interleaved, bottom-up rows
};

// Largest image any reader or writer accepts, in pixels: 2^27 = 2 GiB of RGBA float. Protects
// against absurd sizes in corrupt headers.
constexpr long long kMaxImagePixels = 1LL << 27;

// True when img is self-consistent: 0 < w, h; w * h <= kMaxImagePixels; 4 * w * h floats.
// Otherwise *why says what is wrong.
bool image_ok(const ImageF &img, std::string *why);

// Places the images left to right with gap_px columns between neighbours; the gap pixels are
// (gap_value, gap_value, gap_value, 1). All images must be non-null, well-formed and of equal
// height, and gap_px >= 0; otherwise (or for an empty list) the result is an empty image.
ImageF hstack(const std::vector<const ImageF *> &imgs, int gap_px, float gap_value);

// tiershade base: the ImageF check and the montage (base/image.h).
#include "base/image.h"

#include <cstdint>
#include <cstring>

bool image_ok(const ImageF &img, std::string *why) {
  if (img.w <= 0 || img.h <= 0) {
    *why = "invalid image size " + std::to_string(img.w) + "x" + std::to_string(img.h);
    return false;
  }
  if (static_cast<long long>(img.w) * img.h > kMaxImagePixels) {
    *why = "image too large";
    return false;
  }
  const size_t need = static_cast<size_t>(4) * img.w * img.h;
  if (img.rgba.size() != need) {
    *why = "pixel buffer holds " + std::to_string(img.rgba.size()) + " floats, expected " + std::to_string(need);
    return false;
  }
  return true;
}

ImageF hstack(const std::vector<const ImageF *> &imgs, int gap_px, float gap_value) {
  ImageF out;
  if (imgs.empty() || gap_px < 0) return out;
  std::string why;
  long long total = 0;
  for (const ImageF *im : imgs) {
    if (!im || !image_ok(*im, &why) || im->h != imgs[0]->h) return out;
    total += im->w;
  }
  total += static_cast<long long>(gap_px) * static_cast<long long>(imgs.size() - 1);
  const int h = imgs[0]->h;
  if (total > INT32_MAX || total * h > kMaxImagePixels) return out;

  out.w = static_cast<int>(total);
  out.h = h;
  out.rgba.resize(static_cast<size_t>(4) * out.w * h);
  for (size_t p = 0; p < out.rgba.size(); p += 4) {
    out.rgba[p + 0] = out.rgba[p + 1] = out.rgba[p + 2] = gap_value;
    out.rgba[p + 3] = 1.0f;
  }
  int x0 = 0;
  for (const ImageF *im : imgs) {
    for (int y = 0; y < h; ++y)
      std::memcpy(&out.rgba[4 * (static_cast<size_t>(y) * out.w + x0)], &im->rgba[4 * static_cast<size_t>(y) * im->w],
                  sizeof(float) * 4 * im->w);
    x0 += im->w + gap_px;
  }
  return out;
}

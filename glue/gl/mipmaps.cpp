// tiershade gl: mip chains of 2D textures (see mipmaps.h).
#include "gl/mipmaps.h"

#include <algorithm>
#include <cmath>

int mip_level_count(int w, int h) {
  int n = 1;
  while (w > 1 || h > 1) {
    w = std::max(1, w >> 1);
    h = std::max(1, h >> 1);
    ++n;
  }
  return n;
}

namespace {

// One level down from src (sw x sh).
std::vector<float> reduce(const std::vector<float> &src, int sw, int sh, int dw, int dh, MipContent content) {
  std::vector<float> dst(static_cast<size_t>(dw) * dh * 4);
  for (int y = 0; y < dh; ++y)
    for (int x = 0; x < dw; ++x) {
      double acc[4] = {0, 0, 0, 0};
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const int sx = std::min(sw - 1, 2 * x + i), sy = std::min(sh - 1, 2 * y + j);
          const float *p = &src[(static_cast<size_t>(sy) * sw + sx) * 4];
          for (int c = 0; c < 4; ++c) acc[c] += content == MipContent::NormalMap && c < 3 ? 2.0 * p[c] - 1.0 : p[c];
        }
      float *q = &dst[(static_cast<size_t>(y) * dw + x) * 4];
      if (content == MipContent::NormalMap) {
        // The mean normal renormalised; a mean of opposite normals (length 0) keeps +Z.
        const double l = std::sqrt(acc[0] * acc[0] + acc[1] * acc[1] + acc[2] * acc[2]);
        const double n[3] = {l > 1e-12 ? acc[0] / l : 0.0, l > 1e-12 ? acc[1] / l : 0.0, l > 1e-12 ? acc[2] / l : 1.0};
        for (int c = 0; c < 3; ++c) q[c] = static_cast<float>(0.5 * n[c] + 0.5);
        q[3] = static_cast<float>(acc[3] / 4);
      } else {
        for (int c = 0; c < 4; ++c) q[c] = static_cast<float>(acc[c] / 4);
      }
    }
  return dst;
}

}  // namespace

void build_mip_chain(TextureDesc *t, MipContent content) {
  t->mips.clear();
  int w = t->w, h = t->h;
  const std::vector<float> *src = &t->rgba;
  const int n = mip_level_count(w, h);
  if (n > kMaxMipLevels) return;
  t->mips.reserve(static_cast<size_t>(n - 1));
  for (int k = 1; k < n; ++k) {
    const int dw = std::max(1, w >> 1), dh = std::max(1, h >> 1);
    t->mips.push_back(reduce(*src, w, h, dw, dh, content));
    src = &t->mips.back();
    w = dw;
    h = dh;
  }
}

// tiershade base: ULP distance and the false-colour difference image (base/image_diff.h).
#include "base/image_diff.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace {

uint32_t float_bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

bool bits_nan(uint32_t u) { return (u & 0x7fffffffu) > 0x7f800000u; }
bool bits_finite(uint32_t u) { return (u & 0x7f800000u) != 0x7f800000u; }

// Piecewise-linear ramp: dark blue, blue, cyan, green, yellow, red.
void ramp_colour(float t, float rgb[3]) {
  static const float stops[6][3] = {{0, 0, 0.5f}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  t = std::min(1.0f, std::max(0.0f, t)) * 5.0f;
  const int i = std::min(4, static_cast<int>(t));
  const float f = t - static_cast<float>(i);
  for (int c = 0; c < 3; ++c) rgb[c] = stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f;
}

}  // namespace

uint32_t ulp_distance(float a, float b) {
  const uint32_t ua = float_bits(a), ub = float_bits(b);
  if (ua == ub) return 0;
  if (bits_nan(ua) || bits_nan(ub)) return UINT32_MAX;
  // Ordered position: sign-magnitude to a signed line on which +0 and -0 coincide at 0.
  auto position = [](uint32_t u) -> int64_t {
    const int64_t mag = static_cast<int64_t>(u & 0x7fffffffu);
    return (u & 0x80000000u) ? -mag : mag;
  };
  const int64_t d = position(ua) - position(ub);
  const uint64_t ad = static_cast<uint64_t>(d < 0 ? -d : d);  // at most 2 * 0x7f800000
  return ad > UINT32_MAX ? UINT32_MAX : static_cast<uint32_t>(ad);
}

ImageF diff_image(const ImageF &a, const ImageF &b, DiffStats *stats) {
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
  st.pixels = static_cast<long>(a.w) * a.h;
  for (int y = 0; y < a.h; ++y) {
    for (int x = 0; x < a.w; ++x) {
      const size_t i = 4 * (static_cast<size_t>(y) * a.w + x);
      uint32_t worst = 0;
      bool nonfinite = false;
      for (int c = 0; c < 4; ++c) {
        const float fa = a.rgba[i + c], fb = b.rgba[i + c];
        const uint32_t ua = float_bits(fa), ub = float_bits(fb);
        if (ua == ub) continue;
        worst = std::max(worst, ulp_distance(fa, fb));
        if (bits_finite(ua) && bits_finite(ub))
          st.max_abs = std::max(st.max_abs, std::fabs(static_cast<double>(fa) - static_cast<double>(fb)));
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
        ramp_colour(static_cast<float>(std::log2(static_cast<double>(worst)) / 20.0), o);
      }
    }
  }
  if (stats) *stats = st;
  return out;
}

// tiershade families: input generators shared by the HDR families (see hdr_inputs.h).
#include "families/hdr_inputs.h"

#include <cmath>

#include "math/hdr_formats.h"

TextureDesc hdr_test_texture(Rng &r, const std::string &sampler, int w, int h, bool linear) {
  TextureDesc t = blank_texture(sampler, w, h, linear, false);
  for (size_t i = 0; i < t.rgba.size(); ++i) {
    float v;
    const uint32_t k = r.next() % 64;
    if (i % 4 == 3)
      v = 1.f;
    else if (k == 0)
      v = 0.f;
    else if (k == 1)
      v = 65504.f;
    else if (k == 2)
      v = 3.0e-6f;  // a half denormal
    else
      v = std::exp2(r.uniform(-10.f, 6.f));
    t.rgba[i] = ts_quantize_half(v);
  }
  return t;
}

ts_vec4f random_fragment_position(Rng &r, int w, int h) {
  if (r.next() % 2) {
    return ts_v4f(static_cast<float>(r.next() % static_cast<uint32_t>(w)) + 0.5f,
                  static_cast<float>(r.next() % static_cast<uint32_t>(h)) + 0.5f, 0.f, 0.f);
  }
  return ts_v4f(r.uniform(-1.f, static_cast<float>(w) + 1.f), r.uniform(-1.f, static_cast<float>(h) + 1.f), 0.f, 0.f);
}

ts_vec4f size_slot(int w, int h) {
  return ts_v4f(static_cast<float>(w), static_cast<float>(h), 1.0f / static_cast<float>(w),
                1.0f / static_cast<float>(h));
}

// tiershade color: 3D colour LUTs as GL textures and C sampler views (see lut_texture.h).
#include "color/lut_texture.h"

Lut3D identity_lut(int n) {
  Lut3D l;
  l.n = n;
  l.rgb.resize(static_cast<size_t>(n) * n * n * 3);
  const float s = 1.0f / static_cast<float>(n - 1);
  for (int b = 0; b < n; ++b)
    for (int g = 0; g < n; ++g)
      for (int r = 0; r < n; ++r) {
        float *p = l.at(r, g, b);
        p[0] = static_cast<float>(r) * s;
        p[1] = static_cast<float>(g) * s;
        p[2] = static_cast<float>(b) * s;
      }
  l.title = "identity";
  return l;
}

TextureDesc lut_volume_texture(const Lut3D &lut, const std::string &sampler, bool linear) {
  TextureDesc t;
  t.sampler = sampler;
  t.kind = TexKind::Tex3D;
  t.w = t.h = t.d = lut.n;
  t.linear = linear;
  t.repeat = false;
  const size_t texels = static_cast<size_t>(lut.n) * lut.n * lut.n;
  t.rgba.resize(texels * 4);
  for (size_t i = 0; i < texels; ++i) {  // the .cube order is the glTexImage3D order
    t.rgba[i * 4 + 0] = lut.rgb[i * 3 + 0];
    t.rgba[i * 4 + 1] = lut.rgb[i * 3 + 1];
    t.rgba[i * 4 + 2] = lut.rgb[i * 3 + 2];
    t.rgba[i * 4 + 3] = 1.f;
  }
  return t;
}

TextureDesc lut_atlas_texture(const Lut3D &lut, const std::string &sampler, bool linear) {
  const int n = lut.n;
  TextureDesc t;
  t.sampler = sampler;
  t.kind = TexKind::Tex2D;
  t.w = n * n;
  t.h = n;
  t.linear = linear;
  t.repeat = false;
  t.rgba.resize(static_cast<size_t>(t.w) * t.h * 4);
  for (int b = 0; b < n; ++b)
    for (int g = 0; g < n; ++g)
      for (int r = 0; r < n; ++r) {
        const float *src = lut.at(r, g, b);
        float *dst = &t.rgba[(static_cast<size_t>(g) * t.w + static_cast<size_t>(b) * n + r) * 4];
        dst[0] = src[0];
        dst[1] = src[1];
        dst[2] = src[2];
        dst[3] = 1.f;
      }
  return t;
}

ts_tex3d tex3d_of(const TextureDesc &t) {
  ts_tex3d x;
  x.w = t.w;
  x.h = t.h;
  x.d = t.d;
  x.texels = t.rgba.data();
  x.wrap_s = x.wrap_t = x.wrap_r = t.repeat ? TS_WRAP_REPEAT : TS_WRAP_CLAMP;
  x.filter = t.linear ? TS_FILTER_LINEAR : TS_FILTER_NEAREST;
  return x;
}

// tiershade tests: mip chains (glue/gl/mipmaps.h) and the C sampler's level of detail
// (c_ref/math/ts_sampler.h ts_mip_select, ts_texture2D_gradf) on cases with known answers: level
// counts and sizes, box means, renormalised normal maps, llvmpipe's piecewise-linear log2 at and
// between powers of two, and the levels and weights it gives. (GL against C with mipmaps on,
// pixel for pixel: tests/cli/test_render.sh "mipmaps", tests/unit/test_raster_exact.cpp.)
#include <cmath>
#include <string>
#include <vector>

#include "families/family.h"
#include "math/ts_interval.h"
#include "math/ts_sampler.h"
#include "gl/mipmaps.h"
#include "unit_check.h"

using unit_check::check;

namespace {

TextureDesc texture(int w, int h) {
  TextureDesc t;
  t.w = w;
  t.h = h;
  t.linear = true;
  t.repeat = true;
  t.rgba.assign(static_cast<size_t>(w) * h * 4, 0.f);
  return t;
}

void chain_shape() {
  check(mip_level_count(256, 64) == 9 && mip_level_count(1, 1) == 1 && mip_level_count(5, 3) == 3 &&
            mip_level_count(1, 1024) == 11,
        "mip chain: level counts (256x64: 9, 1x1: 1, 5x3: 3, 1x1024: 11)");
  TextureDesc t = texture(6, 3);
  build_mip_chain(&t, MipContent::Color);
  bool sizes = t.mips.size() == 2 && t.mips[0].size() == 3 * 1 * 4 && t.mips[1].size() == 1 * 1 * 4;
  check(sizes, "mip chain: 6x3 -> 3x1 -> 1x1 (max(1, size >> k), down to 1x1)",
        std::to_string(t.mips.size()) + " levels");
}

void box_means() {
  TextureDesc t = texture(4, 2);
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 4; ++c) t.rgba[i * 4 + c] = static_cast<float>(i * (c + 1));
  build_mip_chain(&t, MipContent::Color);
  // level 1 (2x1): texel 0 = mean of texels 0, 1, 4, 5; texel 1 = mean of 2, 3, 6, 7
  const float a = (0 + 1 + 4 + 5) / 4.f, b = (2 + 3 + 6 + 7) / 4.f;
  bool ok = t.mips.size() == 2;
  for (int c = 0; ok && c < 4; ++c)
    ok = t.mips[0][c] == a * (c + 1) && t.mips[0][4 + c] == b * (c + 1) && t.mips[1][c] == (a + b) / 2 * (c + 1);
  check(ok, "mip chain: colour levels are the 2x2 box means, channel by channel (alpha too)");
  TextureDesc o = texture(3, 3);  // an odd side drops its last column and row from the next level
  for (int i = 0; i < 9; ++i) o.rgba[i * 4] = static_cast<float>(i);
  build_mip_chain(&o, MipContent::Color);
  check(o.mips.size() == 1 && o.mips[0][0] == (0 + 1 + 3 + 4) / 4.f, "mip chain: 3x3 -> 1x1 from the 2x2 corner");
}

void normal_maps() {
  TextureDesc t = texture(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      // a bumpy field of unit normals, encoded 0.5 n + 0.5
      const double nx = 0.6 * std::sin(x * 1.3), ny = 0.5 * std::cos(y * 0.7 + x);
      const double nz = std::sqrt(std::max(0.0, 1 - nx * nx - ny * ny));
      float *p = &t.rgba[(y * 8 + x) * 4];
      p[0] = static_cast<float>(0.5 * nx + 0.5), p[1] = static_cast<float>(0.5 * ny + 0.5);
      p[2] = static_cast<float>(0.5 * nz + 0.5), p[3] = 1.f;
    }
  build_mip_chain(&t, MipContent::NormalMap);
  double worst = 0;
  for (const std::vector<float> &lv : t.mips)
    for (size_t i = 0; i < lv.size(); i += 4) {
      const double x = 2.0 * lv[i] - 1, y = 2.0 * lv[i + 1] - 1, z = 2.0 * lv[i + 2] - 1;
      worst = std::max(worst, std::fabs(std::sqrt(x * x + y * y + z * z) - 1));
    }
  // float storage of 0.5 n + 0.5 rounds each component by 2^-25: |length - 1| below 1e-6
  check(!t.mips.empty() && worst < 1e-6, "mip chain: a normal map's levels hold unit normals (renormalised)",
        "worst |length - 1| " + std::to_string(worst));
  TextureDesc plain = t;
  build_mip_chain(&plain, MipContent::Color);
  const double x = 2.0 * plain.mips.back()[0] - 1, y = 2.0 * plain.mips.back()[1] - 1, z = 2.0 * plain.mips.back()[2] - 1;
  check(std::sqrt(x * x + y * y + z * z) < 0.999, "mip chain: averaged without renormalising, the same normals shorten");
}

void lod() {
  check(ts_fast_log2f(1.f) == 0.f && ts_fast_log2f(4.f) == 2.f && ts_fast_log2f(3.f) == 1.5f &&
            ts_fast_log2f(0.75f) == -0.5f && ts_fast_log2f(0.f) == -127.f,
        "fast_log2: exact at powers of two, linear between (3 -> 1.5, 0.75 -> -0.5), 0 -> -127");
  TextureDesc d = texture(64, 16);
  for (size_t i = 0; i < d.rgba.size(); ++i) d.rgba[i] = static_cast<float>(i % 7) / 7.f;
  build_mip_chain(&d, MipContent::Color);
  d.mip_filter = TS_MIP_LINEAR;
  const ts_tex2d t = tex2d_of(d);
  int l0, l1;
  float w, l;
  // rho^2 = max((64 ds/dx)^2 + (16 dt/dx)^2, ...) in texels: 1 -> lod 0; 4 -> 1; 8 -> 0.5 * 3 = 1.5
  ts_mip_select(&t, ts_v4f(1.f / 64, 0, 0, 0), &l0, &l1, &w, &l);
  bool ok = l0 == 0 && l1 == 1 && w == 0.f && l == 0.f;
  ts_mip_select(&t, ts_v4f(2.f / 64, 0, 0, 0), &l0, &l1, &w, &l);
  ok = ok && l0 == 1 && l1 == 2 && w == 0.f && l == 1.f;
  ts_mip_select(&t, ts_v4f(2.f / 64, 0, 2.f / 16, 0), &l0, &l1, &w, &l);
  ok = ok && l0 == 1 && l1 == 2 && w == 0.5f && l == 1.5f;
  ts_mip_select(&t, ts_v4f(0, 0.5f / 64, 0, 0), &l0, &l1, &w, &l);  // magnified: level 0
  ok = ok && l0 == 0 && l1 == 0 && w == 0.f;
  ts_mip_select(&t, ts_v4f(1000.f, 0, 0, 0), &l0, &l1, &w, &l);  // past the last level (64x16: 7 levels)
  ok = ok && l0 == 6 && l1 == 6 && w == 0.f;
  check(ok, "level of detail (LINEAR mips): levels and weights at and between powers of two, clamped both ways");
  ts_tex2d n = t;
  n.mip_filter = TS_MIP_NEAREST;
  ts_mip_select(&n, ts_v4f(2.f / 64, 0, 2.f / 16, 0), &l0, &l1, &w, &l);  // rho^2 = 8: (130 - 126) >> 1 = 2
  bool nn = l0 == 2 && l1 == 2 && w == 0.f;
  ts_mip_select(&n, ts_v4f(1.5f / 64, 0, 0, 0), &l0, &l1, &w, &l);  // rho^2 = 2.25: (128 - 126) >> 1 = 1
  nn = nn && l0 == 1;
  check(nn, "level of detail (NEAREST mips): llvmpipe's ilog2_sqrt ((exponent - 126) >> 1)");
  // the sampled value: no derivatives = level 0; derivatives past the chain = the 1x1 level
  const ts_vec2f uv = ts_v2f(0.3f, 0.6f);
  const ts_vec4f g = ts_v4f(1000.f, 0, 0, 0);
  const ts_vec4f a = ts_texture2D_gradf(&t, uv, nullptr), b = ts_texture2Df(&t, uv);
  const ts_vec4f c = ts_texture2D_gradf(&t, uv, &g);
  const float *last = d.mips.back().data();
  check(a.x == b.x && a.w == b.w && c.x == last[0] && c.y == last[1] && c.z == last[2],
        "texture2D with derivatives: none -> level 0's lookup; beyond the chain -> the 1x1 level's texel");
}

// textureGrad (ts_sampler_grad.c): the pixel's own (dPdx, dPdy); an Inf/NaN rho^2 (overflowed or
// non-finite derivatives) samples level 0 on llvmpipe; the GLES 3.0 bound holds both answers where
// the spec allows them and only the last level where the exact rho reaches it.
void explicit_derivatives() {
  TextureDesc d = texture(64, 16);
  for (size_t i = 0; i < d.rgba.size(); ++i) d.rgba[i] = static_cast<float>(i % 7) / 7.f;
  build_mip_chain(&d, MipContent::Color);
  d.mip_filter = TS_MIP_LINEAR;
  const ts_tex2d t = tex2d_of(d);
  const ts_vec2f uv = ts_v2f(0.3f, 0.6f);
  const float *last = d.mips.back().data();
  const ts_tex2d l1 = ts_mip_level(&t, 1);
  // (dPdx, dPdy) = ((2/64, 0), (0, 0)): lambda 1 exactly -> level 1 alone
  const ts_vec4f a = ts_texture2DGradf(&t, uv, ts_v4f(2.f / 64, 0, 0, 0)), a1 = ts_texture2Df(&l1, uv);
  // dPdy carries it: ts_mip_select's (ds/dx, ds/dy, dt/dx, dt/dy) order is not GLSL's
  const ts_vec4f b = ts_texture2DGradf(&t, uv, ts_v4f(0, 0, 0, 2.f / 16));
  check(a.x == a1.x && a.y == a1.y && b.x == a1.x && b.w == a1.w,
        "textureGrad: lambda 1 from dPdx.s = 2/w or from dPdy.t = 2/h -> level 1's lookup");
  const ts_vec4f big = ts_texture2DGradf(&t, uv, ts_v4f(1000.f, 0, 0, 0));
  const ts_vec4f over = ts_texture2DGradf(&t, uv, ts_v4f(1e30f, 0, 0, 0)), l0 = ts_texture2Df(&t, uv);
  const ts_vec4f inf = ts_texture2DGradf(&t, uv, ts_v4f(0, 0, INFINITY, 0));
  const ts_vec4f nan = ts_texture2DGradf(&t, uv, ts_v4f(NAN, 0, 0, 0));
  check(big.x == last[0] && over.x == l0.x && over.w == l0.w && inf.y == l0.y && nan.z == l0.z,
        "textureGrad: 1000 -> the 1x1 level; 1e30 (rho^2 overflows), Inf, NaN -> level 0 (llvmpipe 22.3)");
  const ts_vec2iv uvi = ts_v2iv(ts_ivpoint(uv.x), ts_ivpoint(uv.y));
  const ts_vec4iv ib = ts_texture2DGradiv(&t, uvi, ts_v4f(1000.f, 0, 0, 0));
  const ts_vec4iv io = ts_texture2DGradiv(&t, uvi, ts_v4f(1e30f, 0, 0, 0));
  const ts_vec4iv ia = ts_texture2DGradiv(&t, uvi, ts_v4f(2.f / 64, 0, 0, 0));
  // (the texels here: level 0 in k/7, the 1x1 level their mean: distinct values)
  check(ts_ivcontains(ib.x, big.x) && !ts_ivcontains(ib.x, l0.x) && ib.x.hi - ib.x.lo < 1e-5f &&
            ts_ivcontains(io.x, l0.x) && ts_ivcontains(io.x, last[0]) && ts_ivcontains(ia.x, a.x),
        "textureGrad bound: past the chain only the 1x1 texel; an overflowing footprint any level; lambda 1 inside",
        std::to_string(ib.x.lo) + " " + std::to_string(ib.x.hi) + " " + std::to_string(l0.x) + " " +
            std::to_string(io.x.lo) + " " + std::to_string(io.x.hi) + " " + std::to_string(ia.x.lo) + " " +
            std::to_string(ia.x.hi) + " " + std::to_string(a.x));
}

}  // namespace

int main() {
  ts_math_init();
  chain_shape();
  box_means();
  normal_maps();
  lod();
  explicit_derivatives();
  return unit_check::finish();
}

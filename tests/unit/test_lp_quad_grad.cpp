// tiershade tests: lp_quad_grad_span (glue/scene/lp_interp.h), the C fallback's quad derivatives
// of the uv two quads per vector, against the quads' pixels interpolated one at a time with
// lp_interp_span (top-right minus top-left, bottom-left minus top-left: lp_bld_quad.c
// lp_build_packed_ddx_ddy_twocoord), in both fused modes (ts_math_set_fused), for random
// perspective triangles, every slot, runs starting and ending at odd and even columns on odd and
// even rows. 0 bits may differ. And lp_depth24_span (eight pixels a vector on an FMA host)
// against its formula one pixel at a time, planes past [0, 1] and NaN included. No GL context.
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "scene/lp_interp.h"
#include "unit_check.h"

using unit_check::check;

namespace {

// The reference: per pixel of the run, its quad's three pixels through lp_interp_span.
ts_vec4f grad_ref(const LpPlanes &pl, int k, int px, int py) {
  const int qx = px & ~1, qy = py & ~1;
  ts_vec4f tmp[6 * 3];
  const int used[1] = {k};
  lp_interp_span(pl, qx, qy, 2, used, 1, tmp, 3, 0);      // TL, TR at tmp[k * 3 + 0, 1]
  lp_interp_span(pl, qx, qy + 1, 1, used, 1, tmp, 3, 2);  // BL at tmp[k * 3 + 2]
  const ts_vec4f tl = tmp[k * 3], tr = tmp[k * 3 + 1], bl = tmp[k * 3 + 2];
  return ts_v4f(tr.x - tl.x, bl.x - tl.x, tr.y - tl.y, bl.y - tl.y);
}

// Random triangles of the 640 x 360 frame (perspective, some clipped) with every slot used.
void run(bool fused) {
  ts_math_set_fused(fused ? 1 : 0);
  std::mt19937 rng(fused ? 17 : 23);
  std::uniform_real_distribution<float> u(-1.f, 1.f), pos(0.f, 1.f);
  const float W = 640.f, H = 360.f;
  const int used[6] = {0, 1, 2, 3, 4, 5};
  long runs = 0, values = 0, diff = 0, nonzero = 0;
  std::string first;
  for (int it = 0; it < 300; ++it) {
    LpVert in[3];
    int m[3];
    for (int v = 0; v < 3; ++v) {
      const float w = 0.2f + 4.f * pos(rng);
      const float c[4] = {1.3f * u(rng) * w, 1.3f * u(rng) * w, 0.9f * u(rng) * w, w};
      std::memcpy(in[v].clip, c, sizeof c);
      lp_window_pos(c, W, H, in[v].win);
      for (float &a : in[v].attr) a = u(rng) * (it % 3 == 0 ? 1e3f : 1.f);
      m[v] = lp_clipmask(c);
    }
    LpTriSet ts;
    lp_setup_tri(in, m, W, H, used, 6, &ts);
    for (int s = 0; s < ts.n; ++s) {
      if (!ts.valid[s]) continue;
      for (int r = 0; r < 6; ++r) {
        const int k = static_cast<int>(rng() % 6), y = static_cast<int>(rng() % 360);
        const int x0 = static_cast<int>(rng() % 600), n = 1 + static_cast<int>(rng() % 40);
        std::vector<ts_vec4f> out(static_cast<size_t>(n) + 1, ts_v4f(7, 7, 7, 7));
        lp_quad_grad_span(ts.pl[s], k, x0, y, n, out.data());
        ++runs;
        for (int i = 0; i <= n; ++i) {
          // one past the run: untouched
          const ts_vec4f e = i < n ? grad_ref(ts.pl[s], k, x0 + i, y) : ts_v4f(7, 7, 7, 7);
          const float *a = &out[i].x, *b = &e.x;
          for (int c = 0; c < 4; ++c) {
            ++values;
            nonzero += b[c] != 0.f;
            if (std::memcmp(&a[c], &b[c], 4) != 0) {
              if (!diff++)
                first = "tri " + std::to_string(it) + " x " + std::to_string(x0 + i) + " y " + std::to_string(y) +
                    " slot " + std::to_string(k) + " lane " + std::to_string(c) + ": " + std::to_string(a[c]) +
                    " vs " + std::to_string(b[c]);
            }
          }
        }
      }
    }
  }
  const std::string mode = fused ? "fused" : "unfused";
  check(runs > 1000 && nonzero > values / 2, "quad grad " + mode + ": enough runs",
        std::to_string(runs) + " runs, " + std::to_string(nonzero) + " of " + std::to_string(values) + " non-zero");
  check(diff == 0, "quad grad " + mode + ": lp_quad_grad_span = lp_interp_span's quad differences",
        std::to_string(diff) + " of " + std::to_string(values) + " differ; first " + first);
}

// lp_depth24_span's formula (lp_interp.h) for one pixel.
float depth_ref(const LpPlanes &pl, int x, int y, bool fused) {
  const float xf = static_cast<float>(x), yf = static_cast<float>(y);
  float z = fused ? std::fma(pl.zdy, yf, std::fma(pl.zdx, xf, pl.z0)) : pl.zdy * yf + (pl.zdx * xf + pl.z0);
  z = std::min(std::max(z, 0.0f), 1.0f);
  return std::nearbyint(z * 16777215.0f);
}

void depth(bool fused) {
  ts_math_set_fused(fused ? 1 : 0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  long values = 0, diff = 0, inside = 0;
  for (int it = 0; it < 4000; ++it) {
    LpPlanes pl{};
    pl.z0 = 0.5f + 0.7f * u(rng), pl.zdx = u(rng) * 1e-3f, pl.zdy = u(rng) * 1e-3f;
    if (it % 97 == 0) pl.zdx = NAN;
    const int x0 = static_cast<int>(rng() % 1200), y = static_cast<int>(rng() % 700), n = 1 + static_cast<int>(rng() % 64);
    float out[65];
    out[n] = 7.f;
    lp_depth24_span(pl, x0, y, n, out);
    for (int i = 0; i <= n; ++i) {
      const float e = i < n ? depth_ref(pl, x0 + i, y, fused) : 7.f;
      ++values;
      inside += e > 0.f && e < 16777215.f;
      diff += std::memcmp(&out[i], &e, 4) != 0;
    }
  }
  const std::string mode = fused ? "fused" : "unfused";
  check(diff == 0 && inside > values / 2, "depth24 span " + mode + ": the formula's bits",
        std::to_string(diff) + " of " + std::to_string(values) + " differ (" + std::to_string(inside) + " inside)");
}

}  // namespace

int main() {
  ts_math_init();
  run(true);
  run(false);
  depth(true);
  depth(false);
  ts_math_init();
  return unit_check::finish();
}

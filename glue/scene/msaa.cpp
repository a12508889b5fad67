// tiershade scene: MSAA on the integer path (glue/scene/msaa.h): the refusals, the sample
// patterns, llvmpipe's RGBA8 resolve and the C fallback's multisampled frame.
#include "scene/msaa.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <chrono>

#include "base/image.h"
#include "base/parallel_rows.h"
#include "math/hdr_formats.h"
#include "scene/cpu_renderer.h"
#include "scene/raster_tri.h"

namespace {

// 4x: llvmpipe's lp_sample_pos_4x (Mesa src/gallium/drivers/llvmpipe/lp_rast.c, 22.3), the
// standard D3D/Vulkan 4x pattern; its rasteriser rounds them to 1/256 pixel (lp_scene.c:
// util_iround(pos * FIXED_ONE)), which these are exactly. 2x and 8x: the standard patterns
// (Vulkan "Standard sample locations"; D3D11 standard multisample quality levels), for the C
// fallback alone: llvmpipe has no 2- or 8-sample mode (GL_MAX_SAMPLES 4; a request for 2
// allocates 4).
const float kPos2[2][2] = {{0.75f, 0.75f}, {0.25f, 0.25f}};
const float kPos4[4][2] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
const float kPos8[8][2] = {{0.5625f, 0.3125f}, {0.4375f, 0.6875f}, {0.8125f, 0.5625f}, {0.3125f, 0.1875f},
                           {0.1875f, 0.8125f}, {0.0625f, 0.4375f}, {0.6875f, 0.9375f}, {0.9375f, 0.0625f}};

}  // namespace

const float (*msaa_pattern(int n))[2] {
  switch (n) {
    case 2: return kPos2;
    case 4: return kPos4;
    case 8: return kPos8;
    default: return nullptr;
  }
}

std::string msaa_refusal(const PreparedScene &p, bool float_path, bool cpu, Api api, int samples) {
  if (!msaa_pattern(samples)) return "--msaa takes 2, 4 or 8 samples per pixel, not " + std::to_string(samples);
  if (float_path)
    return "the float HDR path has no MSAA: it renders into an RGBA16F target, and the talk's trade-off is that the "
           "float path \"requires floating-point alpha blending\" and has no MSAA on that hardware (the integer path "
           "is the one \"compatible with MSAA\", with 32-bit RGBA targets); render the integer path (--hdr integer, "
           "or \"hdr\": {\"path\": \"integer\"}) to multisample";
  if (!cpu && api == Api::GLES2)
    return "GLES 2.0 has no multisampled framebuffers (glRenderbufferStorageMultisample and glBlitFramebuffer are "
           "GLES 3.0): use --api gles3 or gl33";
  for (size_t i = 0; i < p.draws.size(); ++i) {
    const PreparedDraw &d = p.draws[i];
    if (!d.display_encoded)
      return "draw " + std::to_string(i) + " (" + d.variant->shader->name + " " + d.variant->name() +
          ") writes linear colour (ps20 and world_lighting draws), which the integer path tone-maps and encodes on "
          "the host after the lit pass; a multisampled RGBA8 target stores what the shader wrote, so MSAA needs "
          "every draw to tone-map and encode in the shader (model_lighting OUTPUT_MODE 2: tier ps2b or sm3, no "
          "world faces)";
  }
  return "";
}

uint8_t msaa_resolve_unorm8(const uint8_t *codes, int n, int stride) {
  float acc = 0.f;
  for (int s = 0; s < n; ++s) acc += ts_unorm8_to_float(codes[static_cast<size_t>(s) * stride]);
  return ts_unorm8_from_float(acc * (1.f / static_cast<float>(n)));
}

namespace {

// floor(a / b) and ceil(a / b) for b > 0.
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

// One sample k of pixel i with edge values v (exact): coverage (the top-left rule), then the
// depth test LESS with the depth interpolated at the sample (llvmpipe interpolates depth per
// sample). Robust: inside every edge by more than the edge's change when its vertices move
// 2/256 pixel in x and y (another rasteriser's snapping of the same vertex differs by less).
struct SampleBuffers {
  int S;
  std::vector<int32_t> tri;
  std::vector<float> depth;
  std::vector<uint8_t> robust;
};
inline void sample_test(const ScreenTri &s, int ti, const __int128 *v, size_t i, SampleBuffers *b) {
  double l[3];
  bool robust = true;
  for (int e = 0; e < 3; ++e) {
    if (v[e] < s.bias[e]) return;
    robust = robust && v[e] >= 2 * (static_cast<__int128>(std::llabs(s.dx[e])) + std::llabs(s.dy[e]));
    l[e] = static_cast<double>(v[e]) * s.inv_area;
  }
  const double z = l[0] * s.z[0] + l[1] * s.z[1] + l[2] * s.z[2];
  if (!(z < b->depth[i]) || z < 0.0) return;
  b->depth[i] = static_cast<float>(z);
  b->tri[i] = ti;
  b->robust[i] = robust;
}

// Rows ya..yb of triangle ti. Small triangles (64-bit edge values): per row, the pixels whose
// centre's edge values are within reach of a sample (the span solved as the one-sample
// rasteriser solves it, with each edge's bias lowered by the largest change from the centre to
// a sample), then each sample's edge value as the centre's plus a per-triangle offset (exact
// integers: the same values as scene_tri_edge). Others: every pixel of the box, 128-bit.
void raster_samples(const ScreenTri &s, int ti, const int64_t *ox, const int64_t *oy, int w, int ya, int yb,
                    SampleBuffers *b) {
  const int S = b->S;
  if (!s.small) {
    for (int y = ya; y <= yb; ++y)
      for (int x = s.x0; x <= s.x1; ++x)
        for (int k = 0; k < S; ++k) {
          const int64_t px = static_cast<int64_t>(x) * kSub + ox[k], py = static_cast<int64_t>(y) * kSub + oy[k];
          const __int128 v[3] = {scene_tri_edge(s, 0, px, py), scene_tri_edge(s, 1, px, py), scene_tri_edge(s, 2, px, py)};
          sample_test(s, ti, v, (static_cast<size_t>(y) * w + x) * S + k, b);
        }
    return;
  }
  int64_t A[3], reach[3], delta[8][3];
  for (int e = 0; e < 3; ++e) {
    A[e] = -s.dy[e] * kSub;
    reach[e] = (std::llabs(s.dx[e]) + std::llabs(s.dy[e])) * (kSub / 2);
    for (int k = 0; k < S; ++k) delta[k][e] = s.dx[e] * (oy[k] - kSub / 2) - s.dy[e] * (ox[k] - kSub / 2);
  }
  for (int y = ya; y <= yb; ++y) {
    const int64_t py = static_cast<int64_t>(y) * kSub + kSub / 2;
    int64_t C[3], lo = s.x0, hi = s.x1;
    for (int e = 0; e < 3; ++e) {
      const int a = (e + 1) % 3;
      C[e] = s.dx[e] * (py - s.Y[a]) - s.dy[e] * (kSub / 2 - s.X[a]);
      const int64_t need = s.bias[e] - reach[e];  // some sample may be covered: C + A x >= need
      if (A[e] > 0)
        lo = std::max(lo, ceil_div(need - C[e], A[e]));
      else if (A[e] < 0)
        hi = std::min(hi, floor_div(C[e] - need, -A[e]));
      else if (C[e] < need)
        hi = lo - 1;
    }
    for (int64_t x = lo; x <= hi; ++x) {
      const size_t base = (static_cast<size_t>(y) * w + static_cast<size_t>(x)) * S;
      for (int k = 0; k < S; ++k) {
        const __int128 v[3] = {C[0] + A[0] * x + delta[k][0], C[1] + A[1] * x + delta[k][1],
                               C[2] + A[2] * x + delta[k][2]};
        sample_test(s, ti, v, base + k, b);
      }
    }
  }
}

}  // namespace

void scene_render_msaa_cpu(const PreparedScene &p, int S, MsaaFrameC *out, int threads) {
  const float(*pos)[2] = msaa_pattern(S);
  const int w = p.w, h = p.h;
  const bool timing = getenv("TS_DRAW_MS") != nullptr;
  auto t0 = std::chrono::steady_clock::now();
  auto lap = [&](const char *what) {
    if (!timing) return;
    const auto t1 = std::chrono::steady_clock::now();
    fprintf(stderr, "C MSAA %s: %.1f ms\n", what, std::chrono::duration<double, std::milli>(t1 - t0).count());
    t0 = t1;
  };
  const size_t n = static_cast<size_t>(w) * h;
  out->w = w;
  out->h = h;
  out->samples = S;
  int64_t ox[8], oy[8];
  for (int k = 0; k < S; ++k) {
    ox[k] = std::llround(pos[k][0] * kSub);
    oy[k] = std::llround(pos[k][1] * kSub);
  }
  std::vector<ScreenTri> tris;
  std::vector<float> clip;
  for (size_t di = 0; di < p.draws.size(); ++di) {
    scene_clip_stage(p, p.draws[di], &clip);
    scene_tri_setup(p, static_cast<int>(di), clip, &tris);
  }
  SampleBuffers sb;
  sb.S = S;
  sb.tri.assign(n * S, -1);
  sb.depth.assign(n * S, 1.f);
  sb.robust.assign(n * S, 0);
  out->sample_bytes = n * S * (sizeof(int32_t) + sizeof(float) + 2);  // triangle, depth, robust, layer
  // Bands of 8 rows, each with its triangles in draw order (equal depths keep the first draw).
  const int kBand = 8, bands = (h + kBand - 1) / kBand;
  std::vector<std::vector<int>> band_tris(static_cast<size_t>(bands));
  for (size_t i = 0; i < tris.size(); ++i)
    for (int b = tris[i].y0 / kBand; b <= tris[i].y1 / kBand; ++b) band_tris[static_cast<size_t>(b)].push_back(static_cast<int>(i));
  parallel_rows(bands, threads, [&](int band) {
    const int ra = band * kBand, rb = std::min(h, ra + kBand);
    for (int ti : band_tris[static_cast<size_t>(band)]) {
      const ScreenTri &s = tris[static_cast<size_t>(ti)];
      raster_samples(s, ti, ox, oy, w, std::max(s.y0, ra), std::min(s.y1, rb - 1), &sb);
    }
  });
  lap("set-up and rasterisation");
  const std::vector<int32_t> &stri = sb.tri;
  const std::vector<uint8_t> &srobust = sb.robust;
  // Shading once per pixel and triangle: layer j holds each pixel's j-th distinct triangle
  // (in sample order) with its barycentrics at the pixel centre (outside the triangle for
  // an edge pixel whose centre it misses: the attributes extrapolated, as GL does without
  // centroid), shaded by the C twins as the one-sample frame is.
  std::vector<uint8_t> layer_of(n * S, 0), frags(n, 0);  // per pixel: its distinct triangles
  parallel_rows(h, threads, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      int distinct[8], nd = 0;
      for (int k = 0; k < S; ++k) {
        const int t = stri[i * S + k];
        if (t < 0) continue;
        int j = 0;
        while (j < nd && distinct[j] != t) ++j;
        if (j == nd) distinct[nd++] = t;
        layer_of[i * S + k] = static_cast<uint8_t>(j);
      }
      frags[i] = static_cast<uint8_t>(nd);
    }
  });
  // Layer 0: each pixel's first triangle, in place; the others (edge pixels only) packed one
  // after another into further buffers of the frame's size (the shading does not depend on
  // where a record sits: no derivatives), fragment j >= 1 of pixel i at extra[i] + j - 1.
  std::vector<size_t> extra(n, 0);
  size_t nextra = 0;
  for (size_t i = 0; i < n; ++i) {
    extra[i] = nextra;
    if (frags[i] > 1) nextra += frags[i] - 1;
  }
  const size_t buffers = 1 + (nextra + n - 1) / n;
  std::vector<ImageF> shaded(buffers);
  auto slot_of = [&](size_t i, int j) -> size_t { return j == 0 ? i : n + extra[i] + static_cast<size_t>(j) - 1; };
  for (size_t bi = 0; bi < buffers; ++bi) {
    SceneVisibility L;
    L.w = w;
    L.h = h;
    L.draw.assign(n, -1);
    L.tri.assign(n, -1);
    L.b1.assign(n, 0.f);
    L.b2.assign(n, 0.f);
    L.at.assign(n, 0);
    L.sub.assign(n, 0);
    L.pixel_planes = true;  // each record at its own pixel's centre (L.at), as the one-sample frame
    parallel_rows(h, threads, [&](int y) {
      for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        for (int j = 0; j < frags[i]; ++j) {
          const size_t q = slot_of(i, j);
          if (q / n != bi) continue;
          int t = -1;
          for (int k = 0; k < S && t < 0; ++k)
            if (stri[i * S + k] >= 0 && layer_of[i * S + k] == j) t = stri[i * S + k];
          const ScreenTri &s = tris[static_cast<size_t>(t)];
          const int64_t px = static_cast<int64_t>(x) * kSub + kSub / 2, py = static_cast<int64_t>(y) * kSub + kSub / 2;
          double l[3], b1, b2;
          for (int e = 0; e < 3; ++e) l[e] = static_cast<double>(scene_tri_edge(s, e, px, py)) * s.inv_area;
          scene_tri_bary(s, l[0], l[1], l[2], &b1, &b2);
          const size_t at = q % n;
          L.draw[at] = s.draw;
          L.tri[at] = s.tri;
          L.b1[at] = static_cast<float>(b1);
          L.b2[at] = static_cast<float>(b2);
          L.at[at] = static_cast<int32_t>(i);
          L.sub[at] = static_cast<uint8_t>(s.sub);
        }
      }
    });
    scene_shade_cpu(p, L, &shaded[bi], threads);
  }
  lap("layers and shading");
  // Each sample stores its fragment's colour as an RGBA8 target does (clear colour 0); resolve.
  out->display.assign(n * 4, 0);
  std::vector<int32_t> full(n, -1);  // the one triangle robustly covering every sample, or -1
  out->silhouette.assign(n, 0);
  parallel_rows(h, threads, [&](int y) {
    uint8_t codes[8 * 4];
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      if (frags[i] == 0) continue;  // no sample covered: the clear colour
      bool one = true, all = true;
      for (int k = 0; k < S; ++k) {
        const int t = stri[i * S + k];
        all = all && t >= 0;
        one = one && t >= 0 && t == stri[i * S] && srobust[i * S + k];
      }
      if (one) full[i] = stri[i * S];
      bool sil = !all;
      for (int k = 0; k < S && !sil; ++k) sil = tris[static_cast<size_t>(stri[i * S + k])].draw != tris[static_cast<size_t>(stri[i * S])].draw;
      out->silhouette[i] = sil;
      if (all && frags[i] == 1) {  // every sample holds the same codes, which resolve to themselves
        for (int c = 0; c < 4; ++c) out->display[i * 4 + c] = ts_unorm8_from_float(shaded[0].rgba[i * 4 + static_cast<size_t>(c)]);
        continue;
      }
      for (int k = 0; k < S; ++k) {
        const int t = stri[i * S + k];
        for (int c = 0; c < 4; ++c)
          codes[k * 4 + c] = 0;
        if (t < 0) continue;
        const size_t q = slot_of(i, layer_of[i * S + k]);
        for (int c = 0; c < 4; ++c)
          codes[k * 4 + c] = ts_unorm8_from_float(shaded[q / n].rgba[(q % n) * 4 + static_cast<size_t>(c)]);
      }
      for (int c = 0; c < 4; ++c) out->display[i * 4 + c] = msaa_resolve_unorm8(codes + c, S, 4);
    }
  });
  out->interior.resize(n);
  for (size_t i = 0; i < n; ++i) out->interior[i] = full[i] >= 0;
  lap("codes and resolve");
}

void msaa_compare(const std::vector<uint8_t> &gl, const std::vector<uint8_t> &twin, const MsaaFrameC &cfb,
                  MsaaCheck *out) {
  *out = MsaaCheck();
  const size_t n = static_cast<size_t>(cfb.w) * cfb.h;
  for (size_t i = 0; i < n; ++i) {
    const bool in = cfb.interior[i] != 0;
    const std::vector<uint8_t> &ref = in ? twin : cfb.display;
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(static_cast<int>(gl[i * 4 + c]) - static_cast<int>(ref[i * 4 + c])));
    if (in) {
      ++out->interior;
      out->interior_mismatched += d != 0;
      if (d && getenv("TS_MSAA_DEBUG"))
        fprintf(stderr, "interior mismatch at %zu,%zu: GL %d %d %d twin %d %d %d\n", i % cfb.w, i / cfb.w, gl[i * 4],
                gl[i * 4 + 1], gl[i * 4 + 2], twin[i * 4], twin[i * 4 + 1], twin[i * 4 + 2]);
      out->interior_max = std::max(out->interior_max, d);
    } else if (cfb.display[i * 4 + 3] == 0 && gl[i * 4 + 3] == 0) {
      ++out->background;  // no sample covered, in either frame
      out->background_mismatched += d != 0;
    } else {
      ++out->edge;
      out->edge_over_1 += d > 1;
      out->edge_over_64 += d > 64;
      out->edge_max = std::max(out->edge_max, d);
    }
  }
}

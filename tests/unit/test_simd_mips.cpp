// tiershade tests: the SIMD samplers' mipmapped and shared-addressing paths (c_ref/math/ts_simd_sampler.h:
// texture2D_grad with its uniform-level fast path, texture2D_grad2 for base and bump of the same
// chain, texture2D_n for the three RNM lightmaps) through the world_lighting fast path
// (world_lighting_f_batch) against the scalar twin (world_lighting_f, whose sampler is
// c_ref/math/ts_sampler.c ts_texture2D_gradf), bit for bit: every variant, in four chain shapes (POT and
// NPOT, REPEAT and CLAMP_TO_EDGE) with LINEAR and NEAREST mip filters, with a normal map of the
// base's chain and of another one; per-pixel derivatives one per block (every lane at one level)
// or per pixel (mixed levels), hard ones too (0, huge, inf, NaN); lightmap offsets along s only
// (the shared t addressing), along both, and mixed in a block; for each instruction set the host has
// (ts_batch_force_isa) and each fused-mad mode. (test_fast_path covers single-level textures.)
// The check discriminates: the same frames without derivatives (level 0 only) differ.
//
// Usage: build/tests/test_simd_mips   Prints PASS/FAIL lines and "N passed, N failed";
// exit 1 on failure.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "twins/world_lighting_batch.h"
#include "unit_check.h"

namespace {

struct Rng {
  uint64_t s;
  uint32_t next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<uint32_t>(s >> 33);
  }
  float uniform(float lo, float hi) { return lo + (hi - lo) * static_cast<float>(next() % 1000003u) / 1000003.f; }
};

bool same_bits(const ts_vec4f &a, const ts_vec4f &b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A coordinate: mostly random, sometimes a texel edge or a hard value.
float coord(Rng &r, int len) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  switch (r.next() % 24) {
    case 0:
      return static_cast<float>(static_cast<int>(r.next() % (3 * len)) - len) / len;
    case 1:
      return 0x1.fffffep-1f;
    case 2:
      return -0.0f;
    case 3:
      return (r.next() & 1) ? 1e30f : -1e30f;
    case 4:
      return (r.next() & 1) ? inf : -inf;
    case 5:
      return nan;
    default:
      return r.uniform(-2.5f, 2.5f);
  }
}

// One derivative component: levels 0 .. past the last, and the hard values.
float deriv(Rng &r) {
  switch (r.next() % 20) {
    case 0:
      return 0.f;
    case 1:
      return std::numeric_limits<float>::quiet_NaN();
    case 2:
      return std::numeric_limits<float>::infinity();
    case 3:
      return 1e20f;
    default: {
      const float m = std::ldexp(1.f, -static_cast<int>(r.next() % 9));  // 1 .. 1/256
      return (r.next() & 1 ? m : -m) * r.uniform(0.5f, 1.5f);
    }
  }
}

// A w x h texture with a full chain (max(1, size >> k) down to 1x1), random texels per level.
struct Tex {
  std::vector<std::vector<float>> levels;
  ts_tex2d t;
};

Tex make_chain(Rng &r, int w, int h, int wrap, int mip_filter) {
  Tex x;
  x.t = ts_tex2d_single(w, h, nullptr, wrap, wrap, TS_FILTER_LINEAR);
  int n = 1;
  while ((w >> n) > 0 || (h >> n) > 0) ++n;
  x.levels.resize(static_cast<size_t>(n));
  for (int l = 0; l < n; ++l) {
    const int lw = std::max(1, w >> l), lh = std::max(1, h >> l);
    x.levels[l].resize(static_cast<size_t>(lw) * lh * 4);
    for (size_t i = 0; i < x.levels[l].size(); ++i)
      x.levels[l][i] = i % 4 == 3 ? static_cast<float>(120 + r.next() % 11) / 255.f : r.uniform(0.02f, 1.f);
    x.t.mip_w[l] = lw;
    x.t.mip_h[l] = lh;
  }
  x.t.mip_levels = n;
  x.t.mip_filter = mip_filter;
  return x;
}
void bind(Tex *x) {
  x->t.texels = x->levels[0].data();
  for (size_t l = 0; l < x->levels.size(); ++l) x->t.mip_texels[l] = x->levels[l].data();
}

}  // namespace

int main() {
  ts_math_init();
  Rng r{20261208u};
  const int shapes[4][3] = {
      {64, 32, TS_WRAP_REPEAT}, {24, 12, TS_WRAP_REPEAT}, {32, 32, TS_WRAP_CLAMP}, {20, 10, TS_WRAP_CLAMP}};
  std::vector<float> cube_texels(static_cast<size_t>(4 * 4 * 4 * 6));
  for (float &v : cube_texels) v = r.uniform(0.f, 2.f);
  ts_texcube cube;
  cube.size = 4;
  cube.filter = TS_FILTER_LINEAR;
  for (int f = 0; f < 6; ++f) cube.faces[f] = &cube_texels[static_cast<size_t>(f) * 4 * 4 * 4];

  const int n = 203;  // not a multiple of 8: every block and a tail
  const int host_fused = ts_math_fused();
  long discriminating = 0;
  for (int shape = 0; shape < 4; ++shape)
    for (int mipf : {TS_MIP_LINEAR, TS_MIP_NEAREST})
      for (int other_bump = 0; other_bump < 2; ++other_bump) {
        const int w = shapes[shape][0], h = shapes[shape][1], wrap = shapes[shape][2];
        // base, normal map (the base's chain, or one twice as wide), lightmap (one level), mask
        Tex tex[4] = {make_chain(r, w, h, wrap, mipf), make_chain(r, other_bump ? 2 * w : w, h, wrap, mipf),
                      make_chain(r, 2 * w, h, TS_WRAP_CLAMP, TS_MIP_NONE), make_chain(r, w, h, wrap, mipf)};
        for (Tex &t : tex) bind(&t);
        tex[2].t.mip_levels = 1;
        std::vector<ts_vec4f> recs(static_cast<size_t>(n) * WL_SLOTS), grads(static_cast<size_t>(n));
        ts_vec4f block_grad = ts_v4f(0, 0, 0, 0);
        int lm_mode = 0;
        for (int i = 0; i < n; ++i) {
          if (i % 8 == 0) {  // per block: one derivative for all lanes, or one per pixel; lightmap offsets
            block_grad = r.next() % 3 ? ts_v4f(deriv(r), deriv(r), deriv(r), deriv(r)) : ts_v4f(-1, 0, 0, 0);
            lm_mode = static_cast<int>(r.next() % 4);  // 0, 1: along s; 2: both; 3: mixed
          }
          grads[i] = block_grad.x != -1.f ? block_grad : ts_v4f(deriv(r), deriv(r), deriv(r), deriv(r));
          ts_vec4f *rec = &recs[static_cast<size_t>(i) * WL_SLOTS];
          rec[WL_SLOT_UV] = ts_v4f(coord(r, w), coord(r, h), coord(r, 2 * w), coord(r, h));
          const bool along_s = lm_mode < 2 || (lm_mode == 3 && (r.next() & 1));
          rec[WL_SLOT_LM_OFFSET] = ts_v4f(r.next() % 4 ? r.uniform(-0.3f, 0.3f) : coord(r, w),
                                          along_s ? (r.next() % 5 ? 0.f : -0.f) : r.uniform(-0.2f, 0.2f),
                                          r.uniform(0.f, 50.f), 0.f);
          for (int k = WL_SLOT_NORMAL; k <= WL_SLOT_EYE; ++k)
            rec[k] = ts_v4f(r.uniform(-1.f, 1.f), r.uniform(-1.f, 1.f), r.uniform(-1.f, 1.f), 0.f);
          rec[WL_SLOT_TINT_SCALE] =
              ts_v4f(r.uniform(0.5f, 2.f), r.uniform(0.5f, 2.f), r.uniform(0.5f, 2.f), r.uniform(0.5f, 2.f));
          rec[WL_SLOT_ENV_TINT] =
              ts_v4f(r.uniform(0.f, 1.f), r.uniform(0.f, 1.f), r.uniform(0.f, 1.f), r.uniform(0.f, 2.f));
          rec[WL_SLOT_ENV_PARAMS] =
              r.next() % 2 ? ts_v4f(0.f, 1.f, 0.f, 1.f) : ts_v4f(r.uniform(0.f, 1.f), r.uniform(0.f, 2.f), 0.7f, 0.3f);
          rec[WL_SLOT_FOG_COLOR] =
              ts_v4f(r.uniform(0.f, 1.f), r.uniform(0.f, 1.f), r.uniform(0.f, 1.f), r.uniform(0.f, 1.f));
          rec[WL_SLOT_FOG_PARAMS] = ts_v4f(r.uniform(0.f, 0.05f), r.uniform(0.f, 0.5f), 0.f, 0.f);
        }
        const wl_textures tx = {&tex[0].t, &tex[1].t, &tex[2].t, &tex[3].t, &cube, grads.data(), 1};
        const wl_textures flat = {&tex[0].t, &tex[1].t, &tex[2].t, &tex[3].t, &cube, nullptr, 0};
        long checked = 0, differ = 0;
        std::string first;
        for (int tier = 0; tier < 3; ++tier)
          for (int bump = 0; bump < 3; ++bump)
            for (int enc = 0; enc < 4; ++enc)
              for (int env = 0; env < 2; ++env)
                for (int mask = 0; mask < (env ? 4 : 1); ++mask) {
                  const wl_variant v = {tier, bump, enc, env, mask};
                  for (int fused = 0; fused < 2; ++fused) {
                    ts_math_set_fused(fused);
                    std::vector<ts_vec4f> want(static_cast<size_t>(n));
                    for (int i = 0; i < n; ++i) {
                      wl_textures one = tx;
                      one.uv_grad = &grads[i];
                      want[i] = world_lighting_f(&v, &recs[static_cast<size_t>(i) * WL_SLOTS], &one);
                    }
                    for (int isa : {TS_BATCH_AVX2, TS_BATCH_SSE2}) {
                      ts_batch_force_isa(isa);
                      if (ts_batch_isa() != isa) continue;
                      std::vector<ts_vec4f> got(static_cast<size_t>(n));
                      world_lighting_f_records(&v, recs.data(), &tx, got.data(), n);
                      for (int i = 0; i < n; ++i) {
                        ++checked;
                        if (!same_bits(got[i], want[i]) && differ++ == 0)
                          first = "tier " + std::to_string(tier) + " bump " + std::to_string(bump) + " enc " +
                              std::to_string(enc) + " env " + std::to_string(env) + " mask " + std::to_string(mask) +
                              " fused " + std::to_string(fused) + " isa " + std::to_string(isa) + " pixel " +
                              std::to_string(i);
                      }
                    }
                    ts_batch_force_isa(-1);
                  }
                  // Discrimination: without derivatives (level 0 only) the frame differs.
                  ts_math_set_fused(host_fused);
                  std::vector<ts_vec4f> a(static_cast<size_t>(n)), b(static_cast<size_t>(n));
                  world_lighting_f_records(&v, recs.data(), &tx, a.data(), n);
                  world_lighting_f_records(&v, recs.data(), &flat, b.data(), n);
                  for (int i = 0; i < n; ++i) discriminating += !same_bits(a[i], b[i]);
                }
        ts_math_set_fused(host_fused);
        check(differ == 0,
              std::to_string(w) + "x" + std::to_string(h) + (wrap == TS_WRAP_REPEAT ? " REPEAT" : " CLAMP") +
                  (mipf == TS_MIP_LINEAR ? " LINEAR" : " NEAREST") + " mips, normal map " +
                  (other_bump ? "of another chain" : "of the base's chain") + ": fast path == scalar twin on " +
                  std::to_string(checked) + " pixels",
              std::to_string(differ) + " differ, first " + first);
      }
  check(discriminating > 1000, "the check discriminates: frames with and without derivatives differ",
        std::to_string(discriminating) + " pixels differ");
  return finish();
}

// tiershade tests: the SIMD 2D NEAREST sampler (c_ref/math/ts_simd_sampler_nearest.h) through the world_lighting
// fast path (world_lighting_f_batch) against the scalar twin (world_lighting_f, whose NEAREST
// is c_ref/math/ts_sampler.c), bit for bit: every variant (tier, bump, encoding, envmap, mask), with
// every 2D texture NEAREST, in four shapes (POT and NPOT, REPEAT and CLAMP_TO_EDGE), on
// random coordinates and on hard ones (texel edges, 1 - ulp, -0, denormals, huge, +-inf, NaN),
// for each instruction set the host has (ts_batch_force_isa) and each fused-mad mode.
// test_fast_path covers the LINEAR paths (the family's test textures are LINEAR).
// The check discriminates: the same frames sampled LINEAR differ from the NEAREST ones.
//
// Usage: build/tests/test_simd_nearest   Prints PASS/FAIL lines and "N passed, N failed";
// exit 1 on failure.
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

// A coordinate for a texture of len texels: random, or one of the hard values.
float coord(Rng &r, int len) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  switch (r.next() % 16) {
    case 0:
      return static_cast<float>(static_cast<int>(r.next() % (3 * len)) - len) / len;  // texel edge
    case 1:
      return 0x1.fffffep-1f;
    case 2:
      return -0.0f;
    case 3:
      return (r.next() & 1) ? 1e-40f : -1e-40f;
    case 4:
      return (r.next() & 1) ? 1e30f : -1e30f;
    case 5:
      return (r.next() & 1) ? inf : -inf;
    case 6:
      return nan;
    case 7:
      return 1.0f;
    case 8:
      return std::nextafter(static_cast<float>(r.next() % len) / len, -1.f);  // just below an edge
    default:
      return r.uniform(-2.5f, 2.5f);
  }
}

struct Tex {
  std::vector<float> texels;
  ts_tex2d t;
};

Tex make_tex(Rng &r, int w, int h, int wrap, int filter) {
  Tex x;
  x.texels.resize(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < x.texels.size(); ++i)
    x.texels[i] = i % 4 == 3 ? static_cast<float>(120 + r.next() % 11) / 255.f : r.uniform(0.02f, 1.f);
  x.t = ts_tex2d_single(w, h, nullptr, wrap, wrap, filter);
  return x;
}

}  // namespace

int main() {
  ts_math_init();
  Rng r{20240611u};
  const int shapes[4][3] = {
      {16, 8, TS_WRAP_REPEAT}, {13, 7, TS_WRAP_REPEAT}, {16, 8, TS_WRAP_CLAMP}, {11, 5, TS_WRAP_CLAMP}};
  std::vector<float> cube_texels(static_cast<size_t>(4 * 4 * 4 * 6));
  for (float &v : cube_texels) v = r.uniform(0.f, 2.f);
  ts_texcube cube;
  cube.size = 4;
  cube.filter = TS_FILTER_NEAREST;
  for (int f = 0; f < 6; ++f) cube.faces[f] = &cube_texels[static_cast<size_t>(f) * 4 * 4 * 4];

  const int n = 203;  // not a multiple of 8: every block and a tail
  int host_fused = ts_math_fused();
  long discriminating = 0;
  for (int shape = 0; shape < 4; ++shape) {
    const int w = shapes[shape][0], h = shapes[shape][1], wrap = shapes[shape][2];
    Tex tex[4] = {make_tex(r, w, h, wrap, TS_FILTER_NEAREST), make_tex(r, w, h, wrap, TS_FILTER_NEAREST),
                  make_tex(r, 2 * w, h, wrap, TS_FILTER_NEAREST), make_tex(r, w, 2 * h, wrap, TS_FILTER_NEAREST)};
    for (Tex &t : tex) t.t.texels = t.texels.data();
    const wl_textures tx = {&tex[0].t, &tex[1].t, &tex[2].t, &tex[3].t, &cube, nullptr, 0};
    // Records: uv and the lightmap offsets hard or random, the rest random but sane.
    std::vector<ts_vec4f> recs(static_cast<size_t>(n) * WL_SLOTS);
    for (int i = 0; i < n; ++i) {
      ts_vec4f *rec = &recs[static_cast<size_t>(i) * WL_SLOTS];
      rec[WL_SLOT_UV] = ts_v4f(coord(r, w), coord(r, h), coord(r, 2 * w), coord(r, h));
      rec[WL_SLOT_LM_OFFSET] = ts_v4f(r.next() % 4 ? r.uniform(-0.3f, 0.3f) : coord(r, w), r.uniform(-0.2f, 0.2f),
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
                for (int i = 0; i < n; ++i)
                  want[i] = world_lighting_f(&v, &recs[static_cast<size_t>(i) * WL_SLOTS], &tx);
                for (int isa : {TS_BATCH_AVX2, TS_BATCH_SSE2}) {
                  ts_batch_force_isa(isa);
                  std::vector<ts_vec4f> got(static_cast<size_t>(n));
                  world_lighting_f_records(&v, recs.data(), &tx, got.data(), n);
                  for (int i = 0; i < n; ++i) {
                    ++checked;
                    if (!same_bits(got[i], want[i]) && differ++ == 0)
                      first = "tier " + std::to_string(tier) + " bump " + std::to_string(bump) + " enc " +
                          std::to_string(enc) + " env " + std::to_string(env) + " mask " + std::to_string(mask) +
                          " fused " + std::to_string(fused) + " isa " + std::to_string(ts_batch_isa()) + " pixel " +
                          std::to_string(i);
                  }
                }
                ts_batch_force_isa(-1);
              }
              // Discrimination: the same variant with LINEAR 2D textures gives other values.
              ts_math_set_fused(host_fused);
              Tex lin[4] = {tex[0], tex[1], tex[2], tex[3]};
              for (Tex &t : lin) {
                t.t.texels = t.texels.data();
                t.t.filter = TS_FILTER_LINEAR;
              }
              const wl_textures tl = {&lin[0].t, &lin[1].t, &lin[2].t, &lin[3].t, &cube, nullptr, 0};
              std::vector<ts_vec4f> a(static_cast<size_t>(n)), b(static_cast<size_t>(n));
              world_lighting_f_records(&v, recs.data(), &tx, a.data(), n);
              world_lighting_f_records(&v, recs.data(), &tl, b.data(), n);
              for (int i = 0; i < n; ++i) discriminating += !same_bits(a[i], b[i]);
            }
    ts_math_set_fused(host_fused);
    check(differ == 0,
          "NEAREST " + std::to_string(w) + "x" + std::to_string(h) + (wrap == TS_WRAP_REPEAT ? " REPEAT" : " CLAMP") +
              ": fast path == scalar twin on " + std::to_string(checked) + " pixels",
          std::to_string(differ) + " differ, first " + first);
  }
  check(discriminating > 1000, "the check discriminates: NEAREST and LINEAR frames differ",
        std::to_string(discriminating) + " pixels differ");
  return finish();
}

// tiershade tests: the C fallback's fast path (c_ref/twins/model_lighting_batch.c: the model_lighting twin on 8 or
// 4 pixels at once) against the scalar twin (model_lighting_f), bit for bit (no tolerance,
// NaN not excepted): every model_lighting variant (276), on the family's Random and Hard
// input grids (64x64, make_inputs) and on a deferred-style grid (6 per-pixel slots, the
// other 36 shared, stride 0), through the family glue (eval_row_f against eval_f, rows
// starting and ending off a multiple of 8) and through model_lighting_f_records in chunks
// of 1..13 pixels (every tail length); and the same row check for every world_lighting variant
// (c_ref/twins/world_lighting_batch.c) on its random, hard and deferred grids. Each instruction set the host has (AVX2, SSE2) in
// each fused-mad mode it can run (fused only where the host has FMA: that is when llvmpipe
// fuses; GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 makes it unfused, which ts_math_set_fused(0)
// stands for here).
//
// Usage: build/tests/test_fast_path   Prints PASS/FAIL lines and "N passed, N failed";
// exit 1 on failure.
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "families/family.h"
#include "families/model_lighting.h"
#include "twins/model_lighting_batch.h"
#include "unit_check.h"
#include "unit_vec4.h"

namespace {

// A deferred-style copy of a grid: the first `pixel` slots per pixel, the rest shared
// (taken from pixel (0, 0)), as sphere frames and the scene renderer pass them.
FamilyInputs deferred_copy(const FamilyInputs &g, int pixel) {
  FamilyInputs d;
  d.resize(g.w, g.h, pixel);
  d.textures = g.textures;
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w; ++x)
      for (int k = 0; k < pixel; ++k) d.set_slot(x, y, k, g.slot(x, y, k));
  d.shared.resize(g.slots);
  for (int k = 0; k < g.slots; ++k) d.shared[k] = g.slot(0, 0, k);
  return d;
}

struct Grid {
  const char *name;
  FamilyInputs in;
};

struct Tally {
  long pixels = 0, bad = 0;
  std::string first;
  void add(bool ok, const std::string &where, const ts_vec4f &got, const ts_vec4f &want) {
    ++pixels;
    if (ok) return;
    if (bad++ == 0) first = where + ": fast " + show(got) + ", scalar " + show(want);
  }
  std::string detail() const {
    return std::to_string(bad) + " of " + std::to_string(pixels) + " pixels differ; first " + first;
  }
};

// eval_row_f against eval_f for every variant of `fam` on `in`, in the current fused mode, for each
// instruction set in `isas` the host runs; rows start and end off the 8-pixel blocks.
void check_family_rows(const ShaderFamily &fam, const std::vector<Variant> &variants, const FamilyInputs &in,
                       const char *grid, int fused) {
  const struct {
    int level;
    const char *name;
  } isas[2] = {{TS_BATCH_AVX2, "avx2"}, {TS_BATCH_SSE2, "sse2"}};
  for (const auto &isa : isas) {
    ts_batch_force_isa(isa.level);
    if (ts_batch_isa() != isa.level) continue;
    Tally t;
    std::vector<ts_vec4f> got(static_cast<size_t>(in.w));
    for (const Variant &v : variants) {
      for (int y = 0; y < in.h; ++y) {
        const int x0 = y % 5, count = in.w - x0 - (y % 3);
        fam.eval_row_f(v, in, x0, y, count, got.data());
        for (int p = 0; p < count; ++p) {
          const ts_vec4f want = fam.eval_f(v, in, x0 + p, y);
          t.add(same_bits(got[p], want), v.name() + " pixel (" + std::to_string(x0 + p) + "," + std::to_string(y) + ")",
                got[p], want);
        }
      }
    }
    check(t.bad == 0,
          std::string(fam.name) + " " + isa.name + (fused ? " fused " : " unfused ") + grid +
              ": eval_row_f = eval_f, all " + std::to_string(variants.size()) + " variants (" +
              std::to_string(t.pixels) + " pixels)",
          t.detail());
  }
  ts_batch_force_isa(-1);
}

}  // namespace

int main() {
  ts_math_init();
  const bool host_fma = ts_math_fused() != 0;  // ts_detect_fma: the host's FMA and GALLIUM_OVERRIDE_CPU_CAPS
  std::string err;
  std::vector<ShaderDecl> decls;
  if (!load_shader_decls(&decls, &err)) {
    check(false, "load shader declarations", err);
    return 1;
  }
  const ShaderFamily *fam = find_family("model_lighting");
  const ShaderDecl *decl = nullptr;
  for (const ShaderDecl &d : decls)
    if (d.name == "model_lighting") decl = &d;
  check(fam && fam->eval_row_f && decl, "model_lighting has a fast path");
  if (!fam || !fam->eval_row_f || !decl) return 1;
  const std::vector<Variant> variants = enumerate_variants(*decl, all_tiers(), &err);
  // How many there are is test_glue's (derived from shaders/model_lighting.variants); here every one runs.
  check(!variants.empty(), "model_lighting variants enumerated", std::to_string(variants.size()));

  const int n = 64;
  std::vector<Grid> grids(3);
  grids[0].name = "random";
  fam->make_inputs(InputSet::Random, n, n, 1234u, &grids[0].in);
  grids[1].name = "hard";
  fam->make_inputs(InputSet::Hard, n, n, 5678u, &grids[1].in);
  grids[2].name = "deferred";
  grids[2].in = deferred_copy(grids[0].in, fam->pixel_slots);

  // The C views of a grid's textures for the direct calls (make_inputs' order).
  using Views = MlTextureViews;

  std::vector<int> fused_modes = {0};
  if (host_fma) fused_modes.push_back(1);
  printf("host: %s; fused modes tested: %s\n", host_fma ? "FMA (llvmpipe fuses)" : "no FMA",
         host_fma ? "fused and unfused" : "unfused");
  struct Isa {
    int level;
    const char *name;
  };
  const Isa isas[2] = {{TS_BATCH_AVX2, "avx2"}, {TS_BATCH_SSE2, "sse2"}};
  for (int fused : fused_modes) {
    ts_math_set_fused(fused);
    bool have[2];
    for (int i = 0; i < 2; ++i) {
      ts_batch_force_isa(isas[i].level);
      have[i] = ts_batch_isa() == isas[i].level;
      if (!have[i])
        printf("skip %s %s: not available on this host in this mode (the scalar twin runs instead)\n", isas[i].name,
               fused ? "fused" : "unfused");
    }
    for (const Grid &g : grids) {
      const FamilyInputs &in = g.in;
      const Views views(in);
      const ml_textures &tex = views.tex;
      const int total = in.w * in.h;
      Tally rows[2], recs[2];
      for (const Variant &v : variants) {
        // Reference: the scalar twin through the glue, pixel by pixel.
        std::vector<ts_vec4f> want(static_cast<size_t>(total));
        for (int y = 0; y < in.h; ++y)
          for (int x = 0; x < in.w; ++x) want[static_cast<size_t>(y) * in.w + x] = fam->eval_f(v, in, x, y);
        std::vector<ts_vec4f> all;
        if (in.slots == ML_SLOTS) {
          all.resize(static_cast<size_t>(total) * ML_SLOTS);
          for (int y = 0; y < in.h; ++y)
            for (int x = 0; x < in.w; ++x)
              for (int k = 0; k < ML_SLOTS; ++k)
                all[(static_cast<size_t>(y) * in.w + x) * ML_SLOTS + k] = in.slot(x, y, k);
        }
        const ml_variant m = ml_variant_of(v);
        for (int i = 0; i < 2; ++i) {
          if (!have[i]) continue;
          ts_batch_force_isa(isas[i].level);
          // The glue's row path, rows starting and ending off the 8-pixel blocks.
          std::vector<ts_vec4f> got(static_cast<size_t>(in.w));
          for (int y = 0; y < in.h; ++y) {
            const int x0 = y % 5, count = in.w - x0 - (y % 3);
            fam->eval_row_f(v, in, x0, y, count, got.data());
            for (int p = 0; p < count; ++p) {
              const ts_vec4f &w = want[static_cast<size_t>(y) * in.w + x0 + p];
              rows[i].add(same_bits(got[p], w),
                          v.name() + " pixel (" + std::to_string(x0 + p) + "," + std::to_string(y) + ")", got[p], w);
            }
          }
          // The C API on whole records, in chunks of 1..13 pixels (every tail length).
          if (in.slots == ML_SLOTS) {
            std::vector<ts_vec4f> out(static_cast<size_t>(total));
            for (int first = 0, c = 1; first < total; first += c, c = c % 13 + 1)
              model_lighting_f_records(&m, &all[static_cast<size_t>(first) * ML_SLOTS], &tex, &out[first],
                                       std::min(c, total - first));
            for (int p = 0; p < total; ++p)
              recs[i].add(same_bits(out[p], want[p]), v.name() + " pixel " + std::to_string(p), out[p], want[p]);
          }
        }
      }
      for (int i = 0; i < 2; ++i) {
        if (!have[i]) continue;
        const std::string cfg = std::string(isas[i].name) + (fused ? " fused " : " unfused ") + g.name;
        check(rows[i].bad == 0,
              cfg + ": eval_row_f = eval_f, all variants (" + std::to_string(rows[i].pixels) + " pixels)",
              rows[i].detail());
        if (in.slots == ML_SLOTS)
          check(recs[i].bad == 0,
                cfg + ": model_lighting_f_records = model_lighting_f, all variants (" + std::to_string(recs[i].pixels) +
                    " pixels)",
                recs[i].detail());
      }
    }
  }
  ts_batch_force_isa(-1);

  // The comparison discriminates: the fast path in the other fused-mad mode than the scalar
  // twin differs on a Phong variant (lerps and pow polynomials), so the zeros above are measured.
  if (host_fma) {
    const Variant *phong = nullptr;
    for (const Variant &v : variants)
      if (v.tier == Tier::SM3 && v.value("PHONG") && v.value("ENVMAP") && v.value("OUTPUT_MODE") == 2) phong = &v;
    const FamilyInputs &in = grids[0].in;
    long differ = 0;
    std::vector<ts_vec4f> got(static_cast<size_t>(in.w));
    for (int y = 0; phong && y < in.h; ++y) {
      ts_math_set_fused(1);
      fam->eval_row_f(*phong, in, 0, y, in.w, got.data());
      ts_math_set_fused(0);
      for (int x = 0; x < in.w; ++x) differ += !same_bits(got[x], fam->eval_f(*phong, in, x, y));
    }
    ts_math_set_fused(1);
    check(phong && differ > 0, "the check discriminates: fused fast path vs unfused scalar twin differ",
          std::to_string(differ) + " pixels differ");
    printf("  (%ld of %d pixels differ between the fused fast path and the unfused twin)\n", differ, in.w * in.h);
  }

  // world_lighting: the same row check on its random, hard and deferred grids.
  {
    const ShaderFamily *wl = find_family("world_lighting");
    const ShaderDecl *wdecl = nullptr;
    for (const ShaderDecl &d : decls)
      if (d.name == "world_lighting") wdecl = &d;
    check(wl && wl->eval_row_f && wdecl, "world_lighting has a fast path");
    if (wl && wl->eval_row_f && wdecl) {
      const std::vector<Variant> wvars = enumerate_variants(*wdecl, all_tiers(), &err);
      FamilyInputs wr, wh;
      wl->make_inputs(InputSet::Random, n, n, 4321u, &wr);
      wl->make_inputs(InputSet::Hard, n, n, 8765u, &wh);
      const FamilyInputs wd = deferred_copy(wr, wl->pixel_slots);
      for (int fused : fused_modes) {
        ts_math_set_fused(fused);
        check_family_rows(*wl, wvars, wr, "random", fused);
        check_family_rows(*wl, wvars, wh, "hard", fused);
        check_family_rows(*wl, wvars, wd, "deferred", fused);
      }
      ts_math_set_fused(host_fma);
    }
  }

  // The API on an empty batch writes nothing.
  {
    ts_vec4f sentinel = ts_v4f(7, 7, 7, 7);
    const ml_variant m = ml_variant_of(variants.front());
    const Views views(grids[0].in);
    model_lighting_f_records(&m, nullptr, &views.tex, &sentinel, 0);
    check(same_bits(sentinel, ts_v4f(7, 7, 7, 7)), "count 0 writes nothing");
  }
  return finish();
}

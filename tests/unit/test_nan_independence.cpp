// tiershade tests: the shaders do not lean on what an implementation does with NaN (issue 14,
// "Hard cases that are stable everywhere"; docs/conformance.md "The portable contract").
// Every variant of every family, on its random grid and on its hard grid (tests/conform/*.cases,
// every case at least twice), is evaluated by the scalar float32 twin (eval_f) under two NaN
// models of the builtins (c_ref/math/ts_math.h ts_set_nan_model): llvmpipe's (min/max return the
// non-NaN operand, log2(0) = -inf, pow(0, y) = 0) and a propagating one (any NaN operand of
// min/max/clamp/saturate/exp2/pow gives NaN, log2(0) = -127, pow(0, y) = exp2(-127 y), as
// SwiftShader's log2). A shader whose finite inputs make a NaN reach one of those builtins gives
// a different output in the two models; one that guards its inputs gives the same.
// Pixels of cases marked 'llvmpipe_only' (NaN or Inf written into the inputs) are skipped, and the
// grids' textures are sanitised first as the host contract does (NaN -> 0, +-Inf -> +-65504): the hard
// textures hold a few special texels on purpose, for llvmpipe. Both are outside the portable contract.
// Tolerance: |a - b| <= 2^-20 max(1, |a|) per channel. The two models differ on finite inputs only
// in pow(0, y), 0 against 2^(-127 y): for the y the shaders use (>= 1/2.4) that is below 2^-52, times
// colours up to 65504 (2^16), far below 2^-20. Any NaN in an output fails.
// Also: world_lighting's sm3 fast path and ps2b agree on Inf/NaN cube texels (check_cube_fast_path).
//
// Usage: build/tests/test_nan_independence   Prints PASS/FAIL lines and "N passed, N failed".
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "families/family.h"
#include "families/hard_cases.h"
#include "unit_check.h"
#include "unit_vec4.h"

namespace {

using unit_check::check;

bool close(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return false;
  if (a == b) return true;
  const float scale = std::fabs(a) > 1.0f ? std::fabs(a) : 1.0f;
  return std::fabs(a - b) <= scale * 0x1p-20f;
}

bool same(const ts_vec4f &a, const ts_vec4f &b) {
  return close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z) && close(a.w, b.w);
}

// The host contract on textures (docs/conformance.md): NaN -> 0, +-Inf -> +-65504. Returns the count.
int sanitise_textures(FamilyInputs *in) {
  int n = 0;
  for (TextureDesc &t : in->textures)
    for (float &f : t.rgba)
      if (!std::isfinite(f)) {
        f = std::isnan(f) ? 0.0f : (f > 0 ? 65504.0f : -65504.0f);
        ++n;
      }
  return n;
}

struct CaseTally {
  int variants = 0;  // variants with at least one differing pixel of this case
  std::string first;
};

void check_family(const ShaderFamily &fam, const std::vector<Variant> &variants) {
  const HardCases *cases = nullptr;
  std::string err;
  if (!family_hard_cases(fam, &cases, &err)) {
    check(false, std::string(fam.name) + ": hard cases", err);
    return;
  }
  for (InputSet set : {InputSet::Random, InputSet::Hard}) {
    // Every case at least twice (two random records under it).
    const int n = set == InputSet::Hard ? static_cast<int>(std::ceil(std::sqrt(2.0 * cases->cycle()))) + 1 : 24;
    FamilyInputs in;
    fam.make_inputs(set, n, n, 4242u, &in);
    const int sanitised = sanitise_textures(&in);
    std::map<std::string, CaseTally> tally;
    long checked = 0, bad = 0;
    for (const Variant &v : variants) {
      std::map<std::string, bool> seen;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const size_t i = static_cast<size_t>(y) * n + x;
          std::string label = "random";
          if (set == InputSet::Hard) {
            if (cases->cases[i % cases->cases.size()].llvmpipe_only) continue;
            label = cases->pixel_name(i);
          }
          ts_set_nan_model(TS_NAN_LLVMPIPE);
          const ts_vec4f a = fam.eval_f(v, in, x, y);
          ts_set_nan_model(TS_NAN_PROPAGATE);
          const ts_vec4f b = fam.eval_f(v, in, x, y);
          ts_set_nan_model(TS_NAN_LLVMPIPE);
          ++checked;
          if (same(a, b)) continue;
          ++bad;
          CaseTally &t = tally[label];
          if (!seen[label]) {
            seen[label] = true;
            if (t.variants++ == 0)
              t.first = v.name() + " pixel (" + std::to_string(x) + "," + std::to_string(y) + "): llvmpipe model " +
                        show(a) + ", propagating model " + show(b);
          }
        }
    }
    std::string detail;
    for (const auto &kv : tally)
      detail += "\n  case '" + kv.first + "': " + std::to_string(kv.second.variants) + " variants, e.g. " +
                kv.second.first;
    check(bad == 0,
          std::string(fam.name) + " " + input_set_name(set) + ": same output under both NaN models (" +
              std::to_string(checked) + " pixel evaluations" + ", " + std::to_string(sanitised) + " special texels sanitised" +
              ")",
          std::to_string(bad) + " differ:" + detail);
  }
}

// world_lighting's sm3 fast path (contrast 0, saturation 1, R0 1: the envmap terms skipped) and the
// ps2b path that computes them agree on the hard grid's special cube texels (65504, Inf, 1e30,
// NaN; not sanitised here): both clamp the texel to 65504 first. Before, an Inf texel gave 65504
// on sm3 and 0 on ps2b (Inf * (1 + Inf * 0) = NaN, clamped to 0). Bit for bit (same arithmetic).
void check_cube_fast_path(const std::vector<Variant> &variants) {
  const ShaderFamily *fam = find_family("world_lighting");
  const HardCases *cases = nullptr;
  std::string err;
  if (!fam || !family_hard_cases(*fam, &cases, &err)) {
    check(false, "world_lighting: hard cases for the cube fast-path check", err);
    return;
  }
  int env_params = -1;
  for (size_t k = 0; k < fam->slot_names.size(); ++k)
    if (fam->slot_names[k] == "env_params") env_params = static_cast<int>(k);
  const int n = 24;
  FamilyInputs in;
  fam->make_inputs(InputSet::Hard, n, n, 4242u, &in);
  long pixels = 0, bad = 0;
  std::string first;
  for (const Variant &sm3 : variants) {
    if (sm3.tier != Tier::SM3 || !sm3.value("ENVMAP")) continue;
    const Variant *ps2b = nullptr;
    for (const Variant &v : variants)
      if (v.tier == Tier::PS2B && v.values == sm3.values) ps2b = &v;
    if (!ps2b) continue;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const size_t i = static_cast<size_t>(y) * n + x;
        if (cases->cases[i % cases->cases.size()].name != "cube texel 65504/Inf/NaN") continue;
        ts_vec4f p = in.slot(x, y, env_params);
        p.x = 0.0f, p.y = 1.0f, p.w = 1.0f;
        in.set_slot(x, y, env_params, p);
        const ts_vec4f a = fam->eval_f(sm3, in, x, y), b = fam->eval_f(*ps2b, in, x, y);
        ++pixels;
        if (unit_check::bits_of(a.x) == unit_check::bits_of(b.x) && unit_check::bits_of(a.y) == unit_check::bits_of(b.y) &&
            unit_check::bits_of(a.z) == unit_check::bits_of(b.z))
          continue;
        if (bad++ == 0) first = sm3.name() + " (" + std::to_string(x) + "," + std::to_string(y) + "): sm3 " + show(a) + ", ps2b " + show(b);
      }
  }
  check(env_params >= 0 && pixels > 0 && bad == 0,
        "world_lighting: sm3 fast path = ps2b on special cube texels (" + std::to_string(pixels) + " pixels)",
        std::to_string(bad) + " differ; first " + first);
}

}  // namespace

int main() {
  std::vector<ShaderDecl> decls;
  std::string err;
  if (!load_shader_decls(&decls, &err)) {
    check(false, "load shader declarations", err);
    return unit_check::finish();
  }
  for (const ShaderFamily *fam : all_families()) {
    const ShaderDecl *decl = nullptr;
    for (const ShaderDecl &d : decls)
      if (d.name == fam->name) decl = &d;
    if (!decl) continue;  // a family without a declared shader is test_glue's concern
    const std::vector<Variant> variants = enumerate_variants(*decl, all_tiers(), &err);
    check(!variants.empty(), std::string(fam->name) + ": variants enumerated", err);
    check_family(*fam, variants);
    if (std::string(fam->name) == "world_lighting") check_cube_fast_path(variants);
  }
  return unit_check::finish();
}

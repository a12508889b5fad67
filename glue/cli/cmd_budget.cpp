// tiershade cli: `budget` subcommand: instruction slots per variant in the DX9-like
// model of glue/budget/ (docs/budget_model.md), checked against the tier limits:
// ps20 = ps_2_0 (64 arithmetic + 32 texture slots), ps2b = ps_2_b (512 slots), sm3 unlimited.
// With --nir, each variant's production program is also linked on OSMesa GL 3.3 under
// ST_DEBUG=nir and Mesa's scalar NIR is counted (glue/budget/nir_capture.h) as a cross-check of
// the model: nir_alu / alu must lie in [kNirRatioLo, kNirRatioHi].
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "shaderlib/assembler.h"
#include "budget/budget.h"
#include "families/family.h"
#include "budget/nir_capture.h"
#include "cli/select_args.h"

struct TierLimits {
  int alu, tex, total, constants, vectors;
};  // -1: no limit
// Float constant registers: ps_2_0 and ps_2_b 32, ps_3_0 224 (DirectX 9 pixel shader
// registers; docs/budget_model.md, "Constant registers"). Fragment uniform vectors: ps20, the
// WebGL 1 tier, within the 16 every ES 2.0 implementation has (docs/tiers.md, issue 14).
static TierLimits limits_for(Tier t) {
  switch (t) {
    case Tier::PS20:
      return {64, 32, 96, 32, 16};
    case Tier::PS2B:
      return {-1, -1, 512, 32, -1};
    case Tier::SM3:
      return {-1, -1, -1, 224, -1};
  }
  return {-1, -1, -1, -1, -1};
}
static std::string lim(int v) { return v < 0 ? "null" : std::to_string(v); }
static nlohmann::ordered_json lim_json(int v) {
  return v < 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v);
}

// Consistency band of the NIR cross-check: Mesa's scalar NIR ALU count over the model's
// DX9 ALU slots.  Measured on all 84 model_lighting variants (Mesa 22.3.6 llvmpipe):
// see docs/budget_model.md, "Cross-check against Mesa's NIR", for the table and the reasons.
static constexpr double kNirRatioLo = 0.8;
static constexpr double kNirRatioHi = 5.0;

int cmd_budget(int argc, char **argv) {
  Args a("budget", argc, argv, {"--help", "--json", "--verbose", "--nir"},
         {"--shader", "--tier", "--variant", "--known-over"});
  if (a.flag("--help")) {
    printf(
        "usage: tiershade budget [--json] [--verbose] [--nir] [--shader S] [--tier T]... [--variant V]\n"
        "Counts DX9-style instruction slots of each variant's production fragment shader\n"
        "(GLSL 3.30 -> SPIR-V -> the spirv-opt -O passes -> weight table, in process with the\n"
        "glslang and SPIRV-Tools libraries) and checks the tier limits:\n"
        "ps20 <= 64 arithmetic and <= 32 texture slots, ps2b <= 512 slots. Exit status 1 when\n"
        "a variant is over budget or fails to compile. Constant registers (the vec4 uniform slots\n"
        "the fragment stage uses, arrays at their used size) are checked too: ps20 and ps2b <= 32,\n"
        "sm3 <= 224 (DX9's ps_2_0, ps_2_b and ps_3_0). So are WebGL 1's fragment uniform vectors\n"
        "(vec: the uniforms the stage declares, arrays at their declared size): ps20 <= 16.\n"
        "--known-over FILE: lines 'SHADER VARIANT' known to exceed the constant registers alone;\n"
        "such a variant is reported ok (known over) while it does, and fails once it fits.\n"
        "--nir also links each production program on OSMesa GL 3.3 with ST_DEBUG=nir, counts\n"
        "the scalar ALU and texture ops of Mesa's fragment NIR (nir_alu, nir_tex; JSON also\n"
        "nir_ratio = nir_alu / alu), and fails a variant (exit status 1) whose nir_alu / alu\n"
        "is outside [%.1f, %.1f] (variants with alu 0 are not checked). Weight table:\n\n%s",
        kNirRatioLo, kNirRatioHi, budget_weight_table_markdown().c_str());
    return 0;
  }
  a.no_positional();
  // shader + " " + variant -> "FILE:LINE" of the --known-over list.
  std::map<std::string, std::string> known_over;
  if (a.has("--known-over")) {
    const std::string path = a.get("--known-over");
    std::ifstream in(path);
    if (!in) a.fail(path + ": cannot read");
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      const size_t hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      std::istringstream ls(line);
      std::string shader, variant, extra;
      if (!(ls >> shader)) continue;
      if (!(ls >> variant) || (ls >> extra)) a.fail(path + ":" + std::to_string(n) + ": 'SHADER VARIANT' expected");
      known_over[shader + " " + variant] = path + ":" + std::to_string(n);
    }
  }
  const bool nir = a.flag("--nir");
  // Mesa reads ST_DEBUG once, when the first screen is created: before any context.
  if (nir) nir_capture_setup_env();
  Selection sel;
  select_variants(a, &sel);
  const bool json = a.flag("--json");
  std::unique_ptr<GlContext> ctx;
  std::unique_ptr<GlRenderer> renderer;
  if (nir) {
    std::string err;
    ctx = GlContext::create(Backend::OSMesa, Api::GL33, &err);
    if (!ctx) {
      fprintf(stderr, "tiershade budget: --nir needs an OSMesa GL 3.3 context: %s\n", err.c_str());
      return 1;
    }
    renderer = std::make_unique<GlRenderer>(*ctx);
  }
  int over = 0, inconsistent = 0;
  if (json) printf("[\n");
  for (size_t i = 0; i < sel.variants.size(); ++i) {
    const Variant &v = sel.variants[i];
    Assembled fs;
    std::string err;
    BudgetCounts c;
    bool ok = assemble(v.shader->fragment, Target::GLSL330, Stage::Fragment, variant_defines(v, InputMode::Production),
                       &fs, &err) &&
        budget_count_fragment(fs.text, &c, &err);
    if (!ok) err = map_compile_log(err, fs);
    const TierLimits L = limits_for(v.tier);
    const bool slots_fit =
        ok && (L.alu < 0 || c.alu <= L.alu) && (L.tex < 0 || c.tex <= L.tex) && (L.total < 0 || c.total() <= L.total);
    const bool constants_fit = L.constants < 0 || c.constants <= L.constants;
    const bool vectors_fit = L.vectors < 0 || c.uniform_vectors <= L.vectors;
    bool fits = slots_fit && constants_fit && vectors_fit;
    auto known = known_over.find(v.shader->name + " " + v.name());
    std::string known_note;
    if (known != known_over.end()) {
      if (fits) {
        ok = false;
        err = "listed as over its constant registers (" + known->second + ") but fits: delete the line";
        fits = false;
      } else if (slots_fit && vectors_fit) {
        known_note = "  (known over: constants " + std::to_string(c.constants) + " > " + lim(L.constants) + ", " +
            known->second + ")";
        fits = true;
      }
    }
    if (!fits) ++over;
    // NIR cross-check.
    NirCounts nc;
    std::string nir_err;
    bool nir_ok = true, nir_counted = false, has_ratio = false;
    double ratio = 0;
    if (nir) {
      nir_counted = nir_count_production(*renderer, Api::GL33, v, &nc, &nir_err);
      if (!nir_counted) {
        nir_ok = false;
        nir_err = "NIR count failed: " + nir_err;
      } else if (ok && c.alu > 0) {
        has_ratio = true;
        ratio = static_cast<double>(nc.alu) / c.alu;
        if (ratio < kNirRatioLo || ratio > kNirRatioHi) {
          nir_ok = false;
          char b[160];
          snprintf(b, sizeof b, "inconsistent: nir_alu / alu = %d / %d = %.2f is outside [%.1f, %.1f]", nc.alu, c.alu,
                   ratio, kNirRatioLo, kNirRatioHi);
          nir_err = b;
        }
      }
      if (!nir_ok && fits) ++inconsistent;
    }
    if (json) {  // one object per line, keys in this order (tests/cli/test_budget_nir.sh reads them)
      nlohmann::ordered_json o;
      o["shader"] = v.shader->name;
      o["variant"] = v.name();
      o["tier"] = tier_name(v.tier);
      o["alu"] = c.alu;
      o["tex"] = c.tex;
      o["total"] = c.total();
      o["limit_alu"] = lim_json(L.alu);
      o["limit_tex"] = lim_json(L.tex);
      o["limit_total"] = lim_json(L.total);
      o["constants"] = c.constants;
      o["limit_constants"] = lim_json(L.constants);
      o["uniform_vectors"] = c.uniform_vectors;
      o["limit_uniform_vectors"] = lim_json(L.vectors);
      o["fits"] = fits;
      if (!known_note.empty()) o["known_over"] = true;
      if (nir) {
        o["nir_alu"] = nir_counted ? nlohmann::ordered_json(nc.alu) : nlohmann::ordered_json(nullptr);
        o["nir_tex"] = nir_counted ? nlohmann::ordered_json(nc.tex) : nlohmann::ordered_json(nullptr);
        // three decimals, as documented (docs/budget_model.md)
        o["nir_ratio"] =
            has_ratio ? nlohmann::ordered_json(std::round(ratio * 1000.0) / 1000.0) : nlohmann::ordered_json(nullptr);
      }
      printf("  %s%s\n", o.dump().c_str(), i + 1 < sel.variants.size() ? "," : "");
    } else {
      std::string extra;
      if (nir) {
        char b[96];
        if (nir_counted)
          snprintf(b, sizeof b, "  nir_alu %4d nir_tex %2d", nc.alu, nc.tex);
        else
          snprintf(b, sizeof b, "  nir_alu    ? nir_tex  ?");
        extra = b;
        if (has_ratio)
          snprintf(b, sizeof b, " ratio %4.2f", ratio);
        else
          snprintf(b, sizeof b, " ratio    -");
        extra += b;
      }
      printf("%s %-15s %-60s alu %3d tex %2d total %3d const %3d vec %3d  (limits alu %s tex %s total %s const %s vec %s)%s\n",
             !fits        ? "OVER"
                 : nir_ok ? "ok  "
                          : "FAIL",
             v.shader->name.c_str(), v.name().c_str(), c.alu, c.tex, c.total(), c.constants, c.uniform_vectors,
             lim(L.alu).c_str(), lim(L.tex).c_str(), lim(L.total).c_str(), lim(L.constants).c_str(),
             lim(L.vectors).c_str(), (extra + known_note).c_str());
      if (!ok) printf("  error: %s\n", err.c_str());
      if (!nir_ok) printf("  nir: %s\n", nir_err.c_str());
      if (a.flag("--verbose")) {
        for (const auto &kv : c.by_op) printf("      %-24s %d\n", kv.first.c_str(), kv.second);
        if (nir_counted)
          printf("      nir: fragment NIR printed by Mesa at %s (%zu bytes of dump, all stages)\n",
                 nc.printed_at.c_str(), nc.dump_bytes);
      }
    }
    if (!ok && json) fprintf(stderr, "tiershade budget: %s: %s\n", v.name().c_str(), err.c_str());
    if (!nir_ok && json) fprintf(stderr, "tiershade budget: %s: nir: %s\n", v.name().c_str(), nir_err.c_str());
  }
  if (json)
    printf("]\n");
  else if (!nir)
    printf("budget: %zu variants, %d over budget or failed\n", sel.variants.size(), over);
  else
    printf(
        "budget: %zu variants, %d over budget or failed, %d NIR-inconsistent or NIR count failed "
        "(band nir_alu/alu in [%.1f, %.1f])\n",
        sel.variants.size(), over, inconsistent, kNirRatioLo, kNirRatioHi);
  return over || inconsistent ? 1 : 0;
}

// tiershade: `budget` subcommand: instruction slots per variant in the DX9-like
// model of glue/budget.cpp (docs/budget_model.md), checked against the tier limits:
// ps20 = ps_2_0 (64 arithmetic + 32 texture slots), ps2b = ps_2_b (512 slots), sm3 unlimited.
#include <cstdio>

#include "assembler.h"
#include "budget.h"
#include "family.h"
#include "selection.h"

struct TierLimits { int alu, tex, total; };  // -1: no limit
static TierLimits limits_for(Tier t) {
  switch (t) {
    case Tier::PS20: return {64, 32, 96};
    case Tier::PS2B: return {-1, -1, 512};
    case Tier::SM3: return {-1, -1, -1};
  }
  return {-1, -1, -1};
}
static std::string lim(int v) { return v < 0 ? "null" : std::to_string(v); }

int cmd_budget(int argc, char **argv) {
  Args a("budget", argc, argv, {"--help", "--json", "--verbose"}, {"--shader", "--tier", "--variant"});
  if (a.flag("--help")) {
    printf("usage: tiershade budget [--json] [--verbose] [--shader S] [--tier T]... [--variant V]\n"
           "Counts DX9-style instruction slots of each variant's production fragment shader\n"
           "(GLSL 3.30 -> SPIR-V -> spirv-opt -O -> weight table) and checks the tier limits:\n"
           "ps20 <= 64 arithmetic and <= 32 texture slots, ps2b <= 512 slots. Exit status 1 when\n"
           "a variant is over budget or fails to compile. Weight table:\n\n%s",
           budget_weight_table_markdown().c_str());
    return 0;
  }
  if (!a.positional().empty()) a.fail("unexpected argument '" + a.positional()[0] + "'");
  Selection sel;
  select_variants(a, &sel);
  const bool json = a.flag("--json");
  int over = 0;
  if (json) printf("[\n");
  for (size_t i = 0; i < sel.variants.size(); ++i) {
    const Variant &v = sel.variants[i];
    Assembled fs;
    std::string err;
    BudgetCounts c;
    bool ok = assemble(v.shader->fragment, Target::GLSL330, Stage::Fragment, variant_defines(v, InputMode::Production), &fs, &err) &&
              budget_count_fragment(fs.text, &c, &err);
    if (!ok) err = map_compile_log(err, fs);
    const TierLimits L = limits_for(v.tier);
    const bool fits = ok && (L.alu < 0 || c.alu <= L.alu) && (L.tex < 0 || c.tex <= L.tex) &&
                      (L.total < 0 || c.total() <= L.total);
    if (!fits) ++over;
    if (json) {
      printf("  {\"shader\":\"%s\",\"variant\":\"%s\",\"tier\":\"%s\",\"alu\":%d,\"tex\":%d,\"total\":%d,"
             "\"limit_alu\":%s,\"limit_tex\":%s,\"limit_total\":%s,\"fits\":%s}%s\n",
             v.shader->name.c_str(), v.name().c_str(), tier_name(v.tier), c.alu, c.tex, c.total(), lim(L.alu).c_str(),
             lim(L.tex).c_str(), lim(L.total).c_str(), fits ? "true" : "false", i + 1 < sel.variants.size() ? "," : "");
    } else {
      printf("%s %-15s %-60s alu %3d tex %2d total %3d  (limits alu %s tex %s total %s)\n", fits ? "ok  " : "OVER",
             v.shader->name.c_str(), v.name().c_str(), c.alu, c.tex, c.total(), lim(L.alu).c_str(), lim(L.tex).c_str(),
             lim(L.total).c_str());
      if (!ok) printf("  error: %s\n", err.c_str());
      if (a.flag("--verbose"))
        for (const auto &kv : c.by_op) printf("      %-24s %d\n", kv.first.c_str(), kv.second);
    }
    if (!ok && json) fprintf(stderr, "tiershade budget: %s: %s\n", v.name().c_str(), err.c_str());
  }
  if (json) printf("]\n");
  else printf("budget: %zu variants, %d over budget or failed\n", sel.variants.size(), over);
  return over ? 1 : 0;
}

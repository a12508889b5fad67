// tiershade cli: variant and backend selection from the command line (see selection.h).
#include "cli/select_args.h"

#include <algorithm>

void select_variants(const Args &a, Selection *sel) {
  std::string err;
  if (!load_shader_decls(&sel->decls, &err)) a.fail(err);
  const std::string shader = a.get("--shader");
  std::vector<Tier> tiers;
  for (const auto &t : a.all("--tier")) {
    Tier x;
    if (!parse_tier(t, &x)) a.fail("unknown tier '" + t + "' (ps20, ps2b, sm3)");
    tiers.push_back(x);
  }
  if (tiers.empty()) tiers = all_tiers();
  bool found = shader.empty();
  for (const auto &d : sel->decls) {
    if (!shader.empty() && d.name != shader) continue;
    found = true;
    auto vars = enumerate_variants(d, tiers, &err);
    if (!err.empty()) a.fail(err);
    sel->variants.insert(sel->variants.end(), vars.begin(), vars.end());
  }
  if (!found) a.fail("no shader named '" + shader + "'");
  if (a.has("--variant")) {
    if (shader.empty()) a.fail("--variant needs --shader");
    Variant v;
    if (!find_variant(sel->decls, shader, a.get("--variant"), &v, &err)) a.fail(err);
    if (std::find(tiers.begin(), tiers.end(), v.tier) == tiers.end())
      a.fail("variant '" + v.name() + "' is not in the selected --tier");
    sel->variants = {v};
  }
}

std::vector<BackendApi> select_configs(const Args &a) {
  const std::string b = a.get("--backend", "all");
  const std::string api = a.get("--api", "all");
  std::vector<BackendApi> out;
  Backend bb = Backend::OSMesa;
  Api aa = Api::GL33;
  if (b != "all" && !parse_backend(b, &bb)) a.fail("unknown backend '" + b + "' (osmesa, egl, all)");
  if (b == "cpu") a.fail("this command compares GL with C; choose --backend osmesa or egl");
  if (api != "all" && !parse_api(api, &aa)) a.fail("unknown api '" + api + "' (gl33, gles2, gles3, all)");
  for (const auto &c : all_gl_configs()) {
    if (b != "all" && c.backend != bb) continue;
    if (api != "all" && c.api != aa) continue;
    out.push_back(c);
  }
  if (out.empty()) {
    std::string why;
    config_supported(bb, aa, &why);
    a.fail(why.empty() ? "no backend/api pair selected" : why);
  }
  return out;
}

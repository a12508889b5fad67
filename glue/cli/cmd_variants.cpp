// tiershade cli: `variants` and `assemble` subcommands.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "bundle/webgl.h"
#include "shaderlib/assembler.h"
#include "families/family.h"
#include "cli/select_args.h"

int cmd_variants_bundle(const Args &a);  // glue/cli/cmd_variants_bundle.cpp

// `tiershade variants --help`.
const char kHelp[] = R"(usage: tiershade variants [--list] [--json] [--count] [--shader S] [--tier ps20|ps2b|sm3]... [--target T]
       tiershade variants SCENE --tier T [--target essl100|essl300|glsl330] [--hdr integer|float] -o DIR
       tiershade variants --shader S [--variant V]... [--tier T]... [--target T] -o DIR
Lists every variant: tier x static combos x dynamic combos, minus the skip rules
declared in shaders/<shader>.variants. A variant is named TIER:NAME=V,... and can
also be given by its index in the full list of its shader. With --target and --list, --json
or --count, only the variants
that target offers: essl100 (WebGL 1) leaves out those needing an extension no browser
exposes (color_correction's 3D LUTs: sampler3D needs OES_texture_3D).
With -o DIR it writes a shader bundle for engines (docs/bundles.md): the self-contained
production GLSL of the variants a scene needs (or of the variants given), and
DIR/manifest.json with their defines, attributes, uniforms, sampler units and slots.
--target defaults to essl300. An existing DIR is replaced only if it is a bundle. The manifest
lists each variant's WebGL extensions; a scene on the float HDR path is refused for essl100
(WebGL 1 has no fp16 render targets: --hdr integer).)";

int cmd_variants(int argc, char **argv) {
  Args a("variants", argc, argv, {"--list", "--json", "--help", "--count"},
         {"--shader", "--tier", "--variant", "--target", "-o", "--hdr"});
  if (a.help(kHelp)) return 0;
  if (!a.positional().empty() && !a.has("-o"))
    a.fail("unexpected argument '" + a.positional()[0] +
           "' (a scene bundle: tiershade variants SCENE --tier T -o DIR)");
  // --target alone means a bundle (which then wants -o); with --list, --json or --count it filters.
  const bool listing = a.flag("--list") || a.flag("--json") || a.flag("--count");
  if (a.has("-o") || !a.positional().empty() || (a.has("--target") && !listing)) return cmd_variants_bundle(a);
  Selection sel;
  select_variants(a, &sel);
  if (a.has("--target")) {
    Target t;
    if (!parse_target(a.get("--target"), &t))
      a.fail("unknown target '" + a.get("--target") + "' (essl100, essl300, glsl330)");
    std::vector<Variant> kept;
    for (const auto &v : sel.variants) {
      bool offered = true;
      std::string why, err;
      if (!target_offers(v, t, &offered, &why, &err)) {
        fprintf(stderr, "tiershade variants: %s %s: %s\n", v.shader->name.c_str(), v.name().c_str(), err.c_str());
        return 1;
      }
      if (offered) kept.push_back(v);
    }
    sel.variants = kept;
  }
  if (a.flag("--count")) {
    printf("%zu\n", sel.variants.size());
    return 0;
  }
  if (a.flag("--json")) {
    // One object per line, in an array.
    printf("[\n");
    for (size_t i = 0; i < sel.variants.size(); ++i) {
      const Variant &v = sel.variants[i];
      nlohmann::ordered_json o, defines = nlohmann::ordered_json::object();
      o["shader"] = v.shader->name;
      o["variant"] = v.name();
      o["tier"] = tier_name(v.tier);
      for (const auto &kv : v.values) defines[kv.first] = kv.second;
      o["defines"] = defines;
      printf("  %s%s\n", o.dump().c_str(), i + 1 < sel.variants.size() ? "," : "");
    }
    printf("]\n");
    return 0;
  }
  std::string last;
  for (const auto &v : sel.variants) {
    if (v.shader->name != last) {
      printf("%s  (%s, %s)\n", v.shader->name.c_str(), v.shader->fragment.c_str(), v.shader->file.c_str());
      last = v.shader->name;
    }
    printf("  %s\n", v.name().c_str());
  }
  printf("%zu variants\n", sel.variants.size());
  return 0;
}

int cmd_assemble(int argc, char **argv) {
  Args a("assemble", argc, argv, {"--help", "--conform", "--vertex"}, {"--shader", "--variant", "--target"});
  if (a.flag("--help")) {
    puts(
        "usage: tiershade assemble --shader S --variant V [--target essl100|essl300|glsl330] [--vertex] [--conform]\n"
        "Prints the self-contained GLSL of one variant: #version and extensions, the target,\n"
        "stage and precision defines, the variant's #defines, shaders/ts_portability.glsl,\n"
        "then the entry with its includes resolved (#line directives kept).");
    return 0;
  }
  if (!a.has("--shader") || !a.has("--variant")) a.fail("--shader and --variant are required");
  Target t = Target::GLSL330;
  if (a.has("--target") && !parse_target(a.get("--target"), &t))
    a.fail("unknown target '" + a.get("--target") + "' (essl100, essl300, glsl330)");
  Selection sel;
  select_variants(a, &sel);
  const Variant &v = sel.variants.at(0);
  Assembled out;
  std::string err;
  const bool vertex = a.flag("--vertex");
  const std::string entry =
      vertex ? (a.flag("--conform") ? "conform_fullscreen.vs" : v.shader->vertex) : v.shader->fragment;
  if (!assemble(entry, t, vertex ? Stage::Vertex : Stage::Fragment,
                variant_defines(v, a.flag("--conform") ? InputMode::Conform : InputMode::Production), &out, &err)) {
    fprintf(stderr, "tiershade assemble: %s\n", err.c_str());
    return 1;
  }
  fputs(out.text.c_str(), stdout);
  return 0;
}

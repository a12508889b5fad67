// tiershade cli: `variants ... -o DIR`, shader bundles for engines (glue/bundle/bundle.h, docs/bundles.md):
// the variants a scene needs (SCENE --tier T) or the variants given (--shader S [--variant V]...).
#include <cstdio>

#include "bundle/bundle.h"
#include "cli/args.h"
#include "scene/selection.h"
#include "cli/select_args.h"

namespace {

Target bundle_target(const Args &a) {
  Target t = Target::ESSL300;
  if (a.has("--target") && !parse_target(a.get("--target"), &t))
    a.fail("unknown target '" + a.get("--target") + "' (essl100, essl300, glsl330)");
  return t;
}

int explicit_bundle(const Args &a, Target target) {
  if (!a.has("--shader")) a.fail("a bundle wants a SCENE or --shader S [--variant V]...");
  if (a.flag("--list") || a.flag("--json") || a.flag("--count"))
    a.fail("-o DIR does not go with --list, --json or --count");
  Selection sel;
  std::string err;
  const auto names = a.all("--variant");
  if (names.size() <= 1) {
    select_variants(a, &sel);
  } else {
    if (!load_shader_decls(&sel.decls, &err)) a.fail(err);
    for (const auto &n : names) {
      Variant v;
      if (!find_variant(sel.decls, a.get("--shader"), n, &v, &err)) a.fail(err);
      sel.variants.push_back(v);
    }
  }
  std::vector<BundleEntry> entries;
  for (const auto &v : sel.variants) entries.push_back({&v, {}});
  if (!write_bundle(entries, target, a.get("-o"), "explicit variants", &err)) {
    fprintf(stderr, "tiershade variants: %s\n", err.c_str());
    return 1;
  }
  for (const auto &v : sel.variants)
    printf("%s %s -> %s\n", v.shader->name.c_str(), v.name().c_str(), bundle_file_stem(v).c_str());
  printf("%zu variants written to %s (%s)\n", sel.variants.size(), a.get("-o").c_str(), target_name(target));
  return 0;
}

int scene_bundle(const Args &a, Target target) {
  const std::string path = a.positional()[0];
  const auto tiers = a.all("--tier");
  if (tiers.size() != 1) a.fail("a scene bundle wants exactly one --tier (ps20, ps2b, sm3)");
  Tier tier;
  if (!parse_tier(tiers[0], &tier)) a.fail("unknown tier '" + tiers[0] + "' (ps20, ps2b, sm3)");
  if (a.has("--shader") || a.has("--variant")) a.fail("--shader and --variant do not go with a SCENE");
  if (a.flag("--list") || a.flag("--json") || a.flag("--count"))
    a.fail("-o DIR does not go with --list, --json or --count");
  Scene scene;
  SceneSelection sel;
  std::string err;
  if (!load_scene(path, &scene, &err) || !select_scene_variants(scene, tier, a.get("--hdr"), &sel, &err)) a.fail(err);
  std::vector<BundleEntry> entries;
  for (size_t i = 0; i < sel.variants.size(); ++i)
    entries.push_back({&sel.variants[i], i < sel.variant_why.size() ? sel.variant_why[i] : std::vector<std::string>()});
  if (!write_bundle(entries, target, a.get("-o"), path, &err)) {
    fprintf(stderr, "tiershade variants: %s\n", err.c_str());
    return 1;
  }
  for (const auto &e : entries) {
    printf("%s %s -> %s/%s\n", e.variant->shader->name.c_str(), e.variant->name().c_str(),
           e.variant->shader->name.c_str(), bundle_file_stem(*e.variant).c_str());
    for (const auto &w : e.why) printf("    %s\n", w.c_str());
  }
  printf("%zu variants of %d combos written to %s (%s)\n", entries.size(), sel.all_combos, a.get("-o").c_str(),
         target_name(target));
  return 0;
}

}  // namespace

int cmd_variants_bundle(const Args &a) {
  const Target target = bundle_target(a);
  if (!a.has("-o")) a.fail("a bundle needs -o DIR");
  if (a.get("-o").empty()) a.fail("-o needs a directory name");
  if (a.positional().size() > 1) a.fail("unexpected argument '" + a.positional()[1] + "'");
  if (a.positional().empty()) return explicit_bundle(a, target);
  return scene_bundle(a, target);
}

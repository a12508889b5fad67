// tiershade cli: `variants ... -o DIR`, shader bundles for engines (glue/bundle/bundle.h, docs/bundles.md):
// the variants a scene needs (SCENE --tier T) or the variants given (--shader S [--variant V]...).
#include <cstdio>

#include "bundle/bundle.h"
#include "bundle/webgl.h"
#include "cli/args.h"
#include "scene/selection.h"
#include "cli/select_args.h"

namespace {

// Whether `target` offers v; a.fail()s on an assembly error (an internal error: shipped shaders assemble).
bool offered_on(const Args &a, const Variant &v, Target target, std::string *why) {
  bool offered = true;
  std::string err;
  if (!target_offers(v, target, &offered, why, &err)) a.fail(v.shader->name + " " + v.name() + ": " + err);
  return offered;
}

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
  // Named variants the target does not offer are refused; of a whole selection (--tier, or
  // --shader alone) they are left out, and said so.
  std::vector<Variant> kept;
  int left_out = 0;
  for (const auto &v : sel.variants) {
    std::string why;
    if (offered_on(a, v, target, &why)) {
      kept.push_back(v);
    } else if (a.has("--variant")) {
      a.fail(v.shader->name + " " + v.name() + " is not offered on " + target_name(target) + ": " + why);
    } else {
      ++left_out;
    }
  }
  if (kept.empty()) a.fail(std::string("none of the selected variants is offered on ") + target_name(target));
  sel.variants = kept;
  std::vector<BundleEntry> entries;
  for (const auto &v : sel.variants) entries.push_back({&v, {}});
  if (!write_bundle(entries, target, a.get("-o"), "explicit variants", &err)) {
    fprintf(stderr, "tiershade variants: %s\n", err.c_str());
    return 1;
  }
  for (const auto &v : sel.variants)
    printf("%s %s -> %s\n", v.shader->name.c_str(), v.name().c_str(), bundle_file_stem(v).c_str());
  printf("%zu variants written to %s (%s)\n", sel.variants.size(), a.get("-o").c_str(), target_name(target));
  if (left_out)
    printf("%d variants left out: %s does not offer them (tiershade variants --target %s --list)\n", left_out,
           target_name(target), target_name(target));
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
  // WebGL 1 / ES 2.0 cannot render the float HDR path: it draws linear radiance into RGBA16F
  // targets and its post passes read them back filtered (docs/hdr.md); ES 2.0 has neither
  // half-float colour targets nor their filtering in core, and tiershade's float path needs both.
  if (target == Target::ESSL100 && sel.hdr_path == "float")
    a.fail(path + ": the scene runs the float HDR path (" +
           (a.get("--hdr").empty() ? std::string("its hdr.path is \"float\"") : std::string("--hdr float")) +
           "), which needs fp16 render targets that essl100 (WebGL 1, ES 2.0) lacks; bundle it with --hdr integer, or for "
           "essl300");
  for (const auto &v : sel.variants) {
    std::string why;
    if (!offered_on(a, v, target, &why))
      a.fail(path + ": needs " + v.shader->name + " " + v.name() + ", which " + target_name(target) +
             " does not offer: " + why);
  }
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

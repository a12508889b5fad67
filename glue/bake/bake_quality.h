// tiershade bake: the bake's quality (docs/baking.md, "Quality"): the sampling and bounce settings
// of a lightmap bake, the named presets (draft: what `render` bakes at load; default: what
// `tiershade bake` bakes; final), a scene's or a command line's overrides of them, and what they
// set in a WorldBakeInput. The one source of these defaults: the baker's own structs
// (world_bake.h, bounce.h, sky.h) take theirs from kBakeDraft.
#pragma once
#include <string>

struct WorldBakeInput;

struct BakeQuality {
  const char *preset = "draft";  // the preset the values started from ("draft", "default", "final")
  double luxels_per_unit = 6;  // luxel density (scene units): a layout choice, no preset changes it
  int supersample = 2;  // direct light: n x n samples per luxel (vrad: 4 = 2 x 2, fact sheet section 1)
  int area_samples = 16;  // points per luxel and emitter (glue/bake/area_lights.h); 0: through the bounces
  int spread_samples = 30;  // a sun's jittered shadow rays per luxel (vrad's _sunspreadangle: 30)
  int sky_samples = 64;  // sky rays per luxel and value (glue/bake/sky.h)
  int bounces = 0;  // at most this many bounces (glue/bake/bounce.h; vrad: up to 100)
  int gather_rays = 64;  // per luxel, bounce and value
  double threshold = 1e-3;  // stop when a bounce adds at most this share of the light so far
};
inline constexpr BakeQuality kBakeDraft{};

// Overrides of a preset's values (a scene's lightmaps keys, a command line's options): a field
// below 0 is not set.
struct BakeQualityKeys {
  double luxels_per_unit = -1, threshold = -1;
  int supersample = -1, area_samples = -1, spread_samples = -1, sky_samples = -1, bounces = -1, gather_rays = -1;
  // The names of the fields that are set, as the scene spells them ("bounces, sky.samples"); empty: none.
  std::string names() const;
};

// The preset's values (luxel density: kBakeDraft's); false for a name that is not a preset.
bool bake_quality_preset(const std::string &name, BakeQuality *q);
// The presets' names, for messages: "draft, default or final".
const char *bake_quality_preset_names();
// q with the keys that are set applied.
BakeQuality bake_quality_with(BakeQuality q, const BakeQualityKeys &k);
// True when a and b bake the same (every value; the preset's name aside).
bool bake_quality_same(const BakeQuality &a, const BakeQuality &b);
// "final (supersample 4, ..., threshold 0.0001)": the preset and every value, for reports.
std::string bake_quality_text(const BakeQuality &q);
// The values in the bake's input (luxel density, samples, bounces; the sky's samples).
void apply_bake_quality(const BakeQuality &q, WorldBakeInput *in);

// tiershade bake: the quality presets and their overrides (bake_quality.h). The presets' values and
// what each costs and leaves as error on the shipped room: docs/baking.md ("Quality") and
// docs/accuracy_cost.md ("baking").
#include "bake/bake_quality.h"

#include <cstdio>

#include "bake/world_bake.h"

bool bake_quality_preset(const std::string &name, BakeQuality *q) {
  BakeQuality p;  // draft: direct light only (shadows, sky, area lights), the samples `render` bakes at load
  if (name == "draft") {
    p.preset = "draft";
  } else if (name == "default") {  // + the bounces, as vrad: up to 100, to the threshold
    p.preset = "default";
    p.bounces = 100;
  } else if (name == "final") {  // + 4 x the samples of every pass, a tenth of the threshold
    p.preset = "final";
    p.supersample = 4;
    p.area_samples = 64;
    p.spread_samples = 100;
    p.sky_samples = 256;
    p.bounces = 100;
    p.gather_rays = 256;
    p.threshold = 1e-4;
  } else {
    return false;
  }
  *q = p;
  return true;
}

const char *bake_quality_preset_names() { return "draft, default or final"; }

BakeQuality bake_quality_with(BakeQuality q, const BakeQualityKeys &k) {
  if (k.luxels_per_unit >= 0) q.luxels_per_unit = k.luxels_per_unit;
  if (k.threshold >= 0) q.threshold = k.threshold;
  if (k.supersample >= 0) q.supersample = k.supersample;
  if (k.area_samples >= 0) q.area_samples = k.area_samples;
  if (k.spread_samples >= 0) q.spread_samples = k.spread_samples;
  if (k.sky_samples >= 0) q.sky_samples = k.sky_samples;
  if (k.bounces >= 0) q.bounces = k.bounces;
  if (k.gather_rays >= 0) q.gather_rays = k.gather_rays;
  return q;
}

std::string BakeQualityKeys::names() const {
  std::string s;
  auto add = [&](bool set, const char *name) {
    if (set) s += (s.empty() ? "" : ", ") + std::string(name);
  };
  add(luxels_per_unit >= 0, "luxels_per_unit");
  add(supersample >= 0, "supersample");
  add(area_samples >= 0, "area_samples");
  add(spread_samples >= 0, "spread_samples");
  add(sky_samples >= 0, "sky.samples");
  add(bounces >= 0, "bounces");
  add(gather_rays >= 0, "gather_rays");
  add(threshold >= 0, "threshold");
  return s;
}

bool bake_quality_same(const BakeQuality &a, const BakeQuality &b) {
  return a.luxels_per_unit == b.luxels_per_unit && a.supersample == b.supersample && a.area_samples == b.area_samples &&
      a.spread_samples == b.spread_samples && a.sky_samples == b.sky_samples && a.bounces == b.bounces &&
      a.gather_rays == b.gather_rays && a.threshold == b.threshold;
}

std::string bake_quality_text(const BakeQuality &q) {
  BakeQuality p;
  const bool exact = bake_quality_preset(q.preset, &p) && (p.luxels_per_unit = q.luxels_per_unit, bake_quality_same(p, q));
  char b[400];
  snprintf(b, sizeof b,
           "%s%s (luxels_per_unit %.6g, supersample %d, area_samples %d, spread_samples %d, sky.samples %d, bounces "
           "%d, gather_rays %d, threshold %.6g)",
           q.preset, exact ? "" : " with overrides", q.luxels_per_unit, q.supersample, q.area_samples, q.spread_samples,
           q.sky_samples, q.bounces, q.gather_rays, q.threshold);
  return b;
}

void apply_bake_quality(const BakeQuality &q, WorldBakeInput *in) {
  in->luxels_per_unit = q.luxels_per_unit;
  in->supersample = q.supersample;
  in->area_samples = q.area_samples;
  in->spread_samples = q.spread_samples;
  in->sky.samples = q.sky_samples;
  in->bounce.max_bounces = q.bounces;
  in->bounce.gather_rays = q.gather_rays;
  in->bounce.threshold = q.threshold;
}

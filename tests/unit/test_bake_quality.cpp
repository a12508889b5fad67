// tiershade tests: the bake's quality presets (glue/bake/bake_quality.h):
//   - draft is the baker's own defaults (WorldBakeInput, BounceSettings, BakeSky take theirs from it);
//     default adds the bounces, final more samples of every pass; an unknown name is refused;
//   - overrides apply only the keys that are set, and name them;
//   - apply_bake_quality sets every value in a bake's input;
//   - the presets are ordered in error: a closed box (reflectivity 0.5) lit by a point light, baked at
//     draft, default and final against a converged bake (another seed, 1024 gather rays, bounces to
//     1e-6): RMS(draft) > RMS(default) > RMS(final), and final within 2 % of the converged RMS;
//   - final gives the same page bytes on 1 and 2 threads.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bake/bake_quality.h"
#include "bake/world_bake.h"
#include "unit_check.h"

namespace {

// The six inward faces of the box [0, 1]^3, reflectivity r, no emission, flat lightmaps only.
std::vector<WorldFace> box(double r) {
  auto face = [&](const char *name, ts_vec3d o, ts_vec3d u, ts_vec3d v, ts_vec3d n) {
    WorldFace f{name, o, u, v, 1, 1, -1, n};
    f.reflectivity = ts_v3d(r, r, r);
    f.bumped = false;
    return f;
  };
  return {face("floor", ts_v3d(0, 0, 0), ts_v3d(1, 0, 0), ts_v3d(0, 0, 1), ts_v3d(0, 1, 0)),
          face("ceiling", ts_v3d(0, 1, 0), ts_v3d(1, 0, 0), ts_v3d(0, 0, 1), ts_v3d(0, -1, 0)),
          face("x0", ts_v3d(0, 0, 0), ts_v3d(0, 0, 1), ts_v3d(0, 1, 0), ts_v3d(1, 0, 0)),
          face("x1", ts_v3d(1, 0, 0), ts_v3d(0, 0, 1), ts_v3d(0, 1, 0), ts_v3d(-1, 0, 0)),
          face("z0", ts_v3d(0, 0, 0), ts_v3d(1, 0, 0), ts_v3d(0, 1, 0), ts_v3d(0, 0, 1)),
          face("z1", ts_v3d(0, 0, 1), ts_v3d(1, 0, 0), ts_v3d(0, 1, 0), ts_v3d(0, 0, -1))};
}

bool bake(const BakeQuality &q, uint64_t seed, int threads, WorldBake *out) {
  WorldBakeInput in;
  in.faces = box(0.5);
  rnm_light l{};
  l.pos = ts_v3d(0.3, 0.8, 0.4);
  l.color = ts_v3d(1, 1, 1);
  l.atten[2] = 1;  // 1 / d^2
  in.lights = {l};
  in.probes = {ts_v3d(0.5, 0.5, 0.5)};
  in.page_w = 128;
  in.page_h = 32;
  in.cube_size = 4;
  apply_bake_quality(q, &in);
  in.bounce.seed = seed;
  in.bounce.threads = threads;
  std::string err;
  if (!bake_world(in, out, &err)) {
    check(false, "bake the box", err);
    return false;
  }
  return true;
}

double rms(const WorldBake &a, const WorldBake &b) {
  double d2 = 0;
  long n = 0;
  for (size_t i = 0; i < a.page.size() && a.page.size() == b.page.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = static_cast<double>(a.page[i]) - b.page[i];
    d2 += d * d;
    ++n;
  }
  return n ? std::sqrt(d2 / n) : INFINITY;
}

}  // namespace

int main() {
  // The presets and the baker's defaults.
  BakeQuality d, df, f;
  const WorldBakeInput in0;
  check(bake_quality_preset("draft", &d) && bake_quality_same(d, kBakeDraft) && std::strcmp(d.preset, "draft") == 0 &&
            in0.supersample == d.supersample && in0.area_samples == d.area_samples &&
            in0.spread_samples == d.spread_samples && in0.sky.samples == d.sky_samples &&
            in0.bounce.max_bounces == d.bounces && in0.bounce.gather_rays == d.gather_rays &&
            in0.bounce.threshold == d.threshold && in0.luxels_per_unit == d.luxels_per_unit,
        "draft: the baker's own defaults");
  check(bake_quality_preset("default", &df) && df.bounces == 100 && df.gather_rays == d.gather_rays &&
            df.supersample == d.supersample,
        "default: draft with up to 100 bounces");
  check(bake_quality_preset("final", &f) && f.bounces == 100 && f.gather_rays > df.gather_rays &&
            f.supersample > df.supersample && f.sky_samples > df.sky_samples && f.area_samples > df.area_samples &&
            f.spread_samples > df.spread_samples && f.threshold < df.threshold &&
            f.luxels_per_unit == d.luxels_per_unit,
        "final: more samples of every pass, a lower threshold, the same density");
  BakeQuality keep = f;
  check(!bake_quality_preset("best", &keep) && !bake_quality_preset("", &keep) && bake_quality_same(keep, f),
        "an unknown preset is refused, the quality untouched");
  // Overrides.
  BakeQualityKeys k;
  check(k.names().empty() && bake_quality_same(bake_quality_with(f, k), f), "no key: the preset unchanged");
  k.bounces = 3;
  k.sky_samples = 9;
  const BakeQuality o = bake_quality_with(f, k);
  check(o.bounces == 3 && o.sky_samples == 9 && o.gather_rays == f.gather_rays && !bake_quality_same(o, f) &&
            k.names() == "sky.samples, bounces" && bake_quality_text(o).find("final with overrides") == 0 &&
            bake_quality_text(f).find("final (") == 0,
        "keys override only what they set, and are named", bake_quality_text(o) + " / " + k.names());
  WorldBakeInput in;
  apply_bake_quality(o, &in);
  check(in.supersample == o.supersample && in.area_samples == o.area_samples && in.spread_samples == o.spread_samples &&
            in.sky.samples == 9 && in.bounce.max_bounces == 3 && in.bounce.gather_rays == o.gather_rays &&
            in.bounce.threshold == o.threshold && in.luxels_per_unit == o.luxels_per_unit,
        "apply_bake_quality sets every value of the input");

  // The presets ordered in error on the box (3 luxels per unit: 4 x 4 luxels a face).
  BakeQuality conv = f;
  conv.supersample = 8;
  conv.gather_rays = 1024;
  conv.threshold = 1e-6;
  for (BakeQuality *q : {&d, &df, &f, &conv}) q->luxels_per_unit = 3;
  WorldBake bd, bdf, bf, bc, bf2;
  if (!bake(d, 0, 0, &bd) || !bake(df, 0, 0, &bdf) || !bake(f, 0, 0, &bf) || !bake(conv, 1, 0, &bc) ||
      !bake(f, 0, 1, &bf2))
    return finish();
  const double ed = rms(bd, bc), edf = rms(bdf, bc), ef = rms(bf, bc);
  double ref_rms = 0;
  {
    WorldBake zero = bc;
    for (float &v : zero.page) v = 0;
    ref_rms = rms(bc, zero);
  }
  char msg[200];
  snprintf(msg, sizeof msg, "RMS draft %.5f, default %.5f, final %.5f (converged RMS %.5f, %d passes)", ed, edf, ef,
           ref_rms, bc.bounce.passes);
  printf("%s\n", msg);
  // Tolerance: final's 256 gather rays leave ~1/sqrt(256) of a bounce's noise per luxel, its
  // bounces ~1e-4 of the light unbaked; 2 % of the converged RMS is several times both.
  check(ed > edf && edf > ef && ef < 0.02 * ref_rms, "presets ordered in error: draft > default > final", msg);
  bool same = bf.page.size() == bf2.page.size() &&
      std::memcmp(bf.page.data(), bf2.page.data(), bf.page.size() * sizeof(float)) == 0;
  check(same, "final: the same page bytes on all cores and on 1 thread");
  return finish();
}

/* tiershade offline: the nearest ("best") cube-map probe of a surface (see envmap_probes.h). */
#include "offline/envmap_probes.h"

#include <math.h>
#include <stdio.h>

int env_pick_probe(ts_vec3d center, const ts_vec3d *probes, int num_probes, int explicit_index, char *err,
                   size_t errlen) {
  if (num_probes <= 0 || !probes) {
    snprintf(err, errlen, "env_pick_probe: the scene has no cube-map probe");
    return -1;
  }
  if (explicit_index >= 0) {
    if (explicit_index >= num_probes) {
      snprintf(err, errlen, "env_pick_probe: probe %d assigned, but the scene has %d", explicit_index, num_probes);
      return -1;
    }
    return explicit_index;
  }
  if (!isfinite(center.x) || !isfinite(center.y) || !isfinite(center.z)) {
    snprintf(err, errlen, "env_pick_probe: surface centre is not finite");
    return -1;
  }
  int best = -1;
  double best_d2 = 0.0;
  for (int i = 0; i < num_probes; ++i) {
    const ts_vec3d p = probes[i];
    if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z)) {
      snprintf(err, errlen, "env_pick_probe: probe %d has a non-finite position", i);
      return -1;
    }
    const double dx = p.x - center.x, dy = p.y - center.y, dz = p.z - center.z;
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (best < 0 || d2 < best_d2) {
      best = i;
      best_d2 = d2;
    }
  }
  return best;
}

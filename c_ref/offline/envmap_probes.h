/* tiershade offline: cube-map probes in a scene (talk: "World specular ... cube
 * maps are placed in the level, each surface uses the nearest"): each surface takes
 * the probe nearest to its centre, unless it names one explicitly (an env_cubemap
 * that lists the surface's sides overrides the choice). */
#ifndef TS_ENVMAP_PROBES_H
#define TS_ENVMAP_PROBES_H
#include <stddef.h>

#include "math/ts_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The probe for a surface centred at `center`: explicit_index when it is >= 0, else the
 * nearest probe (squared distance; the lowest index on a tie). Returns the index, or -1
 * with a message when there is no probe, the explicit index is out of range, or a
 * position is not finite. */
int env_pick_probe(ts_vec3d center, const ts_vec3d *probes, int num_probes, int explicit_index, char *err,
                   size_t errlen);

#ifdef __cplusplus
}
#endif
#endif

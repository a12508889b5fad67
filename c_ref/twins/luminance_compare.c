/* tiershade twins: instantiates the luminance_compare twin in float32
 * (llvmpipe-exact), double (accuracy reference) and intervals (GLSL ES 3.00 bounds). See luminance_compare_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/luminance_compare.h"

#define TS_TWIN_IMPL "twins/luminance_compare_impl.h"
#include "twins/twin_instances.h"

/* the third instance: luminance_compare_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

float luminance_compare_lum_f(const lc_variant *v, ts_vec4f color, float tone_map_scale) {
  return lc_lum_f(v, ts_v3f(color.x, color.y, color.z), tone_map_scale);
}

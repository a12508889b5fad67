/* tiershade twins: instantiates the color_correction twin in float32
 * (llvmpipe-exact) and double. See color_correction_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/color_correction.h"

#define TS_TWIN_IMPL "twins/color_correction_impl.h"
#include "twins/twin_instances.h"

/* the third instance: color_correction_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

ts_vec4f cc_lut_params(int n) {
  const float nf = (float)n;
  return ts_v4f((nf - 1.0f) / nf, 0.5f / nf, nf - 1.0f, 1.0f / nf);
}

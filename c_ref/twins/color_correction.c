/* tiershade twins: instantiates the color_correction twin in float32
 * (llvmpipe-exact) and double. See color_correction_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/color_correction.h"

#define TS_TWIN_IMPL "twins/color_correction_impl.h"
#include "twins/twin_instances.h"

ts_vec4f cc_lut_params(int n) {
  const float nf = (float)n;
  return ts_v4f((nf - 1.0f) / nf, 0.5f / nf, nf - 1.0f, 1.0f / nf);
}

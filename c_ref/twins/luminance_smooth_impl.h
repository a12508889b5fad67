/* tiershade twins: generic body of the luminance_smooth twin; mirrors
 * shaders/luminance_smooth.fs statement by statement. Instantiated by luminance_smooth.c through twin_instances.h; gives luminance_smooth_f / luminance_smooth_d, and
 * luminance_smooth_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes through
 * ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_hdr.h"

V4 FN(luminance_smooth)(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]) {
  V3 c = FN(xyz)(rec[LS_SLOT_COLOR]);
  TS_REAL prev = FROMF(rec[LS_SLOT_HISTORY].x);
  V4 params = FN(vec4_in)(rec[LS_SLOT_PARAMS]);
  if (v->input_encoding == 1) c = FN(srgb_decode3)(c);
  TS_REAL lum = MUL(FN(luminance)(c), params.y);
  TS_REAL s = M(clamp)(ADD(prev, MUL(params.x, SUB(lum, prev))), K(0.0), K(65504.0));
  return M(v4)(s, s, s, K(1.0));
}

/* tiershade twins: instantiates the luminance_compare twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See luminance_compare_impl.h. */
#include "twins/luminance_compare.h"

#include "math/ts_generic.h"

/* ---- float32 ---- */
#include "math/ts_generic_float.h"
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "twins/luminance_compare_impl.h"

/* ---- double ---- */
#include "math/ts_generic_double.h"
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "twins/luminance_compare_impl.h"

ts_vec4f luminance_compare_f(const lc_variant *v, const ts_vec4f rec[LC_SLOTS]) {
  return luminance_compare_impl_f(v, rec);
}
ts_vec4d luminance_compare_d(const lc_variant *v, const ts_vec4f rec[LC_SLOTS]) {
  return luminance_compare_impl_d(v, rec);
}
float luminance_compare_lum_f(const lc_variant *v, ts_vec4f color, float tone_map_scale) {
  return lc_lum_f(v, ts_v3f(color.x, color.y, color.z), tone_map_scale);
}

/* tiershade twins: instantiates the luminance_smooth twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See luminance_smooth_impl.h. */
#include "twins/luminance_smooth.h"

#include "math/ts_generic.h"

/* ---- float32 ---- */
#include "math/ts_generic_float.h"
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "twins/luminance_smooth_impl.h"

/* ---- double ---- */
#include "math/ts_generic_double.h"
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "twins/luminance_smooth_impl.h"

ts_vec4f luminance_smooth_f(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]) {
  return luminance_smooth_impl_f(v, rec);
}
ts_vec4d luminance_smooth_d(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]) {
  return luminance_smooth_impl_d(v, rec);
}

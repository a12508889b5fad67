/* c_ref/luminance_smooth.c: instantiates the luminance_smooth twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See luminance_smooth_impl.h. */
#include "luminance_smooth.h"

#include "ts_generic.h"

/* ---- float32 ---- */
#include "ts_generic_float.h"
#include "common_math.h"
#include "common_hdr.h"
#include "luminance_smooth_impl.h"

/* ---- double ---- */
#include "ts_generic_double.h"
#include "common_math.h"
#include "common_hdr.h"
#include "luminance_smooth_impl.h"

ts_vec4f luminance_smooth_f(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]) { return luminance_smooth_impl_f(v, rec); }
ts_vec4d luminance_smooth_d(const ls_variant *v, const ts_vec4f rec[LS_SLOTS]) { return luminance_smooth_impl_d(v, rec); }

/* tiershade twins: instantiates the luminance_smooth twin in float32
 * (llvmpipe-exact), double (accuracy reference) and intervals (GLSL ES 3.00 bounds). See luminance_smooth_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/luminance_smooth.h"

#define TS_TWIN_IMPL "twins/luminance_smooth_impl.h"
#include "twins/twin_instances.h"

/* the third instance: luminance_smooth_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

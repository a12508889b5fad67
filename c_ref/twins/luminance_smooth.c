/* tiershade twins: instantiates the luminance_smooth twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See luminance_smooth_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/luminance_smooth.h"

#define TS_TWIN_IMPL "twins/luminance_smooth_impl.h"
#include "twins/twin_instances.h"

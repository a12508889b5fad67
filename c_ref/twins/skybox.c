/* tiershade twins: instantiates the skybox twin in float32 (llvmpipe-exact) and double
 * (accuracy reference). See skybox_impl.h; twin_instances.h includes it once per precision. */
#include "twins/skybox.h"

#define TS_TWIN_IMPL "twins/skybox_impl.h"
#include "twins/twin_instances.h"

/* the third instance: skybox_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

/* tiershade twins: instantiates the model_lighting twin in float32
 * (llvmpipe-exact), double (accuracy reference) and intervals (GLSL ES 3.00 bounds). See model_lighting_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/model_lighting.h"

#define TS_TWIN_IMPL "twins/model_lighting_impl.h"
#include "twins/twin_instances.h"

/* the third instance: model_lighting_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

/* tiershade twins: instantiates the world_lighting twin in float32
 * (llvmpipe-exact), double (accuracy reference) and intervals (GLSL ES 3.00 bounds). See world_lighting_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/world_lighting.h"

#define TS_TWIN_IMPL "twins/world_lighting_impl.h"
#include "twins/twin_instances.h"

/* the third instance: world_lighting_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

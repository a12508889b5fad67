/* tiershade twins: instantiates the world_lighting twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See world_lighting_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/world_lighting.h"

#define TS_TWIN_IMPL "twins/world_lighting_impl.h"
#include "twins/twin_instances.h"

/* tiershade twins: instantiates the model_lighting twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See model_lighting_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/model_lighting.h"

#define TS_TWIN_IMPL "twins/model_lighting_impl.h"
#include "twins/twin_instances.h"

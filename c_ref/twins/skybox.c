/* tiershade twins: instantiates the skybox twin in float32 (llvmpipe-exact) and double
 * (accuracy reference). See skybox_impl.h; twin_instances.h includes it once per precision. */
#include "twins/skybox.h"

#define TS_TWIN_IMPL "twins/skybox_impl.h"
#include "twins/twin_instances.h"

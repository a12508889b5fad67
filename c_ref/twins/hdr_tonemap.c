/* tiershade twins: instantiates the hdr_tonemap twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See hdr_tonemap_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/hdr_tonemap.h"

#define TS_TWIN_IMPL "twins/hdr_tonemap_impl.h"
#include "twins/twin_instances.h"

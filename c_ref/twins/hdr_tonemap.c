/* tiershade twins: instantiates the hdr_tonemap twin in float32
 * (llvmpipe-exact), double (accuracy reference) and intervals (GLSL ES 3.00 bounds). See hdr_tonemap_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/hdr_tonemap.h"

#define TS_TWIN_IMPL "twins/hdr_tonemap_impl.h"
#include "twins/twin_instances.h"

/* the third instance: hdr_tonemap_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

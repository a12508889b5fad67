/* tiershade twins: instantiates the bloom_downsample twin in float32
 * (llvmpipe-exact), double (accuracy reference) and intervals (GLSL ES 3.00 bounds). See bloom_downsample_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/bloom_downsample.h"

#define TS_TWIN_IMPL "twins/bloom_downsample_impl.h"
#include "twins/twin_instances.h"

/* the third instance: bloom_downsample_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

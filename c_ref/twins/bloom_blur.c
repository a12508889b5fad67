/* tiershade twins: instantiates the bloom_blur twin in float32
 * (llvmpipe-exact), double (accuracy reference) and intervals (GLSL ES 3.00 bounds). See bloom_blur_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/bloom_blur.h"

#define TS_TWIN_IMPL "twins/bloom_blur_impl.h"
#include "twins/twin_instances.h"

/* the third instance: bloom_blur_iv, the interval of results GLSL ES 3.00 allows */
#include "math/ts_generic_interval.h"
#include TS_TWIN_IMPL

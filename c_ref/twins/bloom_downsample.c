/* tiershade twins: instantiates the bloom_downsample twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See bloom_downsample_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/bloom_downsample.h"

#define TS_TWIN_IMPL "twins/bloom_downsample_impl.h"
#include "twins/twin_instances.h"

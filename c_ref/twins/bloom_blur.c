/* tiershade twins: instantiates the bloom_blur twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See bloom_blur_impl.h;
 * twin_instances.h includes it once per precision. */
#include "twins/bloom_blur.h"

#define TS_TWIN_IMPL "twins/bloom_blur_impl.h"
#include "twins/twin_instances.h"

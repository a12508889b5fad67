/* tiershade twins: a scalar twin's two instances, for <family>.c only (once): includes TS_TWIN_IMPL
 * (its <family>_impl.h, as a string) with ts_generic_float.h's macros, giving <family>_f (float32,
 * llvmpipe-exact), then with ts_generic_double.h's, giving <family>_d (the accuracy reference). */
#include "math/ts_generic.h"

#include "math/ts_generic_float.h"
#include TS_TWIN_IMPL

#include "math/ts_generic_double.h"
#include TS_TWIN_IMPL

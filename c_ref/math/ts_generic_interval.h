/* tiershade math: select the interval instantiation (GLSL ES 3.00 precision bounds,
 * c_ref/math/ts_interval.h): M(pow) -> ts_powiv, V3 -> ts_vec3iv, K(0.5) -> ts_ivpoint(0.5f),
 * ADD/MUL/.../SEL through ts_generic.h's TS_OPS iv. */
#include "math/ts_interval.h"
#undef TS_SUFFIX
#undef TS_REAL
#undef TS_LIT
#undef TS_OPS
#define TS_SUFFIX iv
#define TS_REAL ts_iv
#define TS_LIT f
#define TS_OPS iv

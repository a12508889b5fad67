/* tiershade math: one instance of a SIMD twin, for ts_simd_instances.h only: with TSV_W, TSV_SFX, TSV_FUSED
 * and TSV_AVX defined (and the instruction set's `#pragma GCC target` pushed), includes the
 * lane layer (ts_simd.h), the samplers (2D LINEAR, 3D, 2D NEAREST) and the twin (TSV_IMPL),
 * then undefines what the next instance redefines. No include guard: once per instance. */
#include "math/ts_simd.h"
#include "math/ts_simd_sampler.h"
#include "math/ts_simd_sampler3d.h"
#include "math/ts_simd_sampler_nearest.h"
#include TSV_IMPL
#undef TSV_W
#undef TSV_SFX
#undef TSV_FUSED
#undef TSV_AVX
#undef VF
#undef VI
#undef VU
#undef V3v
#undef V4v

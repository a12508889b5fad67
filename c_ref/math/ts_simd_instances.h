/* tiershade math: the three instances of a SIMD twin: AVX2+FMA (8 lanes, fused mads, as llvmpipe fuses them on
 * FMA hosts), AVX2 (8 lanes, unfused) and SSE2 (4 lanes, unfused), each under
 * `#pragma GCC target` so that no build flag changes (-ffp-contract=off still holds: the only
 * fused operations are the FMA intrinsics of the fused instance). The includer defines
 * TSV_IMPL, the twin's *_simd_impl.h as a string, and includes this file once; each instance
 * is ts_simd_instance.h. Defines TS_BATCH_X86 on x86 hosts with GCC (elsewhere nothing is
 * instantiated and the batch calls run the scalar twin). */
#include "math/ts_sampler.h"
#include "math/ts_sampler3d.h"

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define TS_BATCH_X86 1
#include <immintrin.h>
/* a twin uses only some of the samplers: the others are unused static functions here */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"

#pragma GCC push_options
#pragma GCC target("avx2,fma")
#define TSV_W 8
#define TSV_SFX avx2fma
#define TSV_FUSED 1
#define TSV_AVX 1
#include "math/ts_simd_instance.h"
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx2")
#define TSV_W 8
#define TSV_SFX avx2
#define TSV_FUSED 0
#define TSV_AVX 1
#include "math/ts_simd_instance.h"
#pragma GCC pop_options

#define TSV_W 4
#define TSV_SFX sse2
#define TSV_FUSED 0
#define TSV_AVX 0
#include "math/ts_simd_instance.h"

#pragma GCC diagnostic pop
#endif

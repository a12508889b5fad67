/* tiershade math: the instruction-set choice of the batch twins (see ts_batch.h). */
#include "math/ts_batch.h"

#include "math/ts_math.h"

static int g_forced = -1;
static int g_host = -1;

static int host_isa(void) {
  if (g_host < 0) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_cpu_init();
    g_host = __builtin_cpu_supports("avx2") ? TS_BATCH_AVX2 : TS_BATCH_SSE2;
#else
    g_host = TS_BATCH_SCALAR;
#endif
  }
  return g_host;
}

static int host_fma(void) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __builtin_cpu_init();
  return __builtin_cpu_supports("fma");
#else
  return 0;
#endif
}

void ts_batch_force_isa(int isa) { g_forced = isa; }

int ts_batch_isa(void) {
  int isa = host_isa();
  if (g_forced >= 0 && g_forced < isa) isa = g_forced;
  /* fused mads need the FMA instance (AVX2+FMA); otherwise the scalar twin runs */
  if (ts_math_fused() && (isa != TS_BATCH_AVX2 || !host_fma())) isa = TS_BATCH_SCALAR;
  return isa;
}

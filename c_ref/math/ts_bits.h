/* tiershade math: a float32's bits and back, and DAZ where C code does not run through an SSE
 * arithmetic op (the one copy for ts_math.c, ts_sampler.c and tests/unit/test_ts_math.c). */
#ifndef TS_BITS_H
#define TS_BITS_H
#include <stdint.h>
#include <string.h>

static inline uint32_t ts_fbits(float f) {
  uint32_t u;
  memcpy(&u, &f, 4);
  return u;
}
static inline float ts_bitsf(uint32_t u) {
  float f;
  memcpy(&f, &u, 4);
  return f;
}
/* DAZ: a denormal operand is read as a zero of the same sign (what SSE sees under MXCSR.DAZ). */
static inline float ts_daz(float x) {
  const uint32_t u = ts_fbits(x);
  return (u & 0x7f800000u) == 0 ? ts_bitsf(u & 0x80000000u) : x;
}
#endif

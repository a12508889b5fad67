/* tiershade math: select the float32 (llvmpipe-exact) instantiation. */
#undef TS_SUFFIX
#undef TS_REAL
#undef TS_LIT
#undef TS_OPS
#define TS_SUFFIX f
#define TS_REAL float
#define TS_LIT f
#define TS_OPS plain

/* tiershade math: select the double (accuracy reference) instantiation. */
#undef TS_SUFFIX
#undef TS_REAL
#undef TS_LIT
#undef TS_OPS
#define TS_SUFFIX d
#define TS_REAL double
#define TS_LIT
#define TS_OPS plain

/* tiershade math: select the double (accuracy reference) instantiation. */
#undef TS_SUFFIX
#undef TS_REAL
#undef TS_LIT
#define TS_SUFFIX d
#define TS_REAL double
#define TS_LIT

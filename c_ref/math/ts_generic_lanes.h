/* tiershade math: the generic twin names of ts_generic.h on the TSV_W lanes of the current SIMD
 * instance (ts_simd.h), so that a batch twin can include a piece of a generic twin instead of
 * writing it again: M(add3) -> VFN(add3), FN(name) -> VFN(name), V3 -> V3v, TS_REAL -> VF,
 * K(0.5) -> 0.5f, SPLAT(k) -> k in every lane. Only for generic code that is pure arithmetic
 * (on lanes there is no ?: and a constructor takes lanes: constants go through SPLAT).
 * ADD/SUB/MUL/DIV/NEG are the C operators on lanes (as ts_generic.h's plain instances).
 * Used in batch translation units only, which never include ts_generic.h. */
#ifndef TS_GENERIC_LANES_H
#define TS_GENERIC_LANES_H
#define M(name) VFN(name)
#define FN(name) VFN(name)
#define V3 V3v
#define TS_REAL VF
#define K(x) TSV_CAT(x, f)
#define SPLAT(x) VFN(splat)(x)
#define ADD(a, b) ((a) + (b))
#define SUB(a, b) ((a) - (b))
#define MUL(a, b) ((a) * (b))
#define DIV(a, b) ((a) / (b))
#define NEG(a) (-(a))
#endif

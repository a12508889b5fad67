/* tiershade common: generic twin of shaders/common_phong.glsl (fact sheet section 5:
 * Fresnel ranges, Fresnel4, mix()). No include guard (instantiated per precision). */

static inline TS_REAL FN(fresnel_ranges)(TS_REAL NdotV, V3 ranges) {
  TS_REAL f = M(saturate)(SUB(K(1.0), NdotV));
  f = MUL(f, f);
  return ADD(ranges.y, MUL(SUB(f, K(0.5)), SEL(GE(f, K(0.5)), ranges.z, ranges.x)));
}

static inline TS_REAL FN(fresnel4)(TS_REAL NdotV) {
  TS_REAL f = M(saturate)(SUB(K(1.0), NdotV));
  f = MUL(f, f);
  return MUL(f, f);
}

/* GLSL mix() as llvmpipe lowers NIR's flrp (lower_flrp32; see common_phong.glsl):
 * a + (b - a) * t in general, (1 - t) + b * t when a is the constant 1. Unfused. The interval
 * instance widens each to every form an implementation may compute (ALT_LERP, ts_generic.h). */
static inline TS_REAL FN(lerp1)(TS_REAL a, TS_REAL b, TS_REAL t) {
  return ALT_LERP(ADD(a, MUL(SUB(b, a), t)), a, b, t);
}

static inline V3 FN(lerp3)(V3 a, V3 b, TS_REAL t) {
  return M(v3)(FN(lerp1)(a.x, b.x, t), FN(lerp1)(a.y, b.y, t), FN(lerp1)(a.z, b.z, t));
}

static inline TS_REAL FN(lerp_from_one)(TS_REAL b, TS_REAL t) {
  return ALT_LERP(ADD(SUB(K(1.0), t), MUL(b, t)), K(1.0), b, t);
}

static inline V3 FN(lerp3_from_one)(V3 b, TS_REAL t) {
  const TS_REAL u = SUB(K(1.0), t);
  return M(v3)(ALT_LERP(ADD(u, MUL(b.x, t)), K(1.0), b.x, t), ALT_LERP(ADD(u, MUL(b.y, t)), K(1.0), b.y, t),
               ALT_LERP(ADD(u, MUL(b.z, t)), K(1.0), b.z, t));
}

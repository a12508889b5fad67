/* tiershade common: generic twin of shaders/common_rnm.glsl (radiosity normal
 * mapping, fact sheet section 1; see ts_generic.h). No include guard on purpose. The batch
 * twin includes it on lanes too (ts_generic_lanes.h), hence SPLAT() on the constant vectors. */

#define WL_SQRT_2_OVER_3 K(0.816496580927726)
#define WL_OO_SQRT_6 K(0.408248290463863)
#define WL_OO_SQRT_2 K(0.707106781186548)
#define WL_OO_SQRT_3 K(0.577350269189626)
#define WL_NEG_OO_SQRT_6 K(-0.408248290463863)
#define WL_NEG_OO_SQRT_2 K(-0.707106781186548)

/* d_k = saturate(n . b_k)^2 + 1e-30 (TS_RNM_MIN_WEIGHT, not an fp16 number: 0 in fp16, see
 * shaders/common_rnm.glsl). The b0 dot has two terms (its y lane is 0 and
 * NIR drops it); the others are dot() with a constant vector (ts_dot3, last lane first). */
static V3 FN(rnm_weights)(V3 n) {
  V3 d = M(v3)(ADD(MUL(n.x, WL_SQRT_2_OVER_3), MUL(n.z, WL_OO_SQRT_3)),
               M(dot3)(n, M(v3)(SPLAT(WL_NEG_OO_SQRT_6), SPLAT(WL_OO_SQRT_2), SPLAT(WL_OO_SQRT_3))),
               M(dot3)(n, M(v3)(SPLAT(WL_NEG_OO_SQRT_6), SPLAT(WL_NEG_OO_SQRT_2), SPLAT(WL_OO_SQRT_3))));
  d = M(saturate3)(d);
  return M(add3)(M(mul3)(d, d), M(v3)(SPLAT(K(1.0e-30)), SPLAT(K(1.0e-30)), SPLAT(K(1.0e-30))));
}

static V3 FN(rnm_blend)(V3 d, V3 l0, V3 l1, V3 l2) {
  V3 s = M(add3)(M(add3)(M(scale3)(l0, d.x), M(scale3)(l1, d.y)), M(scale3)(l2, d.z));
  /* dot(d, vec3(1.0)): NIR folds the multiplies by 1 and keeps the sum's order (last lane first). */
  TS_REAL sum = ADD(d.x, ADD(d.y, d.z));
  return M(v3)(DIV(s.x, sum), DIV(s.y, sum), DIV(s.z, sum));
}

static V3 FN(ssbump_blend)(V3 t, V3 l0, V3 l1, V3 l2) {
  return M(add3)(M(add3)(M(scale3)(l0, t.x), M(scale3)(l1, t.y)), M(scale3)(l2, t.z));
}

static V3 FN(ssbump_direction)(V3 t) {
  return M(v3)(SUB(MUL(t.x, WL_SQRT_2_OVER_3), MUL(ADD(t.y, t.z), WL_OO_SQRT_6)), MUL(SUB(t.y, t.z), WL_OO_SQRT_2),
               MUL(ADD(ADD(t.x, t.y), t.z), WL_OO_SQRT_3));
}

static V3 FN(ssbump_normal)(V3 t) { return FN(safe_normalize)(FN(ssbump_direction)(t)); }

#undef WL_SQRT_2_OVER_3
#undef WL_OO_SQRT_6
#undef WL_OO_SQRT_2
#undef WL_OO_SQRT_3
#undef WL_NEG_OO_SQRT_6
#undef WL_NEG_OO_SQRT_2

/* c_ref/common/common_envmap.h: generic twin of shaders/common_envmap.glsl (world
 * specular, fact sheet section 6). No include guard on purpose. */

/* 2 (N.E) N - (N.N) E */
static V3 FN(reflect_unnormalized)(V3 N, V3 E) {
  return M(sub3)(M(scale3)(N, K(2.0) * M(dot3)(N, E)), M(scale3)(E, M(dot3)(N, N)));
}

static V3 FN(envmap_contrast)(V3 s, TS_REAL contrast) {
  return M(add3)(s, M(scale3)(M(sub3)(M(mul3)(s, s), s), contrast));
}

static V3 FN(envmap_saturation)(V3 s, TS_REAL saturation) {
  TS_REAL luma = M(dot3)(s, M(v3)(K(0.299), K(0.587), K(0.114)));
  V3 d = M(scale3)(M(sub3)(s, M(v3)(luma, luma, luma)), saturation);
  return M(v3)(luma + d.x, luma + d.y, luma + d.z);
}

/* N.E / sqrt((N.N)(E.E)), the product clamped to 1e-30 (ps20). */
static TS_REAL FN(cosine_between)(V3 N, V3 E) {
  return M(dot3)(N, E) * M(inversesqrt)(M(max)(M(dot3)(N, N) * M(dot3)(E, E), K(1.0e-30)));
}

static TS_REAL FN(fresnel)(TS_REAL NdotV, TS_REAL one_minus_r0, TS_REAL r0) {
  TS_REAL x = K(1.0) - M(saturate)(NdotV);
  TS_REAL x2 = x * x;
  return (x2 * x2) * (x * one_minus_r0) + r0;
}

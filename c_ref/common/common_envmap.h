/* tiershade common: generic twin of shaders/common_envmap.glsl (world
 * specular, fact sheet section 6). No include guard on purpose. */

/* 2 (N.E) N - (N.N) E */
static V3 FN(reflect_unnormalized)(V3 N, V3 E) {
  return M(sub3)(M(scale3)(N, MUL(K(2.0), M(dot3)(N, E))), M(scale3)(E, M(dot3)(N, N)));
}

/* GLSL mix() as Mesa compiles it for llvmpipe (docs/conformance.md, measured in the NIR that
 * ST_DEBUG=nir prints), unfused:
 * mix(s, s*s, contrast): nir_opt_algebraic turns flrp(a, a*b, t) into a * flrp(1, b, t), and
 * flrp(1, b, t) is lowered to (1 - t) + b*t: s * ((1 - c) + s*c).
 * The interval instance widens it to every form an implementation may compute (ALT_LERP,
 * ts_generic.h): the spec's s (1 - c) + (s s) c, and s + (s s - s) c. */
static V3 FN(envmap_contrast)(V3 s, TS_REAL contrast) {
  const TS_REAL u = SUB(K(1.0), contrast);
  return M(v3)(ALT_LERP(MUL(ADD(u, MUL(s.x, contrast)), s.x), s.x, MUL(s.x, s.x), contrast),
               ALT_LERP(MUL(ADD(u, MUL(s.y, contrast)), s.y), s.y, MUL(s.y, s.y), contrast),
               ALT_LERP(MUL(ADD(u, MUL(s.z, contrast)), s.z), s.z, MUL(s.z, s.z), contrast));
}

/* mix(vec3(luma), s, saturation): the same a and t in all three lanes, so nir_lower_flrp picks the
 * form whose a*(1 - t) the lanes share: luma*(1 - t) + s*t. The interval instance widens it to
 * luma + (s - luma) t too, SwiftShader's (measured: 16-53 ULP outside without it, on a channel
 * much dimmer than the luma). */
static V3 FN(envmap_saturation)(V3 s, TS_REAL saturation) {
  TS_REAL luma = M(dot3)(s, M(v3)(K(0.299), K(0.587), K(0.114)));
  const TS_REAL a = MUL(luma, SUB(K(1.0), saturation));
  return M(v3)(ALT_LERP(ADD(a, MUL(s.x, saturation)), luma, s.x, saturation),
               ALT_LERP(ADD(a, MUL(s.y, saturation)), luma, s.y, saturation),
               ALT_LERP(ADD(a, MUL(s.z, saturation)), luma, s.z, saturation));
}

/* N.E / sqrt((N.N)(E.E)), the product clamped to 1e-30 (ps20; TS_MIN_LENGTH2, not an fp16
 * number: 0 in fp16, shaders/common_math.glsl). */
static TS_REAL FN(cosine_between)(V3 N, V3 E) {
  return MUL(M(dot3)(N, E), M(inversesqrt)(M(max)(MUL(M(dot3)(N, N), M(dot3)(E, E)), K(1.0e-30))));
}

static TS_REAL FN(fresnel)(TS_REAL NdotV, TS_REAL one_minus_r0, TS_REAL r0) {
  TS_REAL x = SUB(K(1.0), M(saturate)(NdotV));
  TS_REAL x2 = MUL(x, x);
  return ADD(MUL(MUL(x2, x2), MUL(x, one_minus_r0)), r0);
}

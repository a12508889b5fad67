/* tiershade common: generic twin of shaders/common_output.glsl (FinalOutput,
 * fact sheet section 7; sRGB curve, section 2). No include guard. */

static inline V3 FN(output_linear)(V3 c) {
  return M(v3)(M(clamp)(c.x, K(0.0), K(65504.0)), M(clamp)(c.y, K(0.0), K(65504.0)), M(clamp)(c.z, K(0.0), K(65504.0)));
}

static inline V3 FN(output_gamma22)(V3 c) {
  const TS_REAL e = DIV(K(1.0), K(2.2));
  V3 s = M(saturate3)(c);
  const TS_REAL t = K(TS_POW_TINY_C);
  return M(saturate3)(M(v3)(M(pow)(M(max)(s.x, t), e), M(pow)(M(max)(s.y, t), e), M(pow)(M(max)(s.z, t), e)));
}

static inline TS_REAL FN(srgb_encode)(TS_REAL x) {
  return SEL(LE(x, K(0.0031308)), MUL(K(12.92), x), SUB(MUL(K(1.055), M(pow)(M(max)(x, K(TS_POW_TINY_C)), DIV(K(1.0), K(2.4)))), K(0.055)));
}

static inline V3 FN(output_srgb)(V3 c) {
  V3 s = M(saturate3)(c);
  return M(saturate3)(M(v3)(FN(srgb_encode)(s.x), FN(srgb_encode)(s.y), FN(srgb_encode)(s.z)));
}

static inline V3 FN(final_output)(V3 c, TS_REAL tone_map_scale, int mode) {
  c = M(scale3)(c, tone_map_scale);
  if (mode == 1) return FN(output_gamma22)(c);
  if (mode == 2) return FN(output_srgb)(c);
  return FN(output_linear)(c);
}

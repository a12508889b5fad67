/* tiershade common: generic twin of shaders/common_lightmap.glsl (lightmap
 * page addressing and the four texel decodes, fact sheet sections 1 and 2).
 * No include guard on purpose. */

static V2 FN(lightmap_uv)(V2 uv, V2 offset, TS_REAL k) { return M(v2)(ADD(uv.x, MUL(k, offset.x)), ADD(uv.y, MUL(k, offset.y))); }

/* (2 t)^2.2: gamma 2.2 after undoing the overbright-2 pre-division. */
static V3 FN(lightmap_ldr_to_linear)(V3 t) {
  V3 s = M(scale3)(t, K(2.0));
  const TS_REAL m = K(TS_POW_TINY_C); /* base >= 2^-60 (shaders/common_math.glsl) */
  return M(v3)(M(pow)(M(max)(s.x, m), K(2.2)), M(pow)(M(max)(s.y, m), K(2.2)), M(pow)(M(max)(s.z, m), K(2.2)));
}

/* ps20: (2 t)^2 (Source's X360 approximation of the overbright-2 gamma decode). */
static V3 FN(lightmap_ldr_to_linear_fast)(V3 t) {
  V3 s = M(scale3)(t, K(2.0));
  V3 q = M(mul3)(s, s);
  return M(v3)(M(min)(q.x, K(4.0)), M(min)(q.y, K(4.0)), M(min)(q.z, K(4.0)));
}

/* 0 float, 1 "4.12" (x 16), 2 LDR, 3 RGBE (rgb x 2^(255 a - 128)). */
static V3 FN(lightmap_decode)(V4 t, int encoding) {
  V3 rgb = M(v3)(t.x, t.y, t.z);
  if (encoding == 1) return M(scale3)(rgb, K(16.0));
  if (encoding == 2) return FN(lightmap_ldr_to_linear)(rgb);
  if (encoding == 3) return M(scale3)(rgb, M(exp2)(SUB(MUL(t.w, K(255.0)), K(128.0))));
  return rgb;
}

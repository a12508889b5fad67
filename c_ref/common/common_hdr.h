/* tiershade common: generic twin of shaders/common_hdr.glsl (luminance with the
 * weights of fact sheet section 8, the bucket test, the exact sRGB decode of fact
 * sheet section 2, the bloom shaping p^exp * dot(p, tint) of section 8).
 * No include guard (instantiated per precision, see ts_generic.h). */

static inline TS_REAL FN(luminance)(V3 c) { return M(dot3)(c, M(v3)(K(0.2125), K(0.7154), K(0.0721))); }

static inline TS_REAL FN(in_bucket)(TS_REAL lum, TS_REAL lo, TS_REAL hi) { return MUL(M(step)(lo, lum), M(step)(lum, hi)); }

static inline TS_REAL FN(srgb_decode)(TS_REAL x) {
  return SEL(LE(x, K(0.04045)), DIV(x, K(12.92)), M(pow)(DIV(ADD(x, K(0.055)), K(1.055)), K(2.4)));
}

static inline V3 FN(srgb_decode3)(V3 c) {
  return M(v3)(FN(srgb_decode)(c.x), FN(srgb_decode)(c.y), FN(srgb_decode)(c.z));
}

static inline V3 FN(bloom_shape)(V3 p, V4 shape) {
  const TS_REAL d = M(dot3)(p, M(v3)(shape.x, shape.y, shape.z));
  const TS_REAL m = K(TS_POW_TINY_C); /* base >= 2^-60 (shaders/common_math.glsl) */
  return M(scale3)(M(v3)(M(pow)(M(max)(p.x, m), shape.w), M(pow)(M(max)(p.y, m), shape.w), M(pow)(M(max)(p.z, m), shape.w)), d);
}

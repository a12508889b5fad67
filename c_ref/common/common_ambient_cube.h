/* tiershade common: generic twin of shaders/common_ambient_cube.glsl.
 * Fact sheet section 3: n.x^2 C[x sign] + n.y^2 C[y sign] + n.z^2 C[z sign],
 * order +X -X +Y -Y +Z -Z. No include guard (instantiated per precision). */

static inline V3 FN(ambient_cube)(V3 n, const V3 c[6]) {
  V3 n2 = M(mul3)(n, n);
  V3 cx = SEL3(GE(n.x, K(0.0)), c[0], c[1]);
  V3 cy = SEL3(GE(n.y, K(0.0)), c[2], c[3]);
  V3 cz = SEL3(GE(n.z, K(0.0)), c[4], c[5]);
  return M(add3)(M(add3)(M(scale3)(cx, n2.x), M(scale3)(cy, n2.y)), M(scale3)(cz, n2.z));
}

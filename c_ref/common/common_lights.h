/* tiershade common: generic twin of shaders/common_lights.glsl.
 * Fact sheet section 4: attenuation 1/(c + l d + q d^2); spot
 * saturate(pow(max(1e-4, (cos - spot.z) spot.w), spot.x)); half-Lambert
 * saturate(0.5 N.L + 0.5)^2. A light is 5 vec4: color, dir, pos, spot, atten.
 * No include guard (instantiated per precision). */

static inline TS_REAL FN(light_attenuation)(const V4 l[5], V3 P, V3 *L) {
  V3 Lv = M(sub3)(FN(xyz4)(l[2]), P);
  /* TS_MIN_LENGTH2 and TS_MAX_LIGHT_DISTANCE: neither is an fp16 number (0 and +Inf in fp16:
   * what that does to mediump shaders is in shaders/common_lights.glsl). */
  TS_REAL d2 = M(max)(M(dot3)(Lv, Lv), K(1.0e-30));
  TS_REAL rinv = M(inversesqrt)(d2);
  TS_REAL d = M(min)(MUL(d2, rinv), K(1.0e18));
  int directional = GT(l[0].w, K(0.5));
  *L = SEL3(directional, M(neg3)(FN(xyz4)(l[1])), M(scale3)(Lv, rinv));
  TS_REAL dist_att = DIV(K(1.0), M(max)(ADD(ADD(l[4].x, MUL(l[4].y, d)), MUL(l[4].z, MUL(d, d))), K(1.0e-30)));
  dist_att = SEL(directional, K(1.0), dist_att);
  TS_REAL cos_a = M(dot3)(M(neg3)(*L), FN(xyz4)(l[1]));
  TS_REAL spot = M(saturate)(M(pow)(M(max)(K(1.0e-4), MUL(SUB(cos_a, l[3].z), l[3].w)), l[3].x));
  spot = SEL(GT(l[1].w, K(0.5)), spot, K(1.0));
  return MUL(dist_att, spot);
}

/* ps20: direction only; the attenuation arrives interpolated from the vertex shader. */
static inline V3 FN(light_direction)(const V4 l[5], V3 P) {
  V3 Lv = M(sub3)(FN(xyz4)(l[2]), P);
  TS_REAL rinv = M(inversesqrt)(M(max)(M(dot3)(Lv, Lv), K(1.0e-30))); /* TS_MIN_LENGTH2: 0 in fp16 */
  return SEL3(GT(l[0].w, K(0.5)), M(neg3)(FN(xyz4)(l[1])), M(scale3)(Lv, rinv));
}

static inline TS_REAL FN(half_lambert)(TS_REAL NdotL) {
  TS_REAL h = M(saturate)(ADD(MUL(K(0.5), NdotL), K(0.5)));
  return MUL(h, h);
}

static inline TS_REAL FN(lambert)(TS_REAL NdotL) { return M(saturate)(NdotL); }

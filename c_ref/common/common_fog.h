/* tiershade common: generic twin of shaders/common_fog.glsl (Source's pixel range
 * fog, fact sheet section 7). No include guard on purpose. */

static V3 FN(range_fog)(V3 c, TS_REAL depth, V4 fog_color, V4 fog_params) {
  TS_REAL f = M(saturate)(M(min)(fog_color.w, SUB(MUL(depth, fog_params.x), fog_params.y)));
  return M(add3)(c, M(scale3)(M(sub3)(M(v3)(fog_color.x, fog_color.y, fog_color.z), c), MUL(f, f)));
}

/* tiershade common: generic twin of shaders/common_color_correction.glsl
 * (texel-centre addressing, fact sheet section 9; the lattice cell and the lerps of
 * shader trilinear filtering). Needs FN(cc_tex2d) and FN(cc_tex3d) defined by the
 * includer (the sampler of each precision). No include guard: included once per precision. */

/* uvw = c * (N-1)/N + 0.5/N: mul, then add (GLSL a*b + c is unfused on llvmpipe). */
static V3 FN(cc_uvw)(V3 c, V4 lut) {
  return M(v3)(ADD(MUL(c.x, lut.x), lut.y), ADD(MUL(c.y, lut.x), lut.y), ADD(MUL(c.z, lut.x), lut.y));
}

static void FN(cc_cell)(V3 c, V4 lut, V3 *i0, V3 *i1, V3 *f) {
  V3 p = M(scale3)(c, lut.z);
  *i0 = M(v3)(M(floor)(p.x), M(floor)(p.y), M(floor)(p.z));
  *f = M(sub3)(p, *i0);
  *i1 = M(v3)(M(min)(ADD(i0->x, K(1.0)), lut.z), M(min)(ADD(i0->y, K(1.0)), lut.z), M(min)(ADD(i0->z, K(1.0)), lut.z));
}

static V3 FN(cc_centre)(V3 i, V4 lut) {
  return M(v3)(MUL(ADD(i.x, K(0.5)), lut.w), MUL(ADD(i.y, K(0.5)), lut.w), MUL(ADD(i.z, K(0.5)), lut.w));
}

static V3 FN(cc_lerp)(V3 a, V3 b, TS_REAL t) { return M(add3)(a, M(scale3)(M(sub3)(b, a), t)); }

static V3 FN(cc_atlas_hw)(const ts_tex2d *lut, V2 uv0, V2 uv1, TS_REAL fz) {
  return FN(cc_lerp)(FN(cc_tex2d)(lut, uv0.x, uv0.y), FN(cc_tex2d)(lut, uv1.x, uv1.y), fz);
}

static V3 FN(cc_atlas_shader)(const ts_tex2d *lut, V4 u, V2 v, V3 f) {
  V3 t000 = FN(cc_tex2d)(lut, u.x, v.x);
  V3 t100 = FN(cc_tex2d)(lut, u.y, v.x);
  V3 t010 = FN(cc_tex2d)(lut, u.x, v.y);
  V3 t110 = FN(cc_tex2d)(lut, u.y, v.y);
  V3 t001 = FN(cc_tex2d)(lut, u.z, v.x);
  V3 t101 = FN(cc_tex2d)(lut, u.w, v.x);
  V3 t011 = FN(cc_tex2d)(lut, u.z, v.y);
  V3 t111 = FN(cc_tex2d)(lut, u.w, v.y);
  V3 s0 = FN(cc_lerp)(FN(cc_lerp)(t000, t100, f.x), FN(cc_lerp)(t010, t110, f.x), f.y);
  V3 s1 = FN(cc_lerp)(FN(cc_lerp)(t001, t101, f.x), FN(cc_lerp)(t011, t111, f.x), f.y);
  return FN(cc_lerp)(s0, s1, f.z);
}

static V3 FN(cc_volume_hw)(const ts_tex3d *lut, V3 uvw) { return FN(cc_tex3d)(lut, uvw); }

static V3 FN(cc_volume_shader)(const ts_tex3d *lut, V3 c0, V3 c1, V3 f) {
  V3 t000 = FN(cc_tex3d)(lut, M(v3)(c0.x, c0.y, c0.z));
  V3 t100 = FN(cc_tex3d)(lut, M(v3)(c1.x, c0.y, c0.z));
  V3 t010 = FN(cc_tex3d)(lut, M(v3)(c0.x, c1.y, c0.z));
  V3 t110 = FN(cc_tex3d)(lut, M(v3)(c1.x, c1.y, c0.z));
  V3 t001 = FN(cc_tex3d)(lut, M(v3)(c0.x, c0.y, c1.z));
  V3 t101 = FN(cc_tex3d)(lut, M(v3)(c1.x, c0.y, c1.z));
  V3 t011 = FN(cc_tex3d)(lut, M(v3)(c0.x, c1.y, c1.z));
  V3 t111 = FN(cc_tex3d)(lut, M(v3)(c1.x, c1.y, c1.z));
  V3 s0 = FN(cc_lerp)(FN(cc_lerp)(t000, t100, f.x), FN(cc_lerp)(t010, t110, f.x), f.y);
  V3 s1 = FN(cc_lerp)(FN(cc_lerp)(t001, t101, f.x), FN(cc_lerp)(t011, t111, f.x), f.y);
  return FN(cc_lerp)(s0, s1, f.z);
}

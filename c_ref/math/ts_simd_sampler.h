/* tiershade math: c_ref/math/ts_sampler.c on TSV_W lanes: RGBA32F 2D LINEAR (REPEAT / CLAMP_TO_EDGE, POT / NPOT)
 * and cube maps (CLAMP_TO_EDGE, seamless off), same addressing and lerps, bit for bit.
 * Addressing and filtering are vector code; the texel reads are one RGBA load per lane and
 * corner, transposed to SoA (ts_simd.h gather4). NEAREST filtering, which no frame of ours uses, calls the scalar sampler per lane.
 * Included after c_ref/math/ts_simd.h, once per instruction set (no include guard). */

/* lp_build_sample_wrap_linear (ts_sampler.c wrap_linear), then fetch_safe's clamp; pot: REPEAT
 * addressed as a power of two (llvmpipe decides it from level 0, see wrap_linear_v). */
TSV_INL void VFN(wrap_linear_p)(VF u, int len, int wrap, int pot, VI *i0, VI *i1, VF *w) {
  const float lf = (float)len;
  VI a, b;
  if (wrap != TS_WRAP_CLAMP) {
    if (!pot) u = u - VFN(floor)(u);
    const VF c = u * lf - 0.5f;
    const VF fl = VFN(floor)(c);
    *w = c - fl;
    a = VFN(itrunc)(fl);
    b = (VI)((VU)a + 1u);
    if (pot) {
      a &= len - 1;
      b &= len - 1;
    } else {
      a = VFN(seli)(a < 0, VFN(spliti)(len - 1), a);
      b = VFN(seli)(b == len, VFN(spliti)(0), b);
    }
  } else {
    VF c = VFN(lp_min)(u * lf, VFN(splat)(lf));
    c = c - 0.5f;
    c = VFN(lp_max)(c, VFN(splat)(0.0f));
    const VF fl = VFN(floor)(c);
    *w = c - fl;
    a = VFN(itrunc)(fl);
    b = (VI)((VU)a + 1u);
    b = VFN(seli)(b < len - 1, b, VFN(spliti)(len - 1));
  }
  /* fetch_safe: indices clamped into the image (only NaN/inf coordinates need it) */
  a = VFN(seli)(a < 0, VFN(spliti)(0), a);
  a = VFN(seli)(a > len - 1, VFN(spliti)(len - 1), a);
  b = VFN(seli)(b < 0, VFN(spliti)(0), b);
  b = VFN(seli)(b > len - 1, VFN(spliti)(len - 1), b);
  *i0 = a;
  *i1 = b;
}
TSV_INL int VFN(is_pot)(int wrap, int len) { return wrap == TS_WRAP_REPEAT && len > 0 && (len & (len - 1)) == 0; }
TSV_INL void VFN(wrap_linear)(VF u, int len, int wrap, VI *i0, VI *i1, VF *w) {
  VFN(wrap_linear_p)(u, len, wrap, VFN(is_pot)(wrap, len), i0, i1, w);
}

TSV_INL V4v VFN(lerp4)(VF w, V4v a, V4v b) {
  V4v r;
  r.x = VFN(mad)(w, b.x - a.x, a.x);
  r.y = VFN(mad)(w, b.y - a.y, a.y);
  r.z = VFN(mad)(w, b.z - a.z, a.z);
  r.w = VFN(mad)(w, b.w - a.w, a.w);
  return r;
}

TSV_INL V4v VFN(load4)(const float t[4][TSV_W]) {
  V4v r;
  __builtin_memcpy(&r.x, t[0], sizeof(VF));
  __builtin_memcpy(&r.y, t[1], sizeof(VF));
  __builtin_memcpy(&r.z, t[2], sizeof(VF));
  __builtin_memcpy(&r.w, t[3], sizeof(VF));
  return r;
}

/* A bilinear footprint: the texel indices (y * row width + x, within the lane's image) of the
 * corners (x0,y0) (x1,y0) (x0,y1) (x1,y1) and the weights (ts_sampler.c bilinear). Indices fit
 * 32 bits: an image has at most 32768 x 32768 texels (TS_MAX_MIP_LEVELS). */
typedef struct {
  VU i00, i10, i01, i11;
  VF wx, wy;
} VFN(bl_at);

TSV_INL VFN(bl_at) VFN(bl_addr)(VI x0, VI x1, VI y0, VI y1, VI w, VF wx, VF wy) {
  VFN(bl_at) a;
  const VU r0 = (VU)y0 * (VU)w, r1 = (VU)y1 * (VU)w;
  a.i00 = r0 + (VU)x0;
  a.i10 = r0 + (VU)x1;
  a.i01 = r1 + (VU)x0;
  a.i11 = r1 + (VU)x1;
  a.wx = wx;
  a.wy = wy;
  return a;
}

/* The lerp chain of ts_sampler.c bilinear on a footprint: lane j reads the image tx[j]. */
TSV_INL V4v VFN(bl_fetch)(const float *const tx[TSV_W], const VFN(bl_at) *a) {
  const float *p00[TSV_W], *p10[TSV_W], *p01[TSV_W], *p11[TSV_W];
  for (int j = 0; j < TSV_W; ++j) {
    p00[j] = tx[j] + (size_t)a->i00[j] * 4u;
    p10[j] = tx[j] + (size_t)a->i10[j] * 4u;
    p01[j] = tx[j] + (size_t)a->i01[j] * 4u;
    p11[j] = tx[j] + (size_t)a->i11[j] * 4u;
  }
  return VFN(lerp4)(a->wy, VFN(lerp4)(a->wx, VFN(gather4)(p00), VFN(gather4)(p10)),
                    VFN(lerp4)(a->wx, VFN(gather4)(p01), VFN(gather4)(p11)));
}
/* The same with one image for every lane. */
TSV_INL V4v VFN(bl_fetch1)(const float *tx, const VFN(bl_at) *a) {
  const float *p00[TSV_W], *p10[TSV_W], *p01[TSV_W], *p11[TSV_W];
  for (int j = 0; j < TSV_W; ++j) {
    p00[j] = tx + (size_t)a->i00[j] * 4u;
    p10[j] = tx + (size_t)a->i10[j] * 4u;
    p01[j] = tx + (size_t)a->i01[j] * 4u;
    p11[j] = tx + (size_t)a->i11[j] * 4u;
  }
  return VFN(lerp4)(a->wy, VFN(lerp4)(a->wx, VFN(gather4)(p00), VFN(gather4)(p10)),
                    VFN(lerp4)(a->wx, VFN(gather4)(p01), VFN(gather4)(p11)));
}

/* The footprint of a single-level w x h image. */
TSV_INL VFN(bl_at) VFN(bl_single)(int w, int h, int wrap_s, int wrap_t, VF u, VF v) {
  VI x0, x1, y0, y1;
  VF wx, wy;
  VFN(wrap_linear)(u, w, wrap_s, &x0, &x1, &wx);
  VFN(wrap_linear)(v, h, wrap_t, &y0, &y1, &wy);
  return VFN(bl_addr)(x0, x1, y0, y1, VFN(spliti)(w), wx, wy);
}

/* Bilinear sample; lane j reads the image tx[j] (one image for 2D, the face for cubes). */
static V4v VFN(bilinear)(const float *const tx[TSV_W], int w, int h, int wrap_s, int wrap_t, VF u, VF v) {
  const VFN(bl_at) a = VFN(bl_single)(w, h, wrap_s, wrap_t, u, v);
  return VFN(bl_fetch)(tx, &a);
}

static V4v VFN(texture2D)(const ts_tex2d *t, VF u, VF v) {
  if (t->filter != TS_FILTER_LINEAR) {
    float r[4][TSV_W];
    for (int j = 0; j < TSV_W; ++j) {
      const ts_vec4f s = ts_texture2Df(t, ts_v2f(u[j], v[j]));
      r[0][j] = s.x;
      r[1][j] = s.y;
      r[2][j] = s.z;
      r[3][j] = s.w;
    }
    return VFN(load4)(r);
  }
  const VFN(bl_at) a = VFN(bl_single)(t->w, t->h, t->wrap_s, t->wrap_t, u, v);
  return VFN(bl_fetch1)(t->texels, &a);
}

/* n <= 3 LINEAR samples of one single-level texture at (u[k], v[k]) (the RNM lightmaps: one uv,
 * offsets k * (ox, oy)), each its own texture2D and lerp chain as in the shader. The t
 * addressing is a function of v's bits alone, so when every lane's v[k] has the bits of v[0]
 * it is computed once (the offsets are along s: oy = 0). */
static void VFN(texture2D_n)(const ts_tex2d *t, int n, const VF *u, const VF *v, V4v *out) {
  VI y0[3], y1[3];
  VF wy[3];
  VFN(wrap_linear)(v[0], t->h, t->wrap_t, &y0[0], &y1[0], &wy[0]);
  for (int k = 1; k < n; ++k) {
    const VI same = (VI)(VFN(asu)(v[k]) == VFN(asu)(v[0]));
    int all = 1;
    for (int j = 0; j < TSV_W; ++j) all &= same[j] != 0;
    if (all) {
      y0[k] = y0[0], y1[k] = y1[0], wy[k] = wy[0];
    } else {
      VFN(wrap_linear)(v[k], t->h, t->wrap_t, &y0[k], &y1[k], &wy[k]);
    }
  }
  const VI w = VFN(spliti)(t->w);
  for (int k = 0; k < n; ++k) {
    VI x0, x1;
    VF wx;
    VFN(wrap_linear)(u[k], t->w, t->wrap_s, &x0, &x1, &wx);
    const VFN(bl_at) a = VFN(bl_addr)(x0, x1, y0[k], y1[k], w, wx, wy[k]);
    out[k] = VFN(bl_fetch1)(t->texels, &a);
  }
}

/* wrap_linear with a size per lane (the lanes' mip levels): the same operations, len and
 * (float)len as vectors; pot: REPEAT on a texture whose level 0 is a power of two (then every
 * level is; llvmpipe addresses all levels by level 0's pot_width). */
TSV_INL void VFN(wrap_linear_v)(VF u, VI len, int wrap, int pot, VI *i0, VI *i1, VF *w) {
  const VF lf = VFN(tof)(len);
  const VI top = len - 1;
  VI a, b;
  if (wrap != TS_WRAP_CLAMP) {
    if (!pot) u = u - VFN(floor)(u);
    const VF c = u * lf - 0.5f;
    const VF fl = VFN(floor)(c);
    *w = c - fl;
    a = VFN(itrunc)(fl);
    b = (VI)((VU)a + 1u);
    if (pot) {
      a &= top;
      b &= top;
    } else {
      a = VFN(seli)(a < 0, top, a);
      b = VFN(seli)(b == len, VFN(spliti)(0), b);
    }
  } else {
    VF c = VFN(lp_min)(u * lf, lf);
    c = c - 0.5f;
    c = VFN(lp_max)(c, VFN(splat)(0.0f));
    const VF fl = VFN(floor)(c);
    *w = c - fl;
    a = VFN(itrunc)(fl);
    b = (VI)((VU)a + 1u);
    b = VFN(seli)(b < top, b, top);
  }
  a = VFN(seli)(a < 0, VFN(spliti)(0), a);
  a = VFN(seli)(a > top, top, a);
  b = VFN(seli)(b < 0, VFN(spliti)(0), b);
  b = VFN(seli)(b > top, top, b);
  *i0 = a;
  *i1 = b;
}

/* The footprint of level lv[j] of t in lane j. *uni: the level when every lane has the same
 * one (the common case inside a quad run), else -1; then the sizes are scalars (wrap_linear_p
 * is wrap_linear_v's arithmetic on one size). */
TSV_INL VFN(bl_at) VFN(levels_addr)(const ts_tex2d *t, VI lv, VF u, VF v, int *uni) {
  const int pot_s = VFN(is_pot)(t->wrap_s, t->w), pot_t = VFN(is_pot)(t->wrap_t, t->h);
  VI x0, x1, y0, y1;
  VF wx, wy;
  const int l0 = lv[0];
  int same = 1;
  for (int j = 1; j < TSV_W; ++j) same &= lv[j] == l0;
  if (same) {
    const int w = l0 > 0 ? t->mip_w[l0] : t->w, h = l0 > 0 ? t->mip_h[l0] : t->h;
    *uni = l0;
    VFN(wrap_linear_p)(u, w, t->wrap_s, pot_s, &x0, &x1, &wx);
    VFN(wrap_linear_p)(v, h, t->wrap_t, pot_t, &y0, &y1, &wy);
    return VFN(bl_addr)(x0, x1, y0, y1, VFN(spliti)(w), wx, wy);
  }
  VI w, h;
  for (int j = 0; j < TSV_W; ++j) {
    const int l = lv[j];
    w[j] = l > 0 ? t->mip_w[l] : t->w;
    h[j] = l > 0 ? t->mip_h[l] : t->h;
  }
  *uni = -1;
  VFN(wrap_linear_v)(u, w, t->wrap_s, pot_s, &x0, &x1, &wx);
  VFN(wrap_linear_v)(v, h, t->wrap_t, pot_t, &y0, &y1, &wy);
  return VFN(bl_addr)(x0, x1, y0, y1, w, wx, wy);
}

/* The texels of a levels_addr footprint in t (or in a texture of the same sizes). */
TSV_INL V4v VFN(levels_fetch)(const ts_tex2d *t, VI lv, int uni, const VFN(bl_at) *a) {
  if (uni >= 0) return VFN(bl_fetch1)(uni > 0 ? t->mip_texels[uni] : t->texels, a);
  const float *tx[TSV_W];
  for (int j = 0; j < TSV_W; ++j) tx[j] = lv[j] > 0 ? t->mip_texels[lv[j]] : t->texels;
  return VFN(bl_fetch)(tx, a);
}

/* LINEAR filtering of level lv[j] of t in lane j. */
static V4v VFN(bilinear_levels)(const ts_tex2d *t, VI lv, VF u, VF v) {
  int uni;
  const VFN(bl_at) a = VFN(levels_addr)(t, lv, u, v, &uni);
  return VFN(levels_fetch)(t, lv, uni, &a);
}

/* ts_mip_select on TSV_W lanes (g[j]: lane j's quad derivatives ds/dx, ds/dy, dt/dx, dt/dy):
 * rho^2, fast_log2 from the bits, floor and fraction, the clamps (lp_bld_sample.c lp_build_rho,
 * lp_build_lod_selector, lp_build_linear_mip_levels); NEAREST mips: (exponent - 126) >> 1
 * (lp_build_nearest_mip_level), in *i0 with *f = 0. Returns whether a lane blends two levels
 * (*lerp: those lanes, f > 0). */
TSV_INL int VFN(mip_lanes)(const ts_tex2d *t, const ts_vec4f *g[TSV_W], VI *i0, VI *i1, VF *f, VI *lerp) {
  const float *gp[TSV_W];
  for (int j = 0; j < TSV_W; ++j) gp[j] = &g[j]->x;
  const V4v gv = VFN(gather4)(gp);
  const float fw = (float)t->w, fh = (float)t->h;
  VF a = gv.x * fw, b = gv.y * fw, c = gv.z * fh, d = gv.w * fh;
  a = a * a;
  b = b * b;
  c = c * c;
  d = d * d;
  const VF rho2 = VFN(lp_max)(a + c, b + d);
  const VU bits = VFN(asu)(rho2);
  const VI last = VFN(spliti)(t->mip_levels - 1), zero = VFN(spliti)(0);
  if (t->mip_filter == TS_MIP_NEAREST) {
    VI ip = ((VI)((bits & 0x7f800000u) >> 23) - 126) >> 1;
    ip = VFN(seli)(ip < 0, zero, ip);
    *i0 = *i1 = VFN(seli)(ip > last, last, ip);
    *f = VFN(splat)(0.0f);
    *lerp = zero;
    return 0;
  }
  const VF ipart = VFN(tof)((VI)((bits & 0x7f800000u) >> 23) - 128);
  const VF fpart = VFN(asf)((bits & 0x007fffffu) | 0x3f800000u);
  const VF l = (ipart + fpart) * 0.5f;
  const VF fl = VFN(floor)(l);
  VF fr = l - fl;
  VI a0 = VFN(itrunc)(fl), a1 = (VI)((VU)a0 + 1u);
  const VI below = a0 < 0;
  a0 = VFN(seli)(below, zero, a0);
  a1 = VFN(seli)(below, zero, a1);
  fr = VFN(sel)(below, VFN(splat)(0.0f), fr);
  const VI above = a0 >= last;
  *i0 = VFN(seli)(above, last, a0);
  *i1 = VFN(seli)(above, last, a1);
  *f = fr = VFN(sel)(above, VFN(splat)(0.0f), fr);
  *lerp = fr > 0.0f;
  int any = 0;
  for (int j = 0; j < TSV_W; ++j) any |= (*lerp)[j] != 0;
  return any;
}

/* lerp(f, c0, c1) in the lanes of mask m, c0 in the others. */
TSV_INL V4v VFN(mip_blend)(VI m, VF f, V4v c0, V4v c1) { return VFN(sel4)(m, VFN(lerp4)(f, c0, c1), c0); }

/* Whether two textures have the same sizes, wraps and filters at every level: then one level
 * selection and one footprint serve both (the same uv and derivatives give the same bits). */
TSV_INL int VFN(same_chain)(const ts_tex2d *a, const ts_tex2d *b) {
  if (a->w != b->w || a->h != b->h || a->wrap_s != b->wrap_s || a->wrap_t != b->wrap_t || a->filter != b->filter ||
      a->mip_levels != b->mip_levels || a->mip_filter != b->mip_filter)
    return 0;
  for (int l = 1; l < a->mip_levels; ++l)
    if (a->mip_w[l] != b->mip_w[l] || a->mip_h[l] != b->mip_h[l]) return 0;
  return 1;
}

/* ts_texture2D_gradf on TSV_W lanes: mip_lanes, each lane's two levels filtered with
 * bilinear_levels, lerp(weight, c0, c1) where the weight is > 0. A NEAREST image filter: per lane. */
static V4v VFN(texture2D_grad)(const ts_tex2d *t, VF u, VF v, const ts_vec4f *g[TSV_W]) {
  if (!g[0] || t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return VFN(texture2D)(t, u, v);
  if (t->filter != TS_FILTER_LINEAR) {
    float r[4][TSV_W];
    for (int j = 0; j < TSV_W; ++j) {
      const ts_vec4f s = ts_texture2D_gradf(t, ts_v2f(u[j], v[j]), g[j]);
      r[0][j] = s.x;
      r[1][j] = s.y;
      r[2][j] = s.z;
      r[3][j] = s.w;
    }
    return VFN(load4)(r);
  }
  VI i0, i1, lerp;
  VF f;
  const int any = VFN(mip_lanes)(t, g, &i0, &i1, &f, &lerp);
  const V4v c0 = VFN(bilinear_levels)(t, i0, u, v);
  if (!any) return c0;
  return VFN(mip_blend)(lerp, f, c0, VFN(bilinear_levels)(t, i1, u, v));
}

/* texture2D_grad of two textures with the same chain (same_chain, LINEAR, mipmapped) at one uv:
 * the level selection and the footprints once, the texels and lerp chains per texture. */
static void VFN(texture2D_grad2)(const ts_tex2d *t, const ts_tex2d *t2, VF u, VF v, const ts_vec4f *g[TSV_W],
                                 V4v *r, V4v *r2) {
  VI i0, i1, lerp;
  VF f;
  const int any = VFN(mip_lanes)(t, g, &i0, &i1, &f, &lerp);
  int uni;
  const VFN(bl_at) a0 = VFN(levels_addr)(t, i0, u, v, &uni);
  const V4v c0 = VFN(levels_fetch)(t, i0, uni, &a0), d0 = VFN(levels_fetch)(t2, i0, uni, &a0);
  if (!any) {
    *r = c0;
    *r2 = d0;
    return;
  }
  const VFN(bl_at) a1 = VFN(levels_addr)(t, i1, u, v, &uni);
  *r = VFN(mip_blend)(lerp, f, c0, VFN(levels_fetch)(t, i1, uni, &a1));
  *r2 = VFN(mip_blend)(lerp, f, d0, VFN(levels_fetch)(t2, i1, uni, &a1));
}

/* ts_textureCubef: face and coordinates by selects on sign bits (see ts_sampler.c). */
static V4v VFN(textureCube)(const ts_texcube *c, V3v d) {
  if (c->filter != TS_FILTER_LINEAR) {
    float r[4][TSV_W];
    for (int j = 0; j < TSV_W; ++j) {
      const ts_vec4f s = ts_textureCubef(c, ts_v3f(d.x[j], d.y[j], d.z[j]));
      r[0][j] = s.x;
      r[1][j] = s.y;
      r[2][j] = s.z;
      r[3][j] = s.w;
    }
    return VFN(load4)(r);
  }
  const unsigned S = 0x80000000u;
  const VU bx = VFN(asu)(d.x), by = VFN(asu)(d.y), bz = VFN(asu)(d.z);
  const VF ax = VFN(asf)(bx & ~S), ay = VFN(asf)(by & ~S), az = VFN(asf)(bz & ~S);
  const VF mx = VFN(lp_max)(ax, ay);
  const VI sel_x = ~(ax <= ay); /* |x| UGT |y| */
  const VI sel_z = ~(az < mx); /* |z| UGE mx  */
  const VF ma = VFN(sel)(sel_z, d.z, VFN(sel)(sel_x, d.x, d.y));
  const VU sg = VFN(asu)(ma) & S;
  const VU sc = (VU)VFN(seli)(sel_z, (VI)(bx ^ sg), VFN(seli)(sel_x, (VI)(bz ^ S ^ sg), (VI)bx));
  const VU tc = (VU)VFN(seli)(sel_z | sel_x, (VI)(by ^ S), (VI)(bz ^ sg));
  VI face = VFN(seli)(sel_z, VFN(spliti)(4), VFN(seli)(sel_x, VFN(spliti)(0), VFN(spliti)(2)));
  face += (VI)(sg >> 31);
  const VF ama = VFN(asf)(VFN(asu)(ma) & ~S);
  const VF ima = VFN(sel)(~(ama <= 0.0f), 0.5f / ama, VFN(splat)(0.0f));
  const VF s = VFN(asf)(sc) * ima + 0.5f, t = VFN(asf)(tc) * ima + 0.5f;
  const float *tx[TSV_W];
  for (int j = 0; j < TSV_W; ++j) tx[j] = c->faces[face[j]];
  return VFN(bilinear)(tx, c->size, c->size, TS_WRAP_CLAMP, TS_WRAP_CLAMP, s, t);
}

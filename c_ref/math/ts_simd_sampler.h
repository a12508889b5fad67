/* tiershade math: c_ref/math/ts_sampler.c on TSV_W lanes: RGBA32F 2D LINEAR (REPEAT / CLAMP_TO_EDGE, POT / NPOT)
 * and cube maps (CLAMP_TO_EDGE, seamless off), same addressing and lerps, bit for bit.
 * Addressing and filtering are vector code; the texel reads are one RGBA load per lane and
 * corner, transposed to SoA (ts_simd.h gather4). NEAREST filtering, which no frame of ours uses, calls the scalar sampler per lane.
 * Included after c_ref/math/ts_simd.h, once per instruction set (no include guard). */

/* lp_build_sample_wrap_linear (ts_sampler.c wrap_linear), then fetch_safe's clamp. */
TSV_INL void VFN(wrap_linear)(VF u, int len, int wrap, VI *i0, VI *i1, VF *w) {
  const float lf = (float)len;
  VI a, b;
  if (wrap != TS_WRAP_CLAMP) {
    const int pot = wrap == TS_WRAP_REPEAT && len > 0 && (len & (len - 1)) == 0;
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

/* Bilinear sample; lane j reads the image tx[j] (one image for 2D, the face for cubes). */
static V4v VFN(bilinear)(const float *const tx[TSV_W], int w, int h, int wrap_s, int wrap_t, VF u, VF v) {
  VI x0, x1, y0, y1;
  VF wx, wy;
  const float *p00[TSV_W], *p10[TSV_W], *p01[TSV_W], *p11[TSV_W];
  VFN(wrap_linear)(u, w, wrap_s, &x0, &x1, &wx);
  VFN(wrap_linear)(v, h, wrap_t, &y0, &y1, &wy);
  for (int j = 0; j < TSV_W; ++j) {
    const float *r0 = tx[j] + (size_t)y0[j] * (size_t)w * 4u, *r1 = tx[j] + (size_t)y1[j] * (size_t)w * 4u;
    p00[j] = r0 + (size_t)x0[j] * 4u;
    p10[j] = r0 + (size_t)x1[j] * 4u;
    p01[j] = r1 + (size_t)x0[j] * 4u;
    p11[j] = r1 + (size_t)x1[j] * 4u;
  }
  return VFN(lerp4)(wy, VFN(lerp4)(wx, VFN(gather4)(p00), VFN(gather4)(p10)),
                    VFN(lerp4)(wx, VFN(gather4)(p01), VFN(gather4)(p11)));
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
  const float *tx[TSV_W];
  for (int j = 0; j < TSV_W; ++j) tx[j] = t->texels;
  return VFN(bilinear)(tx, t->w, t->h, t->wrap_s, t->wrap_t, u, v);
}

/* ts_texture2D_gradf on TSV_W lanes (g: the lanes' quad derivatives ds/dx, ds/dy, dt/dx, dt/dy):
 * the levels chosen per lane by ts_mip_select; lanes that share their two levels (the usual
 * case: the level of detail varies slowly over a run of pixels) filter with the vector path,
 * lerp(weight, c0, c1) where the weight is > 0; a block whose lanes differ, per lane. */
static V4v VFN(texture2D_grad)(const ts_tex2d *t, VF u, VF v, const ts_vec4f *g[TSV_W]) {
  if (!g[0] || t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return VFN(texture2D)(t, u, v);
  int l0[TSV_W], l1[TSV_W];
  float wt[TSV_W], lod;
  int same = 1, any = 0;
  for (int j = 0; j < TSV_W; ++j) {
    ts_mip_select(t, *g[j], &l0[j], &l1[j], &wt[j], &lod);
    same = same && l0[j] == l0[0] && l1[j] == l1[0];
    any = any || wt[j] > 0.0f;
  }
  if (!same || t->filter != TS_FILTER_LINEAR) {
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
  const ts_tex2d a = ts_mip_level(t, l0[0]);
  const float *tx[TSV_W];
  for (int j = 0; j < TSV_W; ++j) tx[j] = a.texels;
  const V4v c0 = VFN(bilinear)(tx, a.w, a.h, a.wrap_s, a.wrap_t, u, v);
  if (!any) return c0;
  const ts_tex2d b = ts_mip_level(t, l1[0]);
  for (int j = 0; j < TSV_W; ++j) tx[j] = b.texels;
  const V4v c1 = VFN(bilinear)(tx, b.w, b.h, b.wrap_s, b.wrap_t, u, v);
  VF w;
  __builtin_memcpy(&w, wt, sizeof w);
  const VI lerp = w > 0.0f;
  const V4v m = VFN(lerp4)(w, c0, c1);
  V4v r;
  r.x = VFN(sel)(lerp, m.x, c0.x);
  r.y = VFN(sel)(lerp, m.y, c0.y);
  r.z = VFN(sel)(lerp, m.z, c0.z);
  r.w = VFN(sel)(lerp, m.w, c0.w);
  return r;
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

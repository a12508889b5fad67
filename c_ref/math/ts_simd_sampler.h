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

/* LINEAR filtering of level lv[j] of t in lane j. */
static V4v VFN(bilinear_levels)(const ts_tex2d *t, VI lv, VF u, VF v) {
  VI w, h;
  const float *tx[TSV_W];
  for (int j = 0; j < TSV_W; ++j) {
    const int l = lv[j];
    w[j] = l > 0 ? t->mip_w[l] : t->w;
    h[j] = l > 0 ? t->mip_h[l] : t->h;
    tx[j] = l > 0 ? t->mip_texels[l] : t->texels;
  }
  const int pot_s = t->wrap_s == TS_WRAP_REPEAT && t->w > 0 && (t->w & (t->w - 1)) == 0;
  const int pot_t = t->wrap_t == TS_WRAP_REPEAT && t->h > 0 && (t->h & (t->h - 1)) == 0;
  VI x0, x1, y0, y1;
  VF wx, wy;
  VFN(wrap_linear_v)(u, w, t->wrap_s, pot_s, &x0, &x1, &wx);
  VFN(wrap_linear_v)(v, h, t->wrap_t, pot_t, &y0, &y1, &wy);
  const float *p00[TSV_W], *p10[TSV_W], *p01[TSV_W], *p11[TSV_W];
  for (int j = 0; j < TSV_W; ++j) {
    const size_t W = (size_t)w[j];
    const float *r0 = tx[j] + (size_t)y0[j] * W * 4u, *r1 = tx[j] + (size_t)y1[j] * W * 4u;
    p00[j] = r0 + (size_t)x0[j] * 4u;
    p10[j] = r0 + (size_t)x1[j] * 4u;
    p01[j] = r1 + (size_t)x0[j] * 4u;
    p11[j] = r1 + (size_t)x1[j] * 4u;
  }
  return VFN(lerp4)(wy, VFN(lerp4)(wx, VFN(gather4)(p00), VFN(gather4)(p10)),
                    VFN(lerp4)(wx, VFN(gather4)(p01), VFN(gather4)(p11)));
}

/* ts_texture2D_gradf on TSV_W lanes (g[j]: lane j's quad derivatives ds/dx, ds/dy, dt/dx, dt/dy):
 * ts_mip_select's arithmetic as vector code (rho^2, fast_log2 from the bits, floor and fraction,
 * the clamps; NEAREST mips: (exponent - 126) >> 1), each lane's two levels filtered with
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
  VF gx, gy, gz, gw;
  for (int j = 0; j < TSV_W; ++j) gx[j] = g[j]->x, gy[j] = g[j]->y, gz[j] = g[j]->z, gw[j] = g[j]->w;
  const float fw = (float)t->w, fh = (float)t->h;
  VF a = gx * fw, b = gy * fw, c = gz * fh, d = gw * fh;
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
    ip = VFN(seli)(ip > last, last, ip);
    return VFN(bilinear_levels)(t, ip, u, v);
  }
  const VF ipart = VFN(tof)((VI)((bits & 0x7f800000u) >> 23) - 128);
  const VF fpart = VFN(asf)((bits & 0x007fffffu) | 0x3f800000u);
  const VF l = (ipart + fpart) * 0.5f;
  const VF fl = VFN(floor)(l);
  VF f = l - fl;
  VI i0 = VFN(itrunc)(fl), i1 = (VI)((VU)i0 + 1u);
  const VI below = i0 < 0;
  i0 = VFN(seli)(below, zero, i0);
  i1 = VFN(seli)(below, zero, i1);
  f = VFN(sel)(below, VFN(splat)(0.0f), f);
  const VI above = i0 >= last;
  i0 = VFN(seli)(above, last, i0);
  i1 = VFN(seli)(above, last, i1);
  f = VFN(sel)(above, VFN(splat)(0.0f), f);
  const V4v c0 = VFN(bilinear_levels)(t, i0, u, v);
  const VI lerp = f > 0.0f;
  int any = 0;
  for (int j = 0; j < TSV_W; ++j) any |= lerp[j] != 0;
  if (!any) return c0;
  const V4v c1 = VFN(bilinear_levels)(t, i1, u, v);
  const V4v m = VFN(lerp4)(f, c0, c1);
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

/* tiershade math: c_ref/math/ts_sampler.c's 2D NEAREST sampling (wrap_nearest, then fetch_safe) on TSV_W lanes, bit
 * for bit: REPEAT (POT: ifloor(u * len) & (len - 1); NPOT: itrunc(fract_safe(u) * len),
 * clamped) and CLAMP_TO_EDGE (itrunc(u * len), clamped). NaN and out-of-range coordinates take
 * itrunc's INT32_MIN as the scalar layer does, then the clamp. The texel reads are one RGBA load
 * per lane, transposed to SoA (ts_simd.h gather4).
 * VFN(tex2d) picks this or ts_simd_sampler.h's LINEAR path by the texture's filter.
 * Included after c_ref/math/ts_simd.h and c_ref/math/ts_simd_sampler.h, once per instruction set (no
 * include guard). Checked against the scalar sampler by tests/unit/test_fast_path.cpp (the
 * world_lighting twin's NEAREST lightmaps and textures). */

/* lp_build_sample_wrap_nearest (ts_sampler.c wrap_nearest), then fetch_safe's clamp. */
TSV_INL VI VFN(wrap_nearest)(VF u, int len, int wrap) {
  const float lf = (float)len;
  VI i;
  if (wrap != TS_WRAP_CLAMP) {
    if (wrap == TS_WRAP_REPEAT && len > 0 && (len & (len - 1)) == 0) return VFN(itrunc)(VFN(floor)(u * lf)) & (len - 1);
    /* lp_build_fract_safe: min(u - floor(u), 0x1.fffffep-1), a NaN gives the constant */
    const VF top = VFN(splat)(0x1.fffffep-1f);
    VF f = u - VFN(floor)(u);
    f = VFN(sel)(f < top, f, top);
    i = VFN(itrunc)(f * lf);
  } else {
    i = VFN(itrunc)(u * lf);
  }
  i = VFN(seli)(i < 0, VFN(spliti)(0), i);
  return VFN(seli)(i > len - 1, VFN(spliti)(len - 1), i);
}

static V4v VFN(texture2D_nearest)(const ts_tex2d *t, VF u, VF v) {
  const VI x = VFN(wrap_nearest)(u, t->w, t->wrap_s), y = VFN(wrap_nearest)(v, t->h, t->wrap_t);
  const float *p[TSV_W];
  for (int j = 0; j < TSV_W; ++j) p[j] = t->texels + ((size_t)y[j] * (size_t)t->w + (size_t)x[j]) * 4u;
  return VFN(gather4)(p);
}

/* texture2D with the texture's own filter. */
TSV_INL V4v VFN(tex2d)(const ts_tex2d *t, VF u, VF v) {
  return t->filter == TS_FILTER_NEAREST ? VFN(texture2D_nearest)(t, u, v) : VFN(texture2D)(t, u, v);
}

/* texture2D with the lanes' quad derivatives (ts_simd_sampler.h texture2D_grad): lane j's are
 * grad[pix[j] * stride]; no derivatives (grad NULL) or a single level: VFN(tex2d). */
TSV_INL V4v VFN(tex2d_grad)(const ts_tex2d *t, VF u, VF v, const ts_vec4f *grad, int stride, const size_t *pix) {
  if (!grad || t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE) return VFN(tex2d)(t, u, v);
  const ts_vec4f *g[TSV_W];
  for (int j = 0; j < TSV_W; ++j) g[j] = &grad[pix[j] * (size_t)stride];
  return VFN(texture2D_grad)(t, u, v, g);
}

/* tex2d_grad of two textures at one uv (base and bump): when they have the same chain
 * (ts_simd_sampler.h same_chain) and take the mipmapped LINEAR path, texture2D_grad2 (one level
 * selection, one footprint); otherwise two tex2d_grad calls. Both give tex2d_grad's bits. */
TSV_INL void VFN(tex2d_grad2)(const ts_tex2d *t, const ts_tex2d *t2, VF u, VF v, const ts_vec4f *grad, int stride,
                              const size_t *pix, V4v *r, V4v *r2) {
  if (!grad || t->mip_levels <= 1 || t->mip_filter == TS_MIP_NONE || t->filter != TS_FILTER_LINEAR ||
      !VFN(same_chain)(t, t2)) {
    *r = VFN(tex2d_grad)(t, u, v, grad, stride, pix);
    *r2 = VFN(tex2d_grad)(t2, u, v, grad, stride, pix);
    return;
  }
  const ts_vec4f *g[TSV_W];
  for (int j = 0; j < TSV_W; ++j) g[j] = &grad[pix[j] * (size_t)stride];
  VFN(texture2D_grad2)(t, t2, u, v, g, r, r2);
}

/* The n <= 3 samples of one lightmap (single level) at (u[k], v[k]): texture2D_n when LINEAR,
 * else n tex2d calls. */
TSV_INL void VFN(tex2d_n)(const ts_tex2d *t, int n, const VF *u, const VF *v, V4v *out) {
  if (t->filter == TS_FILTER_LINEAR) {
    VFN(texture2D_n)(t, n, u, v, out);
    return;
  }
  for (int k = 0; k < n; ++k) out[k] = VFN(tex2d)(t, u[k], v[k]);
}

/* tiershade math: c_ref/math/ts_sampler3d.c ts_texture3Df on TSV_W lanes: RGBA32F volume, LINEAR (trilinear) with
 * REPEAT / CLAMP_TO_EDGE per axis, bit for bit. The per-axis addressing is the 2D rule
 * (ts_simd_sampler.h wrap_linear, fetch_safe's clamp included), the lerps run x, then y, then z
 * with gallivm's mad(w, b - a, a) (fused in the FMA instance, as ts_madf). The eight corners
 * are one RGBA load per lane each, transposed to SoA (ts_simd.h gather4). NEAREST calls the
 * scalar sampler per lane. Included after ts_simd.h and ts_simd_sampler.h, once per
 * instruction set (no include guard). Checked by tests/unit/test_fast_path_post.cpp. */

static V4v VFN(texture3D)(const ts_tex3d *t, VF u, VF v, VF r) {
  if (t->filter != TS_FILTER_LINEAR) {
    float o[4][TSV_W];
    for (int j = 0; j < TSV_W; ++j) {
      const ts_vec4f s = ts_texture3Df(t, ts_v3f(u[j], v[j], r[j]));
      o[0][j] = s.x;
      o[1][j] = s.y;
      o[2][j] = s.z;
      o[3][j] = s.w;
    }
    return VFN(load4)(o);
  }
  VI x0, x1, y0, y1, z0, z1;
  VF wx, wy, wz;
  VFN(wrap_linear)(u, t->w, t->wrap_s, &x0, &x1, &wx);
  VFN(wrap_linear)(v, t->h, t->wrap_t, &y0, &y1, &wy);
  VFN(wrap_linear)(r, t->d, t->wrap_r, &z0, &z1, &wz);
  const size_t w = (size_t)t->w, h = (size_t)t->h;
  const float *p[8][TSV_W]; /* corner (x, y, z) bits: 1, 2, 4 */
  for (int j = 0; j < TSV_W; ++j) {
    const size_t r00 = ((size_t)z0[j] * h + (size_t)y0[j]) * w, r10 = ((size_t)z0[j] * h + (size_t)y1[j]) * w;
    const size_t r01 = ((size_t)z1[j] * h + (size_t)y0[j]) * w, r11 = ((size_t)z1[j] * h + (size_t)y1[j]) * w;
    const size_t a = (size_t)x0[j], b = (size_t)x1[j];
    p[0][j] = t->texels + (r00 + a) * 4u;
    p[1][j] = t->texels + (r00 + b) * 4u;
    p[2][j] = t->texels + (r10 + a) * 4u;
    p[3][j] = t->texels + (r10 + b) * 4u;
    p[4][j] = t->texels + (r01 + a) * 4u;
    p[5][j] = t->texels + (r01 + b) * 4u;
    p[6][j] = t->texels + (r11 + a) * 4u;
    p[7][j] = t->texels + (r11 + b) * 4u;
  }
  const V4v s0 = VFN(lerp4)(wy, VFN(lerp4)(wx, VFN(gather4)(p[0]), VFN(gather4)(p[1])),
                            VFN(lerp4)(wx, VFN(gather4)(p[2]), VFN(gather4)(p[3])));
  const V4v s1 = VFN(lerp4)(wy, VFN(lerp4)(wx, VFN(gather4)(p[4]), VFN(gather4)(p[5])),
                            VFN(lerp4)(wx, VFN(gather4)(p[6]), VFN(gather4)(p[7])));
  return VFN(lerp4)(wz, s0, s1);
}

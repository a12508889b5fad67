/* tiershade twins: what several *_simd_impl.h share, on TSV_W lanes: common_output.h (linear
 * clamp, gamma 2.2, exact sRGB) and GLSL mix() as the shaders write it out, a + (b - a) * t,
 * unfused. Same operations in the same order as the scalar twins. Included by a *_simd_impl.h
 * once per instance (ts_simd_instances.h); no include guard on purpose. */

/* TS_POW_TINY (shaders/common_math.glsl, c_ref/common/common_math.h): pow's least base */
#ifndef TS_POW_TINY_F
#define TS_POW_TINY_F 0x1p-60f
#endif

/* common_output.h output_linear / output_gamma22 / output_srgb (final_output after its scale) */
TSV_INL V3v VFN(output_linear)(V3v c) {
  const VF z = VFN(splat)(0.0f), top = VFN(splat)(65504.0f);
  return VFN(v3)(VFN(clamp)(c.x, z, top), VFN(clamp)(c.y, z, top), VFN(clamp)(c.z, z, top));
}
TSV_INL VF VFN(srgb_encode)(VF x) {
  const VF hi = 1.055f * VFN(pow)(VFN(max)(x, VFN(splat)(TS_POW_TINY_F)), VFN(splat)(1.0f / 2.4f)) - 0.055f;
  return VFN(sel)(x <= 0.0031308f, 12.92f * x, hi);
}
TSV_INL V3v VFN(output)(V3v c, int mode) {
  if (mode == 1) {
    const VF e = VFN(splat)(1.0f / 2.2f);
    const VF t = VFN(splat)(TS_POW_TINY_F);
    const V3v s = VFN(saturate3)(c);
    return VFN(saturate3)(VFN(v3)(VFN(pow)(VFN(max)(s.x, t), e), VFN(pow)(VFN(max)(s.y, t), e), VFN(pow)(VFN(max)(s.z, t), e)));
  }
  if (mode == 2) {
    const V3v s = VFN(saturate3)(c);
    return VFN(saturate3)(VFN(v3)(VFN(srgb_encode)(s.x), VFN(srgb_encode)(s.y), VFN(srgb_encode)(s.z)));
  }
  return VFN(output_linear)(c);
}

/* mix(a, b, t) written out: a + (b - a) * t per component */
TSV_INL V3v VFN(lerp3)(V3v a, V3v b, VF t) {
  return VFN(v3)(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}

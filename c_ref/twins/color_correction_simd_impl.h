/* tiershade twins: the color_correction twin (color_correction_impl.h and common_color_correction.h, float32)
 * on TSV_W pixels at once, in SoA, statement by statement: every lane gives the scalar twin's
 * bits. The variant switches stay scalar `if`s; every record value (colour, weights, default
 * weight, LUT addressing) is per lane. Each LUT is one texture for all lanes.
 * Included by c_ref/twins/color_correction_batch.c through ts_simd_instances.h. */

#include "twins/simd_common.h"

TSV_INL V3v VFN(cc_t2)(const ts_tex2d *t, VF u, VF v) { return VFN(xyz)(VFN(texture2D)(t, u, v)); }
TSV_INL V3v VFN(cc_t3)(const ts_tex3d *t, VF u, VF v, VF r) { return VFN(xyz)(VFN(texture3D)(t, u, v, r)); }

/* The addressing of a block, computed once for all lookups (color_correction_impl.h). */
typedef struct {
  V3v uvw, c0, c1, f;
  VF u0x, u1x, uy, fz; /* atlas, hardware filtering: uv0 = (u0x, uy), uv1 = (u1x, uy) */
  VF ux, uy2, uz, uw; /* atlas, shader filtering: u */
  VF vx, vy; /* atlas, shader filtering: vv */
} VFN(cc_addr);

static V3v VFN(cc_lookup)(const cc_variant *v, const cc_luts *luts, int i, const VFN(cc_addr) * a) {
  if (v->shader_trilinear) {
    if (v->atlas) {
      const ts_tex2d *t = &luts->atlas[i];
      const V3v t000 = VFN(cc_t2)(t, a->ux, a->vx), t100 = VFN(cc_t2)(t, a->uy2, a->vx);
      const V3v t010 = VFN(cc_t2)(t, a->ux, a->vy), t110 = VFN(cc_t2)(t, a->uy2, a->vy);
      const V3v t001 = VFN(cc_t2)(t, a->uz, a->vx), t101 = VFN(cc_t2)(t, a->uw, a->vx);
      const V3v t011 = VFN(cc_t2)(t, a->uz, a->vy), t111 = VFN(cc_t2)(t, a->uw, a->vy);
      const V3v s0 = VFN(lerp3)(VFN(lerp3)(t000, t100, a->f.x), VFN(lerp3)(t010, t110, a->f.x), a->f.y);
      const V3v s1 = VFN(lerp3)(VFN(lerp3)(t001, t101, a->f.x), VFN(lerp3)(t011, t111, a->f.x), a->f.y);
      return VFN(lerp3)(s0, s1, a->f.z);
    }
    const ts_tex3d *t = &luts->volume[i];
    const V3v c0 = a->c0, c1 = a->c1;
    const V3v t000 = VFN(cc_t3)(t, c0.x, c0.y, c0.z), t100 = VFN(cc_t3)(t, c1.x, c0.y, c0.z);
    const V3v t010 = VFN(cc_t3)(t, c0.x, c1.y, c0.z), t110 = VFN(cc_t3)(t, c1.x, c1.y, c0.z);
    const V3v t001 = VFN(cc_t3)(t, c0.x, c0.y, c1.z), t101 = VFN(cc_t3)(t, c1.x, c0.y, c1.z);
    const V3v t011 = VFN(cc_t3)(t, c0.x, c1.y, c1.z), t111 = VFN(cc_t3)(t, c1.x, c1.y, c1.z);
    const V3v s0 = VFN(lerp3)(VFN(lerp3)(t000, t100, a->f.x), VFN(lerp3)(t010, t110, a->f.x), a->f.y);
    const V3v s1 = VFN(lerp3)(VFN(lerp3)(t001, t101, a->f.x), VFN(lerp3)(t011, t111, a->f.x), a->f.y);
    return VFN(lerp3)(s0, s1, a->f.z);
  }
  if (v->atlas) {
    const ts_tex2d *t = &luts->atlas[i];
    return VFN(lerp3)(VFN(cc_t2)(t, a->u0x, a->uy), VFN(cc_t2)(t, a->u1x, a->uy), a->fz);
  }
  return VFN(cc_t3)(&luts->volume[i], a->uvw.x, a->uvw.y, a->uvw.z);
}

static V4v VFN(cc_block)(const cc_variant *v, const cc_batch_input *in, const cc_luts *luts, const size_t *pix) {
  const V4v color = TSV_REC(in, CC_SLOT_COLOR, pix);
  const V4v weights = TSV_REC(in, CC_SLOT_WEIGHTS, pix);
  const V4v params = TSV_REC(in, CC_SLOT_PARAMS, pix);
  const V4v lut = TSV_REC(in, CC_SLOT_LUT, pix);
  const V3v c = VFN(saturate3)(VFN(xyz)(color));
  V3v result = VFN(scale3)(c, params.x);
  const VF w[CC_MAX_LOOKUPS] = {weights.x, weights.y, weights.z, weights.w};
  VFN(cc_addr) a;
  __builtin_memset(&a, 0, sizeof a);
  if (v->num_lookups > 0) {
    if (v->shader_trilinear) { /* cc_cell, cc_centre */
      const V3v p = VFN(scale3)(c, lut.z);
      const V3v i0 = VFN(v3)(VFN(floor)(p.x), VFN(floor)(p.y), VFN(floor)(p.z));
      a.f = VFN(sub3)(p, i0);
      const V3v i1 = VFN(v3)(VFN(min)(i0.x + 1.0f, lut.z), VFN(min)(i0.y + 1.0f, lut.z), VFN(min)(i0.z + 1.0f, lut.z));
      a.c0 = VFN(v3)((i0.x + 0.5f) * lut.w, (i0.y + 0.5f) * lut.w, (i0.z + 0.5f) * lut.w);
      a.c1 = VFN(v3)((i1.x + 0.5f) * lut.w, (i1.y + 0.5f) * lut.w, (i1.z + 0.5f) * lut.w);
      if (v->atlas) {
        a.ux = (a.c0.x + i0.z) * lut.w;
        a.uy2 = (a.c1.x + i0.z) * lut.w;
        a.uz = (a.c0.x + i1.z) * lut.w;
        a.uw = (a.c1.x + i1.z) * lut.w;
        a.vx = a.c0.y;
        a.vy = a.c1.y;
      }
    } else { /* cc_uvw: mul, then add */
      a.uvw = VFN(v3)(c.x * lut.x + lut.y, c.y * lut.x + lut.y, c.z * lut.x + lut.y);
      if (v->atlas) {
        const VF pz = c.z * lut.z;
        const VF z0 = VFN(floor)(pz);
        a.fz = pz - z0;
        const VF z1 = VFN(min)(z0 + 1.0f, lut.z);
        a.u0x = (a.uvw.x + z0) * lut.w;
        a.u1x = (a.uvw.x + z1) * lut.w;
        a.uy = a.uvw.y;
      }
    }
  }
  for (int i = 0; i < v->num_lookups && i < CC_MAX_LOOKUPS; ++i)
    result = VFN(add3)(result, VFN(scale3)(VFN(cc_lookup)(v, luts, i, &a), w[i]));
  result = VFN(saturate3)(result);
  return VFN(rgba)(result, VFN(saturate)(color.w));
}
TSV_BATCH(cc_batch, cc_block, cc_variant, cc_batch_input, cc_luts)

/* tiershade twins: generic body of the color_correction twin; mirrors
 * shaders/color_correction.fs statement by statement. Instantiated by color_correction.c through twin_instances.h; gives color_correction_f / color_correction_d, and
 * color_correction_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes through
 * ts_generic.h's ADD/MUL/SEL. */

/* The LUT taps common_color_correction.h reads: the rgb of a 2D / 3D texture lookup. */
static V3 FN(cc_tex2d)(const ts_tex2d *t, TS_REAL u, TS_REAL v) {
  V4 s = M(texture2D)(t, M(v2)(u, v));
  return M(v3)(s.x, s.y, s.z);
}
static V3 FN(cc_tex3d)(const ts_tex3d *t, V3 p) {
  V4 s = M(texture3D)(t, p);
  return M(v3)(s.x, s.y, s.z);
}
#include "common/common_color_correction.h"

/* A record slot in the instantiation's precision (float slots, widened for double). */
static V4 FN(cc_in)(ts_vec4f v) { return M(v4)(FROMF(v.x), FROMF(v.y), FROMF(v.z), FROMF(v.w)); }

static V3 FN(cc_lookup)(const cc_variant *v, const cc_luts *luts, int i, V3 uvw, V2 uv0, V2 uv1, TS_REAL fz, V3 c0,
                        V3 c1, V3 f, V4 u, V2 vv) {
  if (v->shader_trilinear) {
    return v->atlas ? FN(cc_atlas_shader)(&luts->atlas[i], u, vv, f)
                    : FN(cc_volume_shader)(&luts->volume[i], c0, c1, f);
  }
  return v->atlas ? FN(cc_atlas_hw)(&luts->atlas[i], uv0, uv1, fz) : FN(cc_volume_hw)(&luts->volume[i], uvw);
}

V4 FN(color_correction)(const cc_variant *v, const ts_vec4f rec[CC_SLOTS], const cc_luts *luts) {
  V4 color = FN(cc_in)(rec[CC_SLOT_COLOR]);
  V4 weights = FN(cc_in)(rec[CC_SLOT_WEIGHTS]);
  V4 params = FN(cc_in)(rec[CC_SLOT_PARAMS]);
  V4 lut = FN(cc_in)(rec[CC_SLOT_LUT]);
  V3 c = M(saturate3)(M(v3)(color.x, color.y, color.z));
  V3 result = M(scale3)(c, params.x);
  const TS_REAL w[CC_MAX_LOOKUPS] = {weights.x, weights.y, weights.z, weights.w};
  V3 uvw = M(v3)(K(0.0), K(0.0), K(0.0)), c0 = uvw, c1 = uvw, f = uvw, i0 = uvw, i1 = uvw;
  V2 uv0 = M(v2)(K(0.0), K(0.0)), uv1 = uv0, vv = uv0;
  V4 u = M(v4)(K(0.0), K(0.0), K(0.0), K(0.0));
  TS_REAL fz = K(0.0);
  if (v->num_lookups > 0) {
    if (v->shader_trilinear) {
      FN(cc_cell)(c, lut, &i0, &i1, &f);
      c0 = FN(cc_centre)(i0, lut);
      c1 = FN(cc_centre)(i1, lut);
      if (v->atlas) {
        u = M(v4)(MUL(ADD(c0.x, i0.z), lut.w), MUL(ADD(c1.x, i0.z), lut.w), MUL(ADD(c0.x, i1.z), lut.w),
                  MUL(ADD(c1.x, i1.z), lut.w));
        vv = M(v2)(c0.y, c1.y);
      }
    } else {
      uvw = FN(cc_uvw)(c, lut);
      if (v->atlas) {
        TS_REAL pz = MUL(c.z, lut.z);
        TS_REAL z0 = M(floor)(pz);
        TS_REAL z1;
        fz = SUB(pz, z0);
        z1 = M(min)(ADD(z0, K(1.0)), lut.z);
        uv0 = M(v2)(MUL(ADD(uvw.x, z0), lut.w), uvw.y);
        uv1 = M(v2)(MUL(ADD(uvw.x, z1), lut.w), uvw.y);
      }
    }
  }
  for (int i = 0; i < v->num_lookups && i < CC_MAX_LOOKUPS; ++i) {
    V3 l = FN(cc_lookup)(v, luts, i, uvw, uv0, uv1, fz, c0, c1, f, u, vv);
    result = M(add3)(result, M(scale3)(l, w[i]));
  }
  result = M(saturate3)(result);
  return M(v4)(result.x, result.y, result.z, M(saturate)(color.w));
}

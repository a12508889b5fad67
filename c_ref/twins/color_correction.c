/* tiershade twins: instantiates the color_correction twin in float32
 * (llvmpipe-exact) and double. See color_correction_impl.h. */
#include "twins/color_correction.h"

#include "math/ts_generic.h"

ts_vec4f cc_lut_params(int n) {
  const float nf = (float)n;
  return ts_v4f((nf - 1.0f) / nf, 0.5f / nf, nf - 1.0f, 1.0f / nf);
}

/* ---- float32 ---- */
#include "math/ts_generic_float.h"
static ts_vec3f cc_tex2d_f(const ts_tex2d *t, float u, float v) {
  ts_vec4f s = ts_texture2Df(t, ts_v2f(u, v));
  return ts_v3f(s.x, s.y, s.z);
}
static ts_vec3f cc_tex3d_f(const ts_tex3d *t, ts_vec3f p) {
  ts_vec4f s = ts_texture3Df(t, p);
  return ts_v3f(s.x, s.y, s.z);
}
#include "common/common_color_correction.h"
#include "twins/color_correction_impl.h"

/* ---- double ---- */
#include "math/ts_generic_double.h"
static ts_vec3d cc_tex2d_d(const ts_tex2d *t, double u, double v) {
  ts_vec4d s = ts_texture2Dd(t, ts_v2d(u, v));
  return ts_v3d(s.x, s.y, s.z);
}
static ts_vec3d cc_tex3d_d(const ts_tex3d *t, ts_vec3d p) {
  ts_vec4d s = ts_texture3Dd(t, p);
  return ts_v3d(s.x, s.y, s.z);
}
#include "common/common_color_correction.h"
#include "twins/color_correction_impl.h"

ts_vec4f color_correction_f(const cc_variant *v, const ts_vec4f rec[CC_SLOTS], const cc_luts *luts) {
  return color_correction_impl_f(v, rec, luts);
}
ts_vec4d color_correction_d(const cc_variant *v, const ts_vec4f rec[CC_SLOTS], const cc_luts *luts) {
  return color_correction_impl_d(v, rec, luts);
}

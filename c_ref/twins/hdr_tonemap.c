/* tiershade twins: instantiates the hdr_tonemap twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See hdr_tonemap_impl.h. */
#include "twins/hdr_tonemap.h"

#include "math/ts_generic.h"

/* ---- float32 ---- */
#include "math/ts_generic_float.h"
static ts_vec4f sample2d_f(const ts_tex2d *t, float u, float v) { return ts_texture2Df(t, ts_v2f(u, v)); }
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "common/common_output.h"
#include "twins/hdr_tonemap_impl.h"

/* ---- double ---- */
#include "math/ts_generic_double.h"
static ts_vec4d sample2d_d(const ts_tex2d *t, double u, double v) { return ts_texture2Dd(t, ts_v2d(u, v)); }
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "common/common_output.h"
#include "twins/hdr_tonemap_impl.h"

ts_vec4f hdr_tonemap_f(const ht_variant *v, const ts_vec4f rec[HT_SLOTS], const ts_tex2d *bloom) {
  return hdr_tonemap_impl_f(v, rec, bloom);
}
ts_vec4d hdr_tonemap_d(const ht_variant *v, const ts_vec4f rec[HT_SLOTS], const ts_tex2d *bloom) {
  return hdr_tonemap_impl_d(v, rec, bloom);
}

/* tiershade twins: instantiates the bloom_downsample twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See bloom_downsample_impl.h. */
#include "twins/bloom_downsample.h"

#include "math/ts_generic.h"

/* ---- float32 ---- */
#include "math/ts_generic_float.h"
static ts_vec4f sample2d_f(const ts_tex2d *t, float u, float v) { return ts_texture2Df(t, ts_v2f(u, v)); }
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "common/common_output.h"
#include "twins/bloom_downsample_impl.h"

/* ---- double ---- */
#include "math/ts_generic_double.h"
static ts_vec4d sample2d_d(const ts_tex2d *t, double u, double v) { return ts_texture2Dd(t, ts_v2d(u, v)); }
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "common/common_output.h"
#include "twins/bloom_downsample_impl.h"

ts_vec4f bloom_downsample_f(const bd_variant *v, const ts_vec4f rec[BD_SLOTS], const ts_tex2d *source) {
  return bloom_downsample_impl_f(v, rec, source);
}
ts_vec4d bloom_downsample_d(const bd_variant *v, const ts_vec4f rec[BD_SLOTS], const ts_tex2d *source) {
  return bloom_downsample_impl_d(v, rec, source);
}

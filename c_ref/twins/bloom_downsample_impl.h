/* tiershade twins: generic body of the bloom_downsample twin; mirrors
 * shaders/bloom_downsample.fs statement by statement. Instantiated by bloom_downsample.c through twin_instances.h; gives bloom_downsample_f / bloom_downsample_d, and
 * bloom_downsample_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes through
 * ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "common/common_output.h"

static V3 FN(bd_tap)(const bd_variant *v, const ts_tex2d *src, TS_REAL tx, TS_REAL ty, V4 size, V4 shape) {
  V4 s = M(texture2D)(src, M(v2)(MUL(tx, size.z), MUL(ty, size.w)));
  V3 p = M(v3)(s.x, s.y, s.z);
  if (v->shape) p = FN(bloom_shape)(p, shape);
  return p;
}

V4 FN(bloom_downsample)(const bd_variant *v, const ts_vec4f rec[BD_SLOTS], const ts_tex2d *src) {
  V4 pos = FN(vec4_in)(rec[BD_SLOT_POS]);
  V4 size = FN(vec4_in)(rec[BD_SLOT_SIZE]);
  V4 shape = FN(vec4_in)(rec[BD_SLOT_SHAPE]);
  TS_REAL cx = MUL(pos.x, K(4.0)), cy = MUL(pos.y, K(4.0));
  V3 sum = FN(bd_tap)(v, src, SUB(cx, K(1.0)), SUB(cy, K(1.0)), size, shape);
  sum = M(add3)(sum, FN(bd_tap)(v, src, ADD(cx, K(1.0)), SUB(cy, K(1.0)), size, shape));
  sum = M(add3)(sum, FN(bd_tap)(v, src, SUB(cx, K(1.0)), ADD(cy, K(1.0)), size, shape));
  sum = M(add3)(sum, FN(bd_tap)(v, src, ADD(cx, K(1.0)), ADD(cy, K(1.0)), size, shape));
  V3 c = FN(output_linear)(M(scale3)(sum, K(0.25)));
  return M(v4)(c.x, c.y, c.z, K(1.0));
}

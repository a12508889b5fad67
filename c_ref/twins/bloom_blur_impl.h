/* tiershade twins: generic body of the bloom_blur twin; mirrors
 * shaders/bloom_blur.fs statement by statement (weights and offsets: fact sheet
 * section 8, BlurFilter). Instantiated by bloom_blur.c through twin_instances.h; gives bloom_blur_f / bloom_blur_d. */
#include "common/common_math.h"
#include "common/common_output.h"

static V3 FN(bb_fetch)(const ts_tex2d *src, TS_REAL u, TS_REAL v) {
  V4 s = M(texture2D)(src, M(v2)(u, v));
  return M(v3)(s.x, s.y, s.z);
}

static V3 FN(bb_pair)(const bb_variant *v, const ts_tex2d *src, V4 pos, TS_REAL offset, V4 size) {
  if (v->direction == 0) {
    TS_REAL y = pos.y * size.w;
    return M(add3)(FN(bb_fetch)(src, (pos.x + offset) * size.z, y), FN(bb_fetch)(src, (pos.x - offset) * size.z, y));
  }
  TS_REAL x = pos.x * size.z;
  return M(add3)(FN(bb_fetch)(src, x, (pos.y + offset) * size.w), FN(bb_fetch)(src, x, (pos.y - offset) * size.w));
}

V4 FN(bloom_blur)(const bb_variant *v, const ts_vec4f rec[BB_SLOTS], const ts_tex2d *src) {
  static const TS_REAL offsets[6] = {K(1.3366), K(3.4295), K(5.4264), K(7.4359), K(9.4436), K(11.4401)};
  static const TS_REAL weights[6] = {K(0.2185), K(0.0821), K(0.0461), K(0.0262), K(0.0162), K(0.0102)};
  V4 pos = FN(vec4_in)(rec[BB_SLOT_POS]);
  V4 size = FN(vec4_in)(rec[BB_SLOT_SIZE]);
  V4 params = FN(vec4_in)(rec[BB_SLOT_PARAMS]);
  V3 sum = M(scale3)(FN(bb_fetch)(src, pos.x * size.z, pos.y * size.w), K(0.2013));
  for (int i = 0; i < 6; ++i) sum = M(add3)(sum, M(scale3)(FN(bb_pair)(v, src, pos, offsets[i], size), weights[i]));
  V3 c = FN(output_linear)(M(scale3)(sum, params.x));
  return M(v4)(c.x, c.y, c.z, K(1.0));
}

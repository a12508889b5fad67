/* tiershade twins: generic body of the bloom_blur twin; mirrors
 * shaders/bloom_blur.fs statement by statement (weights and offsets: fact sheet
 * section 8, BlurFilter). Instantiated by bloom_blur.c through twin_instances.h; gives bloom_blur_f / bloom_blur_d, and
 * bloom_blur_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes through
 * ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_output.h"

static V3 FN(bb_fetch)(const ts_tex2d *src, TS_REAL u, TS_REAL v) {
  V4 s = M(texture2D)(src, M(v2)(u, v));
  return M(v3)(s.x, s.y, s.z);
}

static V3 FN(bb_pair)(const bb_variant *v, const ts_tex2d *src, V4 pos, TS_REAL offset, V4 size) {
  if (v->direction == 0) {
    TS_REAL y = MUL(pos.y, size.w);
    return M(add3)(FN(bb_fetch)(src, MUL(ADD(pos.x, offset), size.z), y),
                   FN(bb_fetch)(src, MUL(SUB(pos.x, offset), size.z), y));
  }
  TS_REAL x = MUL(pos.x, size.z);
  return M(add3)(FN(bb_fetch)(src, x, MUL(ADD(pos.y, offset), size.w)),
                 FN(bb_fetch)(src, x, MUL(SUB(pos.y, offset), size.w)));
}

V4 FN(bloom_blur)(const bb_variant *v, const ts_vec4f rec[BB_SLOTS], const ts_tex2d *src) {
  static const TS_REAL offsets[6] = {KC(1.3366), KC(3.4295), KC(5.4264), KC(7.4359), KC(9.4436), KC(11.4401)};
  static const TS_REAL weights[6] = {KC(0.2185), KC(0.0821), KC(0.0461), KC(0.0262), KC(0.0162), KC(0.0102)};
  V4 pos = FN(vec4_in)(rec[BB_SLOT_POS]);
  V4 size = FN(vec4_in)(rec[BB_SLOT_SIZE]);
  V4 params = FN(vec4_in)(rec[BB_SLOT_PARAMS]);
  V3 sum = M(scale3)(FN(bb_fetch)(src, MUL(pos.x, size.z), MUL(pos.y, size.w)), K(0.2013));
  for (int i = 0; i < 6; ++i) sum = M(add3)(sum, M(scale3)(FN(bb_pair)(v, src, pos, offsets[i], size), weights[i]));
  V3 c = FN(output_linear)(M(scale3)(sum, params.x));
  return M(v4)(c.x, c.y, c.z, K(1.0));
}

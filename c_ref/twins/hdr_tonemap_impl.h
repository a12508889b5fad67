/* tiershade twins: generic body of the hdr_tonemap twin; mirrors
 * shaders/hdr_tonemap.fs statement by statement. Instantiated by hdr_tonemap.c through twin_instances.h; gives hdr_tonemap_f / hdr_tonemap_d, and
 * hdr_tonemap_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes
 * through ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_hdr.h"
#include "common/common_output.h"

V4 FN(hdr_tonemap)(const ht_variant *v, const ts_vec4f rec[HT_SLOTS], const ts_tex2d *bloom_tex) {
  V4 pos = FN(vec4_in)(rec[HT_SLOT_POS]);
  V4 size = FN(vec4_in)(rec[HT_SLOT_SIZE]);
  V3 fb = FN(xyz)(rec[HT_SLOT_FRAME]);
  V4 params = FN(vec4_in)(rec[HT_SLOT_PARAMS]);
  V4 s = M(texture2D)(bloom_tex, M(v2)(MUL(pos.x, size.z), MUL(pos.y, size.w)));
  V3 bloom = M(scale3)(M(v3)(s.x, s.y, s.z), M(sqrt)(M(max)(params.x, K(0.0))));
  bloom = M(v3)(M(min)(bloom.x, K(1.0)), M(min)(bloom.y, K(1.0)), M(min)(bloom.z, K(1.0)));
  TS_REAL k = MUL(params.y, M(pow)(M(max)(FN(luminance)(bloom), K(TS_POW_TINY_C)), params.z));
  V3 c = M(add3)(M(scale3)(fb, params.x), M(scale3)(bloom, k));
  if (v->output_mode == 1)
    c = FN(output_gamma22)(c);
  else if (v->output_mode == 2)
    c = FN(output_srgb)(c);
  else
    c = FN(output_linear)(c);
  return M(v4)(c.x, c.y, c.z, K(1.0));
}

/* tiershade twins: generic body of the skybox twin; mirrors shaders/skybox.fs statement by
 * statement. Instantiated by skybox.c through twin_instances.h; gives skybox_f / skybox_d, and
 * skybox_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes through
 * ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_output.h"

V4 FN(skybox)(const sb_variant *v, const ts_vec4f rec[SB_SLOTS], const ts_texcube *sky) {
  (void)v;
  V4 pos = FN(vec4_in)(rec[SB_SLOT_POS]);
  V4 size = FN(vec4_in)(rec[SB_SLOT_SIZE]);
  V3 fwd = FN(xyz)(rec[SB_SLOT_FORWARD]);
  V3 right = FN(xyz)(rec[SB_SLOT_RIGHT]);
  V3 up = FN(xyz)(rec[SB_SLOT_UP]);
  V4 color = FN(vec4_in)(rec[SB_SLOT_COLOR]);
  /* ndc = (pos * size.zw) * 2.0 - 1.0 */
  TS_REAL nx = SUB(MUL(MUL(pos.x, size.z), K(2.0)), K(1.0));
  TS_REAL ny = SUB(MUL(MUL(pos.y, size.w), K(2.0)), K(1.0));
  V3 d = M(add3)(M(add3)(fwd, M(scale3)(right, nx)), M(scale3)(up, ny));
  /* dot(d, d) > TS_MIN_LENGTH2 ? clamp(d, -1e30, 1e30) : vec3(0, 1, 0) (NaN: the zenith) */
  d = SEL3(GT(M(dot3)(d, d), K(1.0e-30)),
           M(v3)(M(clamp)(d.x, K(-1.0e30), K(1.0e30)), M(clamp)(d.y, K(-1.0e30), K(1.0e30)),
                 M(clamp)(d.z, K(-1.0e30), K(1.0e30))),
           M(v3)(K(0.0), K(1.0), K(0.0)));
  V4 s = M(textureCube)(sky, d);
  V3 c = M(v3)(M(min)(s.x, K(65504.0)), M(min)(s.y, K(65504.0)), M(min)(s.z, K(65504.0)));
  c = M(scale3)(M(mul3)(c, M(v3)(color.x, color.y, color.z)), color.w);
  c = FN(output_linear)(c);
  return M(v4)(c.x, c.y, c.z, K(1.0));
}

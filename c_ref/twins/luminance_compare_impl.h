/* tiershade twins: generic body of the luminance_compare twin; mirrors
 * shaders/luminance_compare.fs statement by statement. Instantiated by luminance_compare.c through twin_instances.h; gives luminance_compare_f / luminance_compare_d, and
 * luminance_compare_iv (the GLSL ES 3.00 bounds, ts_generic_interval.h): arithmetic on TS_REAL goes through
 * ts_generic.h's ADD/MUL/SEL. */
#include "common/common_math.h"
#include "common/common_hdr.h"

static TS_REAL FN(lc_lum)(const lc_variant *v, V3 c, TS_REAL tscale) {
  if (v->input_encoding == 2) return MUL(c.x, tscale);
  if (v->input_encoding == 1) c = FN(srgb_decode3)(c);
  return MUL(FN(luminance)(c), tscale);
}

V4 FN(luminance_compare)(const lc_variant *v, const ts_vec4f rec[LC_SLOTS]) {
  V3 c = FN(xyz)(rec[LC_SLOT_COLOR]);
  V4 range = FN(vec4_in)(rec[LC_SLOT_RANGE]);
  TS_REAL lum = FN(lc_lum)(v, c, range.z);
  TS_REAL mark = FN(in_bucket)(lum, range.x, range.y);
  /* mark < 0.5: discard, the cleared target (when it may be below, the interval instance joins both) */
  int discard = LT(mark, K(0.5));
  if (discard) return SEL4(discard, M(v4)(K(0.0), K(0.0), K(0.0), K(0.0)), M(v4)(mark, mark, mark, mark));
  return M(v4)(mark, mark, mark, mark);
}

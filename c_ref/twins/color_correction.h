/* tiershade twins: C twin of shaders/color_correction.fs (Source's colour
 * correction: up to four LUTs blended with weights plus the default weight; fact
 * sheet section 9). One call corrects one pixel from its input record (the same
 * slots the shader reads in conformance mode, shaders/color_correction_slots.glsl). */
#ifndef TS_COLOR_CORRECTION_H
#define TS_COLOR_CORRECTION_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"
#include "math/ts_sampler.h"
#include "math/ts_sampler3d.h"

/* The input record's slots (enum cc_slot) and its counts (CC_SLOTS, CC_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/color_correction_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum cc_slot {
#include "../../shaders/color_correction_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int atlas; /* LUT_ATLAS: 1 = 2D atlas, 0 = 3D texture */
  int shader_trilinear; /* SHADER_TRILINEAR: 1 = 8 taps filtered in the shader */
  int num_lookups; /* NUM_LOOKUPS 0..4 */
} cc_variant;

/* The LUTs as the shader sees them: u_lut0..3 (3D) and u_lut_atlas0..3 (2D atlas). */
typedef struct {
  ts_tex3d volume[CC_MAX_LOOKUPS];
  ts_tex2d atlas[CC_MAX_LOOKUPS];
} cc_luts;

/* The addressing slot for LUT edge n, as the shader expects it (CC_SLOT_LUT). */
TS_C_API ts_vec4f cc_lut_params(int n);

/* color_correction_f: float32, bit-exact with llvmpipe; color_correction_d: double, the accuracy reference */
TS_TWIN_DECLARE(color_correction, (const cc_variant *v, const ts_vec4f rec[CC_SLOTS], const cc_luts *luts))
/* color_correction_iv: per channel, the interval of every result GLSL ES 3.00 highp allows (the third
 * instance, ts_generic_interval.h; docs/conformance.md "Error bounds per pixel") */
TS_C_API ts_vec4iv color_correction_iv(const cc_variant *v, const ts_vec4f rec[CC_SLOTS], const cc_luts *luts);

#endif

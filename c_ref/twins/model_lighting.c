/* tiershade twins: instantiates the model_lighting twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See model_lighting_impl.h. */
#include "twins/model_lighting.h"

#include "math/ts_generic.h"

/* ---- float32 ---- */
#include "math/ts_generic_float.h"
static ts_vec4f sample2d_f(const ts_tex2d *t, float u, float v) { return ts_texture2Df(t, ts_v2f(u, v)); }
static ts_vec4f samplecube_f(const ts_texcube *c, ts_vec3f d) { return ts_textureCubef(c, d); }
#include "common/common_math.h"
#include "common/common_ambient_cube.h"
#include "common/common_lights.h"
#include "common/common_phong.h"
#include "common/common_output.h"
#include "twins/model_lighting_impl.h"

/* ---- double ---- */
#include "math/ts_generic_double.h"
static ts_vec4d sample2d_d(const ts_tex2d *t, double u, double v) { return ts_texture2Dd(t, ts_v2d(u, v)); }
static ts_vec4d samplecube_d(const ts_texcube *c, ts_vec3d d) { return ts_textureCubed(c, d); }
#include "common/common_math.h"
#include "common/common_ambient_cube.h"
#include "common/common_lights.h"
#include "common/common_phong.h"
#include "common/common_output.h"
#include "twins/model_lighting_impl.h"

ts_vec4f model_lighting_f(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ml_textures *tex) {
  return model_lighting_impl_f(v, rec, tex);
}
ts_vec4d model_lighting_d(const ml_variant *v, const ts_vec4f rec[ML_SLOTS], const ml_textures *tex) {
  return model_lighting_impl_d(v, rec, tex);
}

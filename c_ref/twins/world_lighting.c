/* tiershade twins: instantiates the world_lighting twin in float32
 * (llvmpipe-exact) and double (accuracy reference). See world_lighting_impl.h. */
#include "twins/world_lighting.h"

#include "math/ts_generic.h"

/* ---- float32 ---- */
#include "math/ts_generic_float.h"
static ts_vec4f sample2d_f(const ts_tex2d *t, ts_vec2f uv) { return ts_texture2Df(t, uv); }
static ts_vec4f samplecube_f(const ts_texcube *c, ts_vec3f d) { return ts_textureCubef(c, d); }
#include "common/common_math.h"
#include "common/common_output.h"
#include "common/common_rnm.h"
#include "common/common_lightmap.h"
#include "common/common_envmap.h"
#include "common/common_fog.h"
#include "twins/world_lighting_impl.h"

/* ---- double ---- */
#include "math/ts_generic_double.h"
static ts_vec4d sample2d_d(const ts_tex2d *t, ts_vec2d uv) { return ts_texture2Dd(t, uv); }
static ts_vec4d samplecube_d(const ts_texcube *c, ts_vec3d d) { return ts_textureCubed(c, d); }
#include "common/common_math.h"
#include "common/common_output.h"
#include "common/common_rnm.h"
#include "common/common_lightmap.h"
#include "common/common_envmap.h"
#include "common/common_fog.h"
#include "twins/world_lighting_impl.h"

ts_vec4f world_lighting_f(const wl_variant *v, const ts_vec4f rec[WL_SLOTS], const wl_textures *t) {
  return world_lighting_impl_f(v, rec, t);
}
ts_vec4d world_lighting_d(const wl_variant *v, const ts_vec4f rec[WL_SLOTS], const wl_textures *t) {
  return world_lighting_impl_d(v, rec, t);
}

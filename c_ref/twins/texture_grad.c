/* tiershade twins: the texture_grad twin (texture_grad.h) in float32 (llvmpipe-exact), double and
 * intervals; the shader is one lookup, so each instance is written out. */
#include "twins/texture_grad.h"

static const ts_tex2d *tg_texture(const tg_variant *v, const tg_textures *t) {
  return v->mip_nearest ? t->mips_nearest : t->mips_linear;
}

ts_vec4f texture_grad_f(const tg_variant *v, const ts_vec4f rec[TG_SLOTS], const tg_textures *t) {
  const ts_vec4f uv = rec[TG_SLOT_UV];
  return ts_texture2DGradf(tg_texture(v, t), ts_v2f(uv.x, uv.y), rec[TG_SLOT_GRAD]);
}

ts_vec4d texture_grad_d(const tg_variant *v, const ts_vec4f rec[TG_SLOTS], const tg_textures *t) {
  const ts_vec4f uv = rec[TG_SLOT_UV];
  return ts_texture2DGradd(tg_texture(v, t), ts_v2d(uv.x, uv.y), rec[TG_SLOT_GRAD]);
}

ts_vec4iv texture_grad_iv(const tg_variant *v, const ts_vec4f rec[TG_SLOTS], const tg_textures *t) {
  const ts_vec4f uv = rec[TG_SLOT_UV];
  return ts_texture2DGradiv(tg_texture(v, t), ts_v2iv(ts_ivpoint(uv.x), ts_ivpoint(uv.y)), rec[TG_SLOT_GRAD]);
}

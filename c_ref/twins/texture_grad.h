/* tiershade twins: C twin of shaders/texture_grad.fs, one lookup of a mip chain with explicit
 * derivatives (textureGrad). One call shades one pixel from its input record
 * (shaders/texture_grad_slots.glsl) and the family's two textures; llvmpipe takes each pixel's
 * level of detail from its own derivatives (c_ref/math/ts_sampler_grad.c). */
#ifndef TS_TEXTURE_GRAD_H
#define TS_TEXTURE_GRAD_H
#include "math/ts_math.h"
#include "twins/twin_api.h"
#include "math/ts_interval.h"
#include "math/ts_sampler.h"

/* The input record's slots (enum tg_slot) and its counts (TG_SLOTS, TG_PIXEL_SLOTS, as #defines)
 * come from the one table shaders/texture_grad_slots.glsl. */
#define TS_SLOT(ID, first, ...) ID = first,
enum tg_slot {
#include "../../shaders/texture_grad_slots.glsl"
};
#undef TS_SLOT

typedef struct {
  int mip_nearest; /* MIP_NEAREST: 0 u_mips_linear, 1 u_mips_nearest */
} tg_variant;

/* The two textures the shader may sample (the variant picks one). */
typedef struct {
  const ts_tex2d *mips_linear, *mips_nearest;
} tg_textures;

/* texture_grad_f: float32, bit-exact with llvmpipe; texture_grad_d: double, the same levels */
TS_TWIN_DECLARE(texture_grad, (const tg_variant *v, const ts_vec4f rec[TG_SLOTS], const tg_textures *t))
/* texture_grad_iv: every result the GLES 3.0 LOD rules and the GLES 3 filtering precision allow
 * (docs/conformance.md "Explicit derivatives") */
TS_C_API ts_vec4iv texture_grad_iv(const tg_variant *v, const ts_vec4f rec[TG_SLOTS], const tg_textures *t);

#endif

/* tiershade twins: the float HDR path's twins on TSV_W pixels at once, in SoA: bloom_downsample_impl.h,
 * bloom_blur_impl.h and hdr_tonemap_impl.h (float32) statement by statement, so every lane
 * gives the scalar twin's bits; plus hdr_formats.c's fp16 and RGBA8 stores on lanes.
 * Variant switches stay scalar `if`s; every record value is per lane.
 * Included by c_ref/twins/hdr_post_batch.c through ts_simd_instances.h (once per instruction set). */

#include "twins/simd_common.h"

TSV_INL V3v VFN(hp_fetch)(const ts_tex2d *t, VF u, VF v) { return VFN(xyz)(VFN(texture2D)(t, u, v)); }

/* ---- bloom_downsample ---- */
TSV_INL V3v VFN(bd_tap)(const bd_variant *v, const ts_tex2d *src, VF tx, VF ty, V4v size, V4v shape) {
  V3v p = VFN(hp_fetch)(src, tx * size.z, ty * size.w);
  if (v->shape) { /* common_hdr.h bloom_shape */
    const VF d = VFN(dot3)(p, VFN(xyz)(shape));
    const VF m = VFN(splat)(TS_POW_TINY_F); /* base >= 2^-60 (shaders/common_math.glsl) */
    p = VFN(scale3)(VFN(v3)(VFN(pow)(VFN(max)(p.x, m), shape.w), VFN(pow)(VFN(max)(p.y, m), shape.w), VFN(pow)(VFN(max)(p.z, m), shape.w)), d);
  }
  return p;
}

static V4v VFN(bd_block)(const bd_variant *v, const bd_batch_input *in, const ts_tex2d *src, const size_t *pix) {
  const V4v pos = TSV_REC(in, BD_SLOT_POS, pix);
  const V4v size = TSV_REC(in, BD_SLOT_SIZE, pix);
  const V4v shape = TSV_REC(in, BD_SLOT_SHAPE, pix);
  const VF cx = pos.x * 4.0f, cy = pos.y * 4.0f;
  V3v sum = VFN(bd_tap)(v, src, cx - 1.0f, cy - 1.0f, size, shape);
  sum = VFN(add3)(sum, VFN(bd_tap)(v, src, cx + 1.0f, cy - 1.0f, size, shape));
  sum = VFN(add3)(sum, VFN(bd_tap)(v, src, cx - 1.0f, cy + 1.0f, size, shape));
  sum = VFN(add3)(sum, VFN(bd_tap)(v, src, cx + 1.0f, cy + 1.0f, size, shape));
  return VFN(rgba)(VFN(output_linear)(VFN(scale3)(sum, VFN(splat)(0.25f))), VFN(splat)(1.0f));
}
TSV_BATCH(bd_batch, bd_block, bd_variant, bd_batch_input, ts_tex2d)

/* ---- bloom_blur ---- */
static V4v VFN(bb_block)(const bb_variant *v, const bb_batch_input *in, const ts_tex2d *src, const size_t *pix) {
  static const float offsets[6] = {1.3366f, 3.4295f, 5.4264f, 7.4359f, 9.4436f, 11.4401f};
  static const float weights[6] = {0.2185f, 0.0821f, 0.0461f, 0.0262f, 0.0162f, 0.0102f};
  const V4v pos = TSV_REC(in, BB_SLOT_POS, pix);
  const V4v size = TSV_REC(in, BB_SLOT_SIZE, pix);
  const V4v params = TSV_REC(in, BB_SLOT_PARAMS, pix);
  const VF x = pos.x * size.z, y = pos.y * size.w;
  V3v sum = VFN(scale3)(VFN(hp_fetch)(src, x, y), VFN(splat)(0.2013f));
  for (int i = 0; i < 6; ++i) {
    V3v pair;
    if (v->direction == 0)
      pair = VFN(add3)(VFN(hp_fetch)(src, (pos.x + offsets[i]) * size.z, y),
                       VFN(hp_fetch)(src, (pos.x - offsets[i]) * size.z, y));
    else
      pair = VFN(add3)(VFN(hp_fetch)(src, x, (pos.y + offsets[i]) * size.w),
                       VFN(hp_fetch)(src, x, (pos.y - offsets[i]) * size.w));
    sum = VFN(add3)(sum, VFN(scale3)(pair, VFN(splat)(weights[i])));
  }
  return VFN(rgba)(VFN(output_linear)(VFN(scale3)(sum, params.x)), VFN(splat)(1.0f));
}
TSV_BATCH(bb_batch, bb_block, bb_variant, bb_batch_input, ts_tex2d)

/* ---- hdr_tonemap ---- */
/* Everything after the bloom fetch; raw: the bilinear bloom sample's rgb. */
TSV_INL V4v VFN(ht_finish)(const ht_variant *v, V3v fb, V4v params, V3v raw) {
  V3v bloom = VFN(scale3)(raw, VFN(sqrt)(VFN(max)(params.x, VFN(splat)(0.0f))));
  const VF one = VFN(splat)(1.0f);
  bloom = VFN(v3)(VFN(min)(bloom.x, one), VFN(min)(bloom.y, one), VFN(min)(bloom.z, one));
  const VF lum = VFN(dot3)(bloom, VFN(v3)(VFN(splat)(0.2125f), VFN(splat)(0.7154f), VFN(splat)(0.0721f)));
  const VF k = params.y * VFN(pow)(VFN(max)(lum, VFN(splat)(TS_POW_TINY_F)), params.z);
  const V3v c = VFN(add3)(VFN(scale3)(fb, params.x), VFN(scale3)(bloom, k));
  return VFN(rgba)(VFN(output)(c, v->output_mode), one);
}

static V4v VFN(ht_block)(const ht_variant *v, const ht_batch_input *in, const ts_tex2d *bloom_tex, const size_t *pix) {
  const V4v pos = TSV_REC(in, HT_SLOT_POS, pix);
  const V4v size = TSV_REC(in, HT_SLOT_SIZE, pix);
  const V3v fb = VFN(xyz)(TSV_REC(in, HT_SLOT_FRAME, pix));
  const V4v params = TSV_REC(in, HT_SLOT_PARAMS, pix);
  return VFN(ht_finish)(v, fb, params, VFN(hp_fetch)(bloom_tex, pos.x * size.z, pos.y * size.w));
}
TSV_BATCH(ht_batch, ht_block, ht_variant, ht_batch_input, ts_tex2d)

/* The tone map of one row (hdr_tonemap_f_row): the bilinear bloom sample is lerp(wy, H(y0), H(y1))
 * with H(r) = lerp(wx, texel(r, x0), texel(r, x1)), texture2D's own lerps in its own order, so
 * H(r) at the row's pixels is computed once (ht_hrow) and kept for the rows that read it again. */
static void VFN(ht_hrow)(const ht_batch_input *in, const ts_tex2d *t, int r, float *rgb, int count) {
  const float *row = t->texels + (size_t)r * (size_t)t->w * 4u;
  for (int first = 0; first < count; first += TSV_W) {
    size_t pix[TSV_W];
    const int n = VFN(block_pix)(first, count, pix);
    const V4v pos = TSV_REC(in, HT_SLOT_POS, pix);
    const V4v size = TSV_REC(in, HT_SLOT_SIZE, pix);
    VI x0, x1;
    VF wx;
    VFN(wrap_linear)(pos.x * size.z, t->w, t->wrap_s, &x0, &x1, &wx);
    const float *p0[TSV_W], *p1[TSV_W];
    for (int j = 0; j < TSV_W; ++j) {
      p0[j] = row + (size_t)x0[j] * 4u;
      p1[j] = row + (size_t)x1[j] * 4u;
    }
    const V4v h = VFN(lerp4)(wx, VFN(gather4)(p0), VFN(gather4)(p1));
    for (int j = 0; j < n; ++j) {
      rgb[first + j] = h.x[j];
      rgb[(size_t)count + (size_t)(first + j)] = h.y[j];
      rgb[2u * (size_t)count + (size_t)(first + j)] = h.z[j];
    }
  }
}

TSV_INL V4v VFN(ht_hload)(const float *rgb, int count, const size_t *pix, int n) {
  V4v h;
  h.w = VFN(splat)(0.0f);
  if (n == TSV_W) {
    __builtin_memcpy(&h.x, rgb + pix[0], sizeof(VF));
    __builtin_memcpy(&h.y, rgb + (size_t)count + pix[0], sizeof(VF));
    __builtin_memcpy(&h.z, rgb + 2u * (size_t)count + pix[0], sizeof(VF));
    return h;
  }
  for (int j = 0; j < TSV_W; ++j) {
    h.x[j] = rgb[pix[j]];
    h.y[j] = rgb[(size_t)count + pix[j]];
    h.z[j] = rgb[2u * (size_t)count + pix[j]];
  }
  return h;
}

static void VFN(ht_row)(const ht_variant *v, const ht_batch_input *in, const ts_tex2d *t, ht_bloom_rows *rows,
                        ts_vec4f *out, int count) {
  const size_t pix0[TSV_W] = {0};
  const V4v pos0 = TSV_REC(in, HT_SLOT_POS, pix0), size0 = TSV_REC(in, HT_SLOT_SIZE, pix0);
  VI y0, y1;
  VF wy;
  VFN(wrap_linear)(pos0.y * size0.w, t->h, t->wrap_t, &y0, &y1, &wy);
  const int need[2] = {y0[0], y1[0]};
  const float *h[2];
  for (int k = 0; k < 2; ++k) {
    int slot = rows->row[0] == need[k] ? 0 : rows->row[1] == need[k] ? 1 : -1;
    if (slot < 0) {
      slot = rows->row[0] == need[1 - k] ? 1 : 0; /* keep the other row this one needs */
      VFN(ht_hrow)(in, t, need[k], rows->rgb[slot], count);
      rows->row[slot] = need[k];
    }
    h[k] = rows->rgb[slot];
  }
  for (int first = 0; first < count; first += TSV_W) {
    size_t pix[TSV_W];
    const int n = VFN(block_pix)(first, count, pix);
    const V3v fb = VFN(xyz)(TSV_REC(in, HT_SLOT_FRAME, pix));
    const V4v params = TSV_REC(in, HT_SLOT_PARAMS, pix);
    const V4v raw = VFN(lerp4)(wy, VFN(ht_hload)(h[0], count, pix, n), VFN(ht_hload)(h[1], count, pix, n));
    VFN(store4)(VFN(ht_finish)(v, fb, params, VFN(xyz)(raw)), out + first, n);
  }
}

/* ---- hdr_formats.c on lanes ---- */
/* ts_quantize_half: round toward zero to fp16 and back, as bit masks. A finite value in the
 * half range keeps its float exponent and loses the mantissa bits below the half's step
 * (13 bits for a normal half, 13 + k for a half denormal k binades down); below 2^-24: +-0;
 * 2^16 and up: +-65504; Inf kept; NaN quieted with the 10-bit payload. */
TSV_INL VU VFN(quantize_half_bits)(VU u) {
  const VU sign = u & 0x80000000u, a = u & 0x7fffffffu;
  const VI e = (VI)(a >> 23) - 127;
  VI sh = VFN(seli)(e < -14, -1 - e, VFN(spliti)(13));
  sh = VFN(seli)(sh > 31, VFN(spliti)(31), sh); /* only lanes replaced below */
  VU b = sign | (a & ~(((VU)VFN(spliti)(1) << (VU)sh) - 1u));
  b = (VU)VFN(seli)(e < -24, (VI)sign, (VI)b);
  b = (VU)VFN(seli)(e >= 16, (VI)(sign | 0x477fe000u), (VI)b);
  b = (VU)VFN(seli)((VI)a == 0x7f800000, (VI)u, (VI)b);
  return (VU)VFN(seli)((VI)a > 0x7f800000, (VI)(sign | 0x7fc00000u | (a & 0x007fe000u)), (VI)b);
}

static void VFN(quantize_half_n)(const float *in, float *out, size_t n) {
  size_t i = 0;
  for (; i + TSV_W <= n; i += TSV_W) {
    VU u;
    __builtin_memcpy(&u, in + i, sizeof u);
    u = VFN(quantize_half_bits)(u);
    __builtin_memcpy(out + i, &u, sizeof u);
  }
  for (; i < n; ++i) out[i] = ts_quantize_half(in[i]);
}

/* ts_unorm8_from_float: saturate (NaN -> 0), then x * (255/256) + 2^15, low 8 bits. */
static void VFN(unorm8_n)(const float *in, uint8_t *out, size_t n) {
  size_t i = 0;
  for (; i + TSV_W <= n; i += TSV_W) {
    VF x;
    __builtin_memcpy(&x, in + i, sizeof x);
    const VF c = VFN(lp_min)(VFN(lp_max)(x, VFN(splat)(0.0f)), VFN(splat)(1.0f));
    const VU b = VFN(asu)(c * 0.99609375f + 32768.0f);
    for (int j = 0; j < TSV_W; ++j) out[i + (size_t)j] = (uint8_t)(b[j] & 0xffu);
  }
  for (; i < n; ++i) out[i] = ts_unorm8_from_float(in[i]);
}

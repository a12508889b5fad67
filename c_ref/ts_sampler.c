/* tiershade -- c_ref/ts_sampler.c
 * RGBA32F texture sampling, mirror of llvmpipe (Mesa 22.3.6) SoA float path.
 * Addressing read in gallivm lp_bld_sample_soa.c (lp_build_sample_wrap_nearest,
 * lp_build_sample_wrap_linear), lp_bld_sample.c (lp_build_cube_lookup,
 * lp_build_cube_imapos) and lp_bld_arit.c (lerp, fract_safe, ifloor, itrunc).
 * LINEAR and cube facts also in /work/shared/docs/llvmpipe_bitexact.md;
 * everything re-verified bit for bit against the driver (docs/c_math_layer.md).
 */
#include "ts_sampler.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

static uint32_t fb(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }
static float bf(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
/* DAZ: denormal -> zero of the same sign (what SSE compares see under MXCSR.DAZ) */
static float daz(float x) { return (fb(x) & 0x7f800000u) ? x : bf(fb(x) & 0x80000000u); }

static int is_pot(int n) { return n > 0 && (n & (n - 1)) == 0; }

static ts_vec4f texel(const float *tx, int w, int x, int y)
{
    const float *p = tx + ((size_t)y * (size_t)w + (size_t)x) * 4u;
    return ts_v4f(p[0], p[1], p[2], p[3]);
}

ts_vec4f ts_texelFetchf(const ts_tex2d *t, int x, int y)
{
    if (x < 0 || y < 0 || x >= t->w || y >= t->h) return ts_v4f(0.0f, 0.0f, 0.0f, 0.0f);
    return texel(t->texels, t->w, x, y);
}

/* ---------------------------------------------------------------------------- */
/* float32, llvmpipe-exact                                                       */
/* ---------------------------------------------------------------------------- */

static int clampi(int i, int lo, int hi) { return i < lo ? lo : (i > hi ? hi : i); }

/* lp_build_fract_safe: min(u - floor(u), 0x1.fffffep-1); a NaN gives the constant. */
static float fract_safe(float u)
{
    float f = u - ts_floorf(u);
    return f < 0x1.fffffep-1f ? f : 0x1.fffffep-1f;
}

/* lp_build_sample_wrap_nearest (float coords, normalized). */
static int wrap_nearest(float u, int len, int wrap)
{
    float lf = (float)len;
    if (wrap == TS_WRAP_REPEAT) {
        if (is_pot(len))                                /* ifloor(u*len) & (len-1) */
            return ts_lp_itruncf(ts_floorf(u * lf)) & (len - 1);
        return clampi(ts_lp_itruncf(fract_safe(u) * lf), 0, len - 1); /* itrunc */
    }
    return clampi(ts_lp_itruncf(u * lf), 0, len - 1);  /* CLAMP_TO_EDGE: itrunc, clamp */
}

/* lp_build_sample_wrap_linear (llvmpipe_bitexact.md "Texture sampling"). */
static void wrap_linear(float u, int len, int wrap, int *i0, int *i1, float *w)
{
    float lf = (float)len, c, fl;
    if (wrap == TS_WRAP_REPEAT) {
        if (!is_pot(len)) u = u - ts_floorf(u);
        c = u * lf - 0.5f;
        fl = ts_floorf(c);
        *w = c - fl;
        *i0 = ts_lp_itruncf(fl);
        *i1 = (int)((unsigned)*i0 + 1u);
        if (is_pot(len)) {
            *i0 &= len - 1;
            *i1 &= len - 1;
        } else {
            if (*i0 < 0) *i0 = len - 1;
            if (*i1 == len) *i1 = 0;
        }
    } else {
        c = ts_lp_minf(u * lf, lf);
        c = c - 0.5f;
        c = ts_lp_maxf(c, 0.0f);
        fl = ts_floorf(c);
        *w = c - fl;
        *i0 = ts_lp_itruncf(fl);
        *i1 = *i0 + 1 < len - 1 ? *i0 + 1 : len - 1;
    }
}

/* gallivm lerp(w, a, b) = mad(w, b - a, a). */
static ts_vec4f lerp4(float w, ts_vec4f a, ts_vec4f b)
{
    return ts_v4f(ts_madf(w, b.x - a.x, a.x), ts_madf(w, b.y - a.y, a.y),
                  ts_madf(w, b.z - a.z, a.z), ts_madf(w, b.w - a.w, a.w));
}

/* Fetch that never reads outside the image (llvmpipe only produces in-range
 * indices for finite coordinates; NaN/inf coordinates are clamped here). */
static ts_vec4f fetch_safe(const float *tx, int w, int h, int x, int y)
{
    return texel(tx, w, clampi(x, 0, w - 1), clampi(y, 0, h - 1));
}

static ts_vec4f sample2d_f(const float *tx, int w, int h, int wrap_s, int wrap_t,
                           int filter, float u, float v)
{
    int x0, x1, y0, y1;
    float wx, wy;
    if (filter == TS_FILTER_NEAREST)
        return fetch_safe(tx, w, h, wrap_nearest(u, w, wrap_s), wrap_nearest(v, h, wrap_t));
    wrap_linear(u, w, wrap_s, &x0, &x1, &wx);
    wrap_linear(v, h, wrap_t, &y0, &y1, &wy);
    return lerp4(wy, lerp4(wx, fetch_safe(tx, w, h, x0, y0), fetch_safe(tx, w, h, x1, y0)),
                 lerp4(wx, fetch_safe(tx, w, h, x0, y1), fetch_safe(tx, w, h, x1, y1)));
}

ts_vec4f ts_texture2Df(const ts_tex2d *t, ts_vec2f uv)
{
    return sample2d_f(t->texels, t->w, t->h, t->wrap_s, t->wrap_t, t->filter, uv.x, uv.y);
}

/* lp_build_cube_lookup (non-seamless, no derivatives), read in lp_bld_sample.c:
 * as_gt_at = |x| > |y| (unordered: NaN -> true); mx = maxps(|x|,|y|);
 * ar_ge = |z| >= mx (unordered); major = ar_ge ? Z : (as_gt_at ? X : Y).
 * The face is negative iff the SIGN BIT of the major coordinate is set (-0 -> -face);
 * minor coords are mirrored by XOR-ing sign bits: sc = {+X:-z, -X:z, Y:x, +Z:x, -Z:-x},
 * tc = {X:-y, +Y:z, -Y:-z, Z:-y}.  s = sc * ima + 0.5 (mul, add: no mad) with
 * ima = |ma| > 0 (unordered) ? 0.5/|ma| : 0, so a zero direction samples the
 * centre of the +-Z face. */
ts_vec4f ts_textureCubef(const ts_texcube *c, ts_vec3f d)
{
    const uint32_t S = 0x80000000u;
    float ax = bf(fb(d.x) & ~S), ay = bf(fb(d.y) & ~S), az = bf(fb(d.z) & ~S);
    float mx = ts_lp_maxf(ax, ay);
    int sel_x = !(daz(ax) <= daz(ay)); /* |x| UGT |y| */
    int sel_z = !(daz(az) < mx);       /* |z| UGE mx  */
    float ma = sel_z ? d.z : (sel_x ? d.x : d.y);
    uint32_t sg = fb(ma) & S;
    uint32_t sc, tc;
    int face;
    if (sel_z) { face = 4; sc = fb(d.x) ^ sg; tc = fb(d.y) ^ S; }
    else if (sel_x) { face = 0; sc = fb(d.z) ^ S ^ sg; tc = fb(d.y) ^ S; }
    else { face = 2; sc = fb(d.x); tc = fb(d.z) ^ sg; }
    face += sg ? 1 : 0;
    {
        float ama = bf(fb(ma) & ~S);
        float ima = !(daz(ama) <= 0.0f) ? 0.5f / ama : 0.0f; /* |ma| UGT 0, else 0 */
        float s = bf(sc) * ima + 0.5f, t = bf(tc) * ima + 0.5f;
        return sample2d_f(c->faces[face], c->size, c->size, TS_WRAP_CLAMP, TS_WRAP_CLAMP,
                          c->filter, s, t);
    }
}

/* ---------------------------------------------------------------------------- */
/* double reference: same addressing, computed in double                         */
/* ---------------------------------------------------------------------------- */

static ts_vec4d texel_d(const float *tx, int w, int h, int x, int y)
{
    ts_vec4f p = fetch_safe(tx, w, h, x, y);
    return ts_v4d(p.x, p.y, p.z, p.w);
}

static int itrunc_d(double x)
{
    if (!(x > -2147483648.0 && x < 2147483647.0)) return x > 0 ? 2147483647 : -2147483647;
    return (int)x;
}

static int wrap_nearest_d(double u, int len, int wrap)
{
    if (wrap == TS_WRAP_REPEAT) u -= floor(u);
    return clampi(itrunc_d(floor(u * len)), 0, len - 1);
}

static void wrap_linear_d(double u, int len, int wrap, int *i0, int *i1, double *w)
{
    double c, fl;
    if (wrap == TS_WRAP_REPEAT) {
        u -= floor(u);
        c = u * len - 0.5;
        fl = floor(c);
        *w = c - fl;
        *i0 = itrunc_d(fl);           /* in [-1, len-1] */
        *i1 = *i0 + 1;
        if (*i0 < 0) *i0 += len;
        if (*i1 >= len) *i1 -= len;
    } else {
        c = u * len;
        c = (c < len ? c : len) - 0.5; /* NaN -> len - 0.5 */
        c = c > 0.0 ? c : 0.0;
        fl = floor(c);
        *w = c - fl;
        *i0 = itrunc_d(fl);
        *i1 = *i0 + 1 < len - 1 ? *i0 + 1 : len - 1;
    }
}

static ts_vec4d lerp4d(double w, ts_vec4d a, ts_vec4d b)
{
    return ts_v4d(a.x + w * (b.x - a.x), a.y + w * (b.y - a.y),
                  a.z + w * (b.z - a.z), a.w + w * (b.w - a.w));
}

static ts_vec4d sample2d_d(const float *tx, int w, int h, int wrap_s, int wrap_t,
                           int filter, double u, double v)
{
    int x0, x1, y0, y1;
    double wx, wy;
    if (filter == TS_FILTER_NEAREST)
        return texel_d(tx, w, h, wrap_nearest_d(u, w, wrap_s), wrap_nearest_d(v, h, wrap_t));
    wrap_linear_d(u, w, wrap_s, &x0, &x1, &wx);
    wrap_linear_d(v, h, wrap_t, &y0, &y1, &wy);
    return lerp4d(wy, lerp4d(wx, texel_d(tx, w, h, x0, y0), texel_d(tx, w, h, x1, y0)),
                  lerp4d(wx, texel_d(tx, w, h, x0, y1), texel_d(tx, w, h, x1, y1)));
}

ts_vec4d ts_texture2Dd(const ts_tex2d *t, ts_vec2d uv)
{
    return sample2d_d(t->texels, t->w, t->h, t->wrap_s, t->wrap_t, t->filter, uv.x, uv.y);
}

ts_vec4d ts_textureCubed(const ts_texcube *c, ts_vec3d d)
{
    /* same face rule as the float mirror, sign taken from the sign bit */
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z), ma, sc, tc;
    int face;
    if (az >= (ax > ay ? ax : ay)) { face = 4; ma = d.z; sc = signbit(ma) ? -d.x : d.x; tc = -d.y; }
    else if (ax > ay) { face = 0; ma = d.x; sc = signbit(ma) ? d.z : -d.z; tc = -d.y; }
    else { face = 2; ma = d.y; sc = d.x; tc = signbit(ma) ? -d.z : d.z; }
    face += signbit(ma) ? 1 : 0;
    ma = fabs(ma) > 0.0 ? 0.5 / fabs(ma) : 0.0;
    return sample2d_d(c->faces[face], c->size, c->size, TS_WRAP_CLAMP, TS_WRAP_CLAMP,
                      c->filter, sc * ma + 0.5, tc * ma + 0.5);
}

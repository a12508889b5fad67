/* tiershade -- c_ref/ts_sampler3d.c
 * RGBA32F 3D texture sampling, mirror of llvmpipe (Mesa 22.3.6) SoA float path.
 * Addressing: gallivm lp_bld_sample_soa.c (lp_build_sample_wrap_nearest,
 * lp_build_sample_wrap_linear), applied per axis exactly as for 2D textures
 * (/work/shared/docs/llvmpipe_bitexact.md "Texture sampling"; c_ref/ts_sampler.c).
 * Trilinear = lerp(wz, bilinear(slice z0), bilinear(slice z1)), bilinear =
 * lerp(wy, lerp(wx, t000, t100), lerp(wx, t010, t110)), lerp = mad(w, b - a, a)
 * fused iff the host has FMA (gallivm lp_build_lerp_3d; measured bit for bit by
 * tests/unit/test_sampler3d.cpp on OSMesa GL 3.3 and EGL GLES 3.0).
 * The wrap helpers repeat ts_sampler.c's rules (its helpers are file-local).
 */
#include "ts_sampler3d.h"

#include <math.h>
#include <stddef.h>

static int is_pot(int n) { return n > 0 && (n & (n - 1)) == 0; }
static int clampi(int i, int lo, int hi) { return i < lo ? lo : (i > hi ? hi : i); }

static ts_vec4f texel(const ts_tex3d *t, int x, int y, int z)
{
    const float *p = t->texels + (((size_t)z * (size_t)t->h + (size_t)y) * (size_t)t->w + (size_t)x) * 4u;
    return ts_v4f(p[0], p[1], p[2], p[3]);
}

/* Never reads outside the volume: llvmpipe produces in-range indices for
 * finite coordinates; NaN/inf coordinates are clamped here. */
static ts_vec4f fetch_safe(const ts_tex3d *t, int x, int y, int z)
{
    return texel(t, clampi(x, 0, t->w - 1), clampi(y, 0, t->h - 1), clampi(z, 0, t->d - 1));
}

ts_vec4f ts_texelFetch3Df(const ts_tex3d *t, int x, int y, int z)
{
    if (x < 0 || y < 0 || z < 0 || x >= t->w || y >= t->h || z >= t->d) return ts_v4f(0.0f, 0.0f, 0.0f, 0.0f);
    return texel(t, x, y, z);
}

/* ---------------------------------------------------------------------------- */
/* float32, llvmpipe-exact                                                       */
/* ---------------------------------------------------------------------------- */

/* lp_build_fract_safe: min(u - floor(u), 0x1.fffffep-1); a NaN gives the constant. */
static float fract_safe(float u)
{
    float f = u - ts_floorf(u);
    return f < 0x1.fffffep-1f ? f : 0x1.fffffep-1f;
}

static int wrap_nearest(float u, int len, int wrap)
{
    float lf = (float)len;
    if (wrap == TS_WRAP_REPEAT) {
        if (is_pot(len)) return ts_lp_itruncf(ts_floorf(u * lf)) & (len - 1);
        return clampi(ts_lp_itruncf(fract_safe(u) * lf), 0, len - 1);
    }
    return clampi(ts_lp_itruncf(u * lf), 0, len - 1);
}

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

ts_vec4f ts_texture3Df(const ts_tex3d *t, ts_vec3f p)
{
    int x0, x1, y0, y1, z0, z1;
    float wx, wy, wz;
    ts_vec4f s0, s1;
    if (t->filter == TS_FILTER_NEAREST)
        return fetch_safe(t, wrap_nearest(p.x, t->w, t->wrap_s), wrap_nearest(p.y, t->h, t->wrap_t),
                          wrap_nearest(p.z, t->d, t->wrap_r));
    wrap_linear(p.x, t->w, t->wrap_s, &x0, &x1, &wx);
    wrap_linear(p.y, t->h, t->wrap_t, &y0, &y1, &wy);
    wrap_linear(p.z, t->d, t->wrap_r, &z0, &z1, &wz);
    s0 = lerp4(wy, lerp4(wx, fetch_safe(t, x0, y0, z0), fetch_safe(t, x1, y0, z0)),
               lerp4(wx, fetch_safe(t, x0, y1, z0), fetch_safe(t, x1, y1, z0)));
    s1 = lerp4(wy, lerp4(wx, fetch_safe(t, x0, y0, z1), fetch_safe(t, x1, y0, z1)),
               lerp4(wx, fetch_safe(t, x0, y1, z1), fetch_safe(t, x1, y1, z1)));
    return lerp4(wz, s0, s1);
}

/* ---------------------------------------------------------------------------- */
/* double reference: same addressing, computed in double                         */
/* ---------------------------------------------------------------------------- */

static ts_vec4d texel_d(const ts_tex3d *t, int x, int y, int z)
{
    ts_vec4f p = fetch_safe(t, x, y, z);
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
        *i0 = itrunc_d(fl); /* in [-1, len-1] */
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
    return ts_v4d(a.x + w * (b.x - a.x), a.y + w * (b.y - a.y), a.z + w * (b.z - a.z), a.w + w * (b.w - a.w));
}

ts_vec4d ts_texture3Dd(const ts_tex3d *t, ts_vec3d p)
{
    int x0, x1, y0, y1, z0, z1;
    double wx, wy, wz;
    ts_vec4d s0, s1;
    if (t->filter == TS_FILTER_NEAREST)
        return texel_d(t, wrap_nearest_d(p.x, t->w, t->wrap_s), wrap_nearest_d(p.y, t->h, t->wrap_t),
                       wrap_nearest_d(p.z, t->d, t->wrap_r));
    wrap_linear_d(p.x, t->w, t->wrap_s, &x0, &x1, &wx);
    wrap_linear_d(p.y, t->h, t->wrap_t, &y0, &y1, &wy);
    wrap_linear_d(p.z, t->d, t->wrap_r, &z0, &z1, &wz);
    s0 = lerp4d(wy, lerp4d(wx, texel_d(t, x0, y0, z0), texel_d(t, x1, y0, z0)),
                lerp4d(wx, texel_d(t, x0, y1, z0), texel_d(t, x1, y1, z0)));
    s1 = lerp4d(wy, lerp4d(wx, texel_d(t, x0, y0, z1), texel_d(t, x1, y0, z1)),
                lerp4d(wx, texel_d(t, x0, y1, z1), texel_d(t, x1, y1, z1)));
    return lerp4d(wz, s0, s1);
}

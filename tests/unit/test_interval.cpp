// tiershade tests: the interval operations of c_ref/math/ts_interval.c (GLSL ES 3.00 highp bounds).
// Each bound is checked against float32 evaluation (the llvmpipe mirror ts_*f of c_ref/math with
// FTZ/DAZ set, the way llvmpipe runs, plus the other summation orders and fused forms where the
// rule allows them) and against the double reference: both must lie inside. Inputs: a stride of
// every float32 bit pattern (exhaustive up to the stride), random points and random intervals
// with values drawn inside them, and the edges 0, -0, denormals, FLT_MIN, FLT_MAX, Inf, NaN.
// Widths are checked too (an interval that swallows everything would contain everything):
// + - * at most 1 ULP on a normal result (either neighbour), and exact on representable ones.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if anything failed.
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "math/ts_interval.h"
#include "math/ts_math.h"
#include "math/ts_sampler.h"
#include "math/ts_sampler3d.h"
#include "unit_check.h"

using unit_check::bits_of;
using unit_check::check;
using unit_check::float_of_bits;

namespace {

struct Rng {
  uint64_t s = 0x9e3779b97f4a7c15ull;
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return static_cast<uint32_t>(s >> 16);
  }
  float uniform(float lo, float hi) { return lo + (hi - lo) * static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
  float any_float() { return float_of_bits(next()); }
};

const float kEdges[] = {0.f,         -0.f,         1e-40f,  -1e-40f, FLT_MIN,  -FLT_MIN, 1.f,      -1.f, 0.5f, 2.f,
                        FLT_MAX,     -FLT_MAX,     INFINITY, -INFINITY, NAN,   65504.f,  1e30f,    -1e30f, 3.f, 0.1f,
                        0x1.fffffep-1f, 0x1.000002p+0f, 1e-30f, 127.9f, -126.5f, 150.f};

std::string fmt(float x) {
  char b[64];
  snprintf(b, sizeof b, "%.9g (0x%08x)", x, bits_of(x));
  return b;
}
std::string fmt(ts_iv a) {
  char b[128];
  snprintf(b, sizeof b, "[%.9g, %.9g]%s", a.lo, a.hi, a.nan ? "+NaN" : "");
  return b;
}

// the values to try: edges, a stride over every bit pattern, random floats
std::vector<float> sample_floats(uint32_t stride, int randoms, Rng &r) {
  std::vector<float> v(std::begin(kEdges), std::end(kEdges));
  for (uint64_t b = 0; b < (1ull << 32); b += stride) v.push_back(float_of_bits(static_cast<uint32_t>(b)));
  for (int i = 0; i < randoms; ++i) v.push_back(r.any_float());
  return v;
}

// A double value's rounding to float32 under FTZ: both neighbours (and 0 when flushing).
bool double_inside(ts_iv iv, double d) {
  if (std::isnan(d)) return iv.nan || (iv.lo == -INFINITY && iv.hi == INFINITY);
  return static_cast<double>(iv.lo) <= d && d <= static_cast<double>(iv.hi);
}

// Checks one unary rule over xs: f32 (the llvmpipe mirror) and f64 (the double reference) inside.
void check_unary(const char *name, const std::vector<float> &xs, ts_iv (*ivf)(ts_iv), float (*f32)(float),
                 double (*f64)(double), double max_width_ulp, bool (*in_domain)(float)) {
  long bad = 0, bad_d = 0, wide = 0, n = 0;
  std::string first, first_d, first_w;
  for (float x : xs) {
    if (!in_domain(x)) continue;
    ++n;
    const ts_iv iv = ivf(ts_ivpoint(x));
    const float y = f32(x);
    if (!ts_ivcontains(iv, y) && bad++ == 0) first = "x " + fmt(x) + " f32 " + fmt(y) + " not in " + fmt(iv);
    const double yd = f64(static_cast<double>(x));
    if (std::isfinite(yd) && std::fabs(yd) >= FLT_MIN && std::fabs(yd) <= FLT_MAX && !double_inside(iv, yd) &&
        bad_d++ == 0)
      first_d = "x " + fmt(x) + " f64 " + std::to_string(yd) + " not in " + fmt(iv);
    if (std::isfinite(yd) && std::fabs(yd) >= FLT_MIN && std::fabs(yd) < FLT_MAX / 2 &&
        ts_ivwidth_ulp(iv) > max_width_ulp && wide++ == 0)
      first_w = "x " + fmt(x) + " width " + std::to_string(ts_ivwidth_ulp(iv)) + " ULP " + fmt(iv);
  }
  check(bad == 0, std::string(name) + " llvmpipe mirror inside (" + std::to_string(n) + " points)", first);
  check(bad_d == 0, std::string(name) + " double reference inside", first_d);
  check(wide == 0, std::string(name) + " width at most " + std::to_string(max_width_ulp) + " ULP", first_w);
}

bool dom_pos(float x) { return x > 0 && ts_ivpoint(x).lo > 0; }  // x > 0 after DAZ
bool dom_exp2(float x) { return std::fabs(x) < 120.f; }

float f_exp2(float x) { return ts_exp2f(x); }
float f_log2(float x) { return ts_log2f(x); }
float f_isqrt(float x) { return ts_inversesqrtf(x); }
float f_sqrt(float x) { return ts_sqrtf(x); }
double d_isqrt(double x) { return 1.0 / std::sqrt(x); }
double d_exp2(double x) { return std::exp2(x); }
double d_log2(double x) { return std::log2(x); }
double d_sqrt(double x) { return std::sqrt(x); }

// + - * /: point operands (edges x edges, random pairs) and random intervals with inner values
void check_binary(Rng &r) {
  struct Op {
    const char *name;
    ts_iv (*iv)(ts_iv, ts_iv);
    std::function<float(float, float)> f32;
    std::function<double(double, double)> f64;
    double width;  // ULP on normal results
  };
  const Op ops[] = {
      {"add", ts_addiv, [](float a, float b) { return a + b; }, [](double a, double b) { return a + b; }, 1},
      {"sub", ts_subiv, [](float a, float b) { return a - b; }, [](double a, double b) { return a - b; }, 1},
      {"mul", ts_muliv, [](float a, float b) { return a * b; }, [](double a, double b) { return a * b; }, 1},
      // 2.5 ULP each side of the exact quotient: at most 5 ULP, and 10 across a power of two
      {"div", ts_diviv, [](float a, float b) { return a / b; }, [](double a, double b) { return a / b; }, 10},
  };
  std::vector<std::pair<float, float>> pairs;
  for (float a : kEdges)
    for (float b : kEdges) pairs.push_back({a, b});
  for (int i = 0; i < 200000; ++i) {
    const int kind = static_cast<int>(r.next() % 3);
    const float a = kind == 0 ? r.any_float() : r.uniform(-4, 4), b = kind == 2 ? r.any_float() : r.uniform(-4, 4);
    pairs.push_back({a, b});
    // close magnitudes: cancellation in add/sub
    pairs.push_back({a, -nextafterf(a, INFINITY)});
  }
  for (const Op &op : ops) {
    long bad = 0, bad_d = 0, wide = 0, inexact = 0;
    std::string first, first_d, first_w, first_e;
    for (auto [a, b] : pairs) {
      const ts_iv iv = op.iv(ts_ivpoint(a), ts_ivpoint(b));
      const float y = op.f32(a, b);
      if (!ts_ivcontains(iv, y) && bad++ == 0) first = fmt(a) + ", " + fmt(b) + ": f32 " + fmt(y) + " not in " + fmt(iv);
      const double yd = op.f64(a, b);
      const bool normal = std::isfinite(yd) && std::fabs(yd) >= FLT_MIN && std::fabs(yd) <= FLT_MAX &&
                          std::fabs(a) >= FLT_MIN && std::fabs(b) >= FLT_MIN && std::isfinite(a) && std::isfinite(b);
      if (normal && !double_inside(iv, yd) && bad_d++ == 0)
        first_d = fmt(a) + ", " + fmt(b) + ": f64 " + std::to_string(yd) + " not in " + fmt(iv);
      // (results below 2^-120 may flush to 0 after their allowance: not a width finding)
      // (the CTS bounds a quotient only for |b| in [2^-126, 2^127]: any result outside)
      const bool div_range = op.width == 1 || (std::fabs(b) >= 0x1p-126f && std::fabs(b) <= 0x1p127f);
      if (normal && div_range && std::fabs(yd) < FLT_MAX / 4 && std::fabs(yd) > 0x1p-120 && ts_ivwidth_ulp(iv) > op.width &&
          wide++ == 0)
        first_w = fmt(a) + ", " + fmt(b) + ": width " + std::to_string(ts_ivwidth_ulp(iv)) + " " + fmt(iv);
      // + - *: an exactly representable result admits only itself
      // (only where the double operation itself is exact: operands within 2^25 of each other)
      const double ratio = std::fabs(static_cast<double>(a) / b);
      if (op.width == 1 && normal && ratio > 0x1p-25 && ratio < 0x1p25 && static_cast<double>(static_cast<float>(yd)) == yd &&
          iv.lo != iv.hi &&
          inexact++ == 0)
        first_e = fmt(a) + ", " + fmt(b) + ": exact " + std::to_string(yd) + " but " + fmt(iv);
    }
    check(bad == 0, std::string(op.name) + " float32 result inside (" + std::to_string(pairs.size()) + " pairs)", first);
    check(bad_d == 0, std::string(op.name) + " double reference inside", first_d);
    check(wide == 0, std::string(op.name) + " width at most " + std::to_string(op.width) + " ULP", first_w);
    if (op.width == 1) check(inexact == 0, std::string(op.name) + " representable results exact", first_e);
    // random intervals: values drawn inside the operands give results inside the result
    long bad_i = 0;
    std::string first_i;
    for (int i = 0; i < 100000; ++i) {
      float a0 = r.uniform(-8, 8), a1 = r.uniform(-8, 8), b0 = r.uniform(-8, 8), b1 = r.uniform(-8, 8);
      if (op.width > 1) b0 = r.uniform(0.25f, 8), b1 = r.uniform(0.25f, 8);
      const ts_iv ia = ts_ivrange(std::fmin(a0, a1), std::fmax(a0, a1)), ib = ts_ivrange(std::fmin(b0, b1), std::fmax(b0, b1));
      const ts_iv iv = op.iv(ia, ib);
      for (int k = 0; k < 4; ++k) {
        const float a = r.uniform(ia.lo, ia.hi), b = r.uniform(ib.lo, ib.hi);
        const float y = op.f32(a, b);
        if (!ts_ivcontains(iv, y) && bad_i++ == 0) first_i = fmt(a) + ", " + fmt(b) + ": " + fmt(y) + " not in " + fmt(iv);
      }
    }
    check(bad_i == 0, std::string(op.name) + " on intervals: inner values inside", first_i);
  }
  // NaN and Inf edges
  check(ts_addiv(ts_ivpoint(INFINITY), ts_ivpoint(-INFINITY)).nan, "add Inf - Inf admits NaN");
  check(ts_muliv(ts_ivpoint(0.f), ts_ivpoint(INFINITY)).nan, "mul 0 * Inf admits NaN");
  check(ts_diviv(ts_ivpoint(1.f), ts_ivrange(-1.f, 1.f)).nan, "div by an interval around 0: any result");
  const ts_iv ov = ts_muliv(ts_ivpoint(FLT_MAX), ts_ivpoint(2.f));
  check(ov.hi == INFINITY && ov.lo == FLT_MAX, "mul overflow admits FLT_MAX and Inf", fmt(ov));
  const ts_iv tiny = ts_muliv(ts_ivpoint(1e-20f), ts_ivpoint(1e-20f));
  check(ts_ivcontains(tiny, 0.f) && tiny.hi <= FLT_MIN, "mul underflow admits the FTZ 0", fmt(tiny));
  const ts_iv den = ts_ivpoint(1e-40f);
  check(ts_ivcontains(den, 0.f) && !ts_ivcontains(den, 2 * FLT_MIN), "a denormal input admits DAZ 0", fmt(den));
}

void check_builtins(Rng &r) {
  const std::vector<float> xs = sample_floats(4099, 200000, r);
  check_unary("exp2", xs, ts_exp2iv, f_exp2, d_exp2, 2 * (3 + 2 * 120) + 2, dom_exp2);
  // log2: 3 ULP each side (8 with the power-of-two rule) outside [0.5, 2]; inside it the absolute
  // 2^-21 is many ULP of a small log2, so its width is checked in absolute terms below
  std::vector<float> xs_far, xs_near;
  for (float x : xs) (x >= 0.5f && x <= 2.f ? xs_near : xs_far).push_back(x);
  // (9: 3 below and 6 above a result just under a power of two, e.g. log2(FLT_MAX) ~ 128)
  check_unary("log2 outside [0.5, 2]", xs_far, ts_log2iv, f_log2, d_log2, 9, dom_pos);
  check_unary("log2 in [0.5, 2]", xs_near, ts_log2iv, f_log2, d_log2, INFINITY, dom_pos);
  float worst_abs = 0;
  for (float x : xs_near) worst_abs = std::fmax(worst_abs, ts_log2iv(ts_ivpoint(x)).hi - ts_log2iv(ts_ivpoint(x)).lo);
  // 2 x 2^-21, plus one float ULP of 1 at each end for the outward rounding
  check(worst_abs <= 0x1p-20f + 0x1p-22f, "log2 in [0.5, 2]: width at most 2 x 2^-21 + 2 ULP", std::to_string(worst_abs));
  // inversesqrt 2 ULP each side, 8 across a power of two
  check_unary("inversesqrt", xs, ts_inversesqrtiv, f_isqrt, d_isqrt, 8, dom_pos);
  // sqrt = 1 / inversesqrt: inversesqrt's 2 ULP and the division's 2.5 compound (16 with the rule)
  check_unary("sqrt", xs, ts_sqrtiv, f_sqrt, d_sqrt, 16, dom_pos);
  // log2 near 1: the absolute 2^-21 rule, not 3 ULP of a tiny result
  const ts_iv l1 = ts_log2iv(ts_ivpoint(1.f));
  check(l1.lo <= -0x1p-21f && l1.hi >= 0x1p-21f && l1.hi < 0x1p-20f, "log2(1) within the absolute 2^-21", fmt(l1));
  check(ts_log2iv(ts_ivpoint(0.f)).nan && ts_log2iv(ts_ivpoint(-1.f)).nan, "log2 of x <= 0: any result");
  check(ts_inversesqrtiv(ts_ivpoint(0.f)).nan, "inversesqrt(0): any result");
  check(ts_sqrtiv(ts_ivpoint(0.f)).lo == 0 && ts_sqrtiv(ts_ivpoint(0.f)).hi == 0, "sqrt(0) = 0");
  check(ts_sqrtiv(ts_ivpoint(-1.f)).nan, "sqrt(-1): any result");
  // pow = exp2(y log2 x): llvmpipe's and the double pow inside, x > 0
  long bad = 0, bad_d = 0;
  std::string first, first_d;
  for (int i = 0; i < 300000; ++i) {
    const float x = i % 3 ? r.uniform(1e-3f, 4.f) : float_of_bits(r.next() & 0x7fffffffu);
    const float y = i % 2 ? r.uniform(-4.f, 4.f) : r.uniform(0.f, 150.f);
    if (!(x > 0) || !std::isfinite(x) || ts_ivpoint(x).lo == 0) continue;
    const ts_iv iv = ts_powiv(ts_ivpoint(x), ts_ivpoint(y));
    const float p = ts_powf(x, y);
    if (!ts_ivcontains(iv, p) && bad++ == 0) first = "pow(" + fmt(x) + ", " + fmt(y) + ") = " + fmt(p) + " not in " + fmt(iv);
    const double pd = std::pow(static_cast<double>(x), static_cast<double>(y));
    if (pd >= FLT_MIN && pd <= FLT_MAX && !double_inside(iv, pd) && bad_d++ == 0)
      first_d = "pow(" + fmt(x) + ", " + fmt(y) + ") = " + std::to_string(pd) + " not in " + fmt(iv);
  }
  check(bad == 0, "pow llvmpipe mirror inside", first);
  check(bad_d == 0, "pow double reference inside", first_d);
  check(ts_powiv(ts_ivpoint(0.f), ts_ivpoint(0.4545f)).nan, "pow(0, y): any result (log2(0) undefined)");
  // min / max / clamp / step
  const ts_iv a = ts_ivrange(-1, 2), b = ts_ivrange(0.5f, 3);
  const ts_iv mn = ts_miniv(a, b), mx = ts_maxiv(a, b);
  check(mn.lo == -1 && mn.hi == 2 && mx.lo == 0.5f && mx.hi == 3, "min and max of intervals", fmt(mn) + " " + fmt(mx));
  check(ts_miniv(ts_ivpoint(NAN), ts_ivpoint(0)).nan && ts_clampiv(ts_ivpoint(NAN), ts_ivpoint(0), ts_ivpoint(1)).nan,
        "min and clamp of a NaN: any result");
  const ts_iv s = ts_stepiv(ts_ivpoint(0.5f), ts_ivrange(0.f, 1.f)), s1 = ts_stepiv(ts_ivpoint(0.5f), ts_ivpoint(0.7f));
  check(s.lo == 0 && s.hi == 1 && s1.lo == 1 && s1.hi == 1, "step straddling takes both branches", fmt(s) + " " + fmt(s1));
  check(ts_leiv(ts_ivrange(0, 1), ts_ivpoint(0.5f)) == TS_IV_EITHER && ts_leiv(ts_ivrange(0, 0.4f), ts_ivpoint(0.5f)) == TS_IV_TRUE &&
            ts_leiv(ts_ivpoint(NAN), ts_ivpoint(0)) == TS_IV_EITHER,
        "comparisons: true, either, NaN either");
}

// dot3 in every order, fused or not
void check_dot(Rng &r) {
  long bad = 0, bad_d = 0, wide = 0;
  std::string first, first_d, first_w;
  for (int i = 0; i < 200000; ++i) {
    float a[3], b[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = i % 4 ? r.uniform(-2, 2) : r.uniform(-1e4f, 1e4f);
      b[k] = r.uniform(-2, 2);
    }
    const ts_iv iv = ts_dot3iv(ts_v3iv(ts_ivpoint(a[0]), ts_ivpoint(a[1]), ts_ivpoint(a[2])),
                               ts_v3iv(ts_ivpoint(b[0]), ts_ivpoint(b[1]), ts_ivpoint(b[2])));
    const float p0 = a[0] * b[0], p1 = a[1] * b[1], p2 = a[2] * b[2];
    const float forms[] = {(p0 + p1) + p2, p0 + (p1 + p2), (p0 + p2) + p1,
                           std::fma(a[2], b[2], std::fma(a[1], b[1], p0)), std::fma(a[0], b[0], std::fma(a[1], b[1], p2)),
                           ts_dot3f(ts_v3f(a[0], a[1], a[2]), ts_v3f(b[0], b[1], b[2]))};
    for (float f : forms)
      if (!ts_ivcontains(iv, f) && bad++ == 0) first = "dot form " + fmt(f) + " not in " + fmt(iv);
    const double d = static_cast<double>(a[0]) * b[0] + static_cast<double>(a[1]) * b[1] + static_cast<double>(a[2]) * b[2];
    if (!double_inside(iv, d) && bad_d++ == 0) first_d = std::to_string(d) + " not in " + fmt(iv);
    // width: 5 ULP of 2 M each side; no wider than 24 ULP of M (and so of |result| when no cancellation)
    const double m = std::fabs(static_cast<double>(p0)) + std::fabs(static_cast<double>(p1)) + std::fabs(static_cast<double>(p2));
    if (std::fabs(d) > m / 2 && ts_ivwidth_ulp(iv) > 48 && wide++ == 0) first_w = "width " + std::to_string(ts_ivwidth_ulp(iv));
  }
  check(bad == 0, "dot3 in any order and fused forms inside", first);
  check(bad_d == 0, "dot3 double reference inside", first_d);
  check(wide == 0, "dot3 width without cancellation at most 48 ULP", first_w);
}

// texture lookups: the dEQP lookup precision (coordBits 20, uvwBits 7), or the hull of the reachable texels
void check_texture(Rng &r) {
  const int w = 7, h = 5;
  std::vector<float> tx(static_cast<size_t>(w) * h * 4);
  for (float &v : tx) v = r.uniform(-3, 3);
  long bad = 0, trials = 0;
  std::string first;
  for (int wrap = 0; wrap < 2; ++wrap)
    for (int filter = 0; filter < 2; ++filter) {
      const ts_tex2d t = ts_tex2d_single(w, h, tx.data(), wrap, wrap, filter);
      for (int i = 0; i < 20000; ++i) {
        const float u0 = r.uniform(-1.5f, 2.5f), v0 = r.uniform(-1.5f, 2.5f);
        // wide ranges (the hull fallback) and narrow ones (a point, a fragment's coordinate)
        const float du = i % 2 ? r.uniform(0, 0.2f) : (i % 4 ? 0.f : r.uniform(0, 1e-3f)), dv = i % 2 ? r.uniform(0, 0.2f) : 0.f;
        const ts_vec4iv iv = ts_texture2Div(&t, ts_v2iv(ts_ivrange(u0, u0 + du), ts_ivrange(v0, v0 + dv)));
        for (int k = 0; k < 4; ++k) {
          ++trials;
          const ts_vec4f s = ts_texture2Df(&t, ts_v2f(r.uniform(u0, u0 + du), r.uniform(v0, v0 + dv)));
          if ((!ts_ivcontains(iv.x, s.x) || !ts_ivcontains(iv.y, s.y) || !ts_ivcontains(iv.z, s.z) ||
               !ts_ivcontains(iv.w, s.w)) &&
              bad++ == 0)
            first = "wrap " + std::to_string(wrap) + " filter " + std::to_string(filter) + ": " + fmt(s.x) + " vs " + fmt(iv.x);
        }
      }
    }
  check(bad == 0, "texture2D llvmpipe mirror inside (" + std::to_string(trials) + " lookups)", first);
  // a point coordinate at a texel centre on a LINEAR texture: within 2^-7 of the weight either side,
  // so far narrower than the hull of the texture (texels in [-3, 3])
  const ts_tex2d lin = ts_tex2d_single(w, h, tx.data(), TS_WRAP_CLAMP, TS_WRAP_CLAMP, TS_FILTER_LINEAR);
  const ts_vec4iv c = ts_texture2Div(&lin, ts_v2iv(ts_ivpoint(2.5f / w), ts_ivpoint(1.5f / h)));
  const float t21 = tx[(1 * w + 2) * 4];
  check(ts_ivcontains(c.x, t21) && c.x.hi - c.x.lo < 6.f * 4 / 128 + 1e-5f,
        "texture2D at a texel centre: the texel, +-2^-7 of its neighbours' differences", fmt(c.x));
}

// cube lookups: every face the direction box can select, seamless or not; the llvmpipe mirror
// (non-seamless, CLAMP_TO_EDGE per face) inside for directions drawn in the box, near face edges
// and corners too; a point direction at a face centre is narrow; the zero vector: any result
void check_cube(Rng &r) {
  const int n = 5;
  std::vector<float> faces(static_cast<size_t>(6) * n * n * 4);
  for (float &v : faces) v = r.uniform(-2, 2);
  long bad = 0, trials = 0;
  std::string first;
  for (int filter = 0; filter < 2; ++filter) {
    ts_texcube c;
    c.size = n;
    c.filter = filter;
    for (int f = 0; f < 6; ++f) c.faces[f] = faces.data() + static_cast<size_t>(f) * n * n * 4;
    for (int i = 0; i < 20000; ++i) {
      // half the boxes near a cube edge or corner (|x| ~ |y|, ~ |z|), half anywhere
      float d0[3];
      for (float &v : d0) v = r.uniform(-1, 1);
      if (i % 2) d0[1] = std::copysign(std::fabs(d0[0]) * r.uniform(0.98f, 1.02f), d0[1]);
      const float dd = i % 3 == 0 ? 0.f : r.uniform(0, i % 3 == 1 ? 1e-3f : 0.1f);
      const ts_vec3iv box = ts_v3iv(ts_ivrange(d0[0], d0[0] + dd), ts_ivrange(d0[1], d0[1] + dd), ts_ivrange(d0[2], d0[2] + dd));
      const ts_vec4iv iv = ts_textureCubeiv(&c, box);
      for (int k = 0; k < 4; ++k) {
        ++trials;
        const ts_vec4f s = ts_textureCubef(&c, ts_v3f(r.uniform(d0[0], d0[0] + dd), r.uniform(d0[1], d0[1] + dd),
                                                      r.uniform(d0[2], d0[2] + dd)));
        if ((!ts_ivcontains(iv.x, s.x) || !ts_ivcontains(iv.y, s.y) || !ts_ivcontains(iv.z, s.z) || !ts_ivcontains(iv.w, s.w)) &&
            bad++ == 0)
          first = "filter " + std::to_string(filter) + ": " + fmt(s.x) + " vs " + fmt(iv.x);
      }
    }
    // the centre of +X: the centre texel, within 2^-7 of its neighbours' differences (LINEAR), exact (NEAREST)
    const ts_vec4iv ctr = ts_textureCubeiv(&c, ts_v3iv(ts_ivpoint(1.f), ts_ivpoint(0.f), ts_ivpoint(0.f)));
    const float t = faces[(2 * n + 2) * 4];
    check(ts_ivcontains(ctr.x, t) && ctr.x.hi - ctr.x.lo < (filter ? 4.f * 4 / 128 + 1e-5f : 1e-5f),
          std::string("textureCube at a face centre is narrow, filter ") + std::to_string(filter), fmt(ctr.x));
    const ts_vec4iv z = ts_textureCubeiv(&c, ts_v3iv(ts_ivrange(-1e-3f, 1e-3f), ts_ivpoint(0.f), ts_ivpoint(0.f)));
    check(z.x.nan && std::isinf(ts_ivwidth_ulp(z.x)), "textureCube of a box around the zero vector: any result");
  }
  check(bad == 0, "textureCube llvmpipe mirror inside (" + std::to_string(trials) + " lookups)", first);
}

// 3D lookups: the 2D rule on three axes, trilinear at the weight box's corners
void check_texture3d(Rng &r) {
  const int w = 5, h = 4, d = 3;
  std::vector<float> tx(static_cast<size_t>(w) * h * d * 4);
  for (float &v : tx) v = r.uniform(-3, 3);
  long bad = 0, trials = 0;
  std::string first;
  for (int wrap = 0; wrap < 2; ++wrap)
    for (int filter = 0; filter < 2; ++filter) {
      const ts_tex3d t = {w, h, d, tx.data(), wrap, wrap, wrap, filter};
      for (int i = 0; i < 20000; ++i) {
        float c0[3];
        for (float &v : c0) v = r.uniform(-1.5f, 2.5f);
        const float dc = i % 2 ? r.uniform(0, 0.2f) : (i % 4 ? 0.f : r.uniform(0, 1e-3f));
        const ts_vec4iv iv = ts_texture3Div(
            &t, ts_v3iv(ts_ivrange(c0[0], c0[0] + dc), ts_ivrange(c0[1], c0[1] + dc), ts_ivrange(c0[2], c0[2] + dc)));
        for (int k = 0; k < 4; ++k) {
          ++trials;
          const ts_vec4f s =
              ts_texture3Df(&t, ts_v3f(r.uniform(c0[0], c0[0] + dc), r.uniform(c0[1], c0[1] + dc), r.uniform(c0[2], c0[2] + dc)));
          if ((!ts_ivcontains(iv.x, s.x) || !ts_ivcontains(iv.y, s.y) || !ts_ivcontains(iv.z, s.z) ||
               !ts_ivcontains(iv.w, s.w)) &&
              bad++ == 0)
            first = "wrap " + std::to_string(wrap) + " filter " + std::to_string(filter) + ": " + fmt(s.x) + " vs " + fmt(iv.x);
        }
      }
    }
  check(bad == 0, "texture3D llvmpipe mirror inside (" + std::to_string(trials) + " lookups)", first);
  const ts_tex3d lin = {w, h, d, tx.data(), TS_WRAP_CLAMP, TS_WRAP_CLAMP, TS_WRAP_CLAMP, TS_FILTER_LINEAR};
  const ts_vec4iv c = ts_texture3Div(&lin, ts_v3iv(ts_ivpoint(2.5f / w), ts_ivpoint(1.5f / h), ts_ivpoint(1.5f / d)));
  const float t211 = tx[((1 * h + 1) * w + 2) * 4];
  check(ts_ivcontains(c.x, t211) && c.x.hi - c.x.lo < 6.f * 6 / 128 + 1e-5f,
        "texture3D at a texel centre: the texel, +-2^-7 of its neighbours' differences", fmt(c.x));
}

// mix() in the other forms (ts_ivlerp_forms, ALT_LERP in ts_generic.h): llvmpipe's x + (y - x) t as
// the interval, then x (1 - t) + y t and (fused) fmaf(y - x, t, x) computed in float32 (FTZ, as
// set by ts_math_init) must lie inside; so must the saturation case the browser found (a dim
// channel next to a bright luma). The widening stays within 8 ULP of the largest magnitude.
void check_lerp_forms(Rng &r) {
  long bad = 0, wide = 0, n = 0;
  std::string first, first_w;
  for (int i = 0; i < 200000; ++i) {
    const float scale = std::ldexp(1.0f, static_cast<int>(r.next() % 40) - 20);
    const float x = r.uniform(-1.f, 1.f) * scale, y = r.uniform(-1.f, 1.f) * scale * (i % 3 ? 1.f : 0.01f);
    const float t = i % 5 ? r.uniform(-0.5f, 1.5f) : (i % 2 ? 0.f : 1.f);
    const ts_iv X = ts_ivpoint(x), Y = ts_ivpoint(y), T = ts_ivpoint(t);
    const ts_iv a = ts_addiv(X, ts_muliv(ts_subiv(Y, X), T));
    const ts_iv w = ts_ivlerp_forms(a, X, Y, T);
    volatile float omt = 1.0f - t;
    volatile float f1 = x * omt;
    volatile float f2 = y * t;
    const float spec_form = f1 + f2;
    const float fused = std::fmaf(y - x, t, x);
    ++n;
    if (!ts_ivcontains(w, spec_form) || !ts_ivcontains(w, fused) || !ts_ivcontains(w, x + (y - x) * t)) {
      if (!bad++) first = "x " + std::to_string(x) + " y " + std::to_string(y) + " t " + std::to_string(t) + " " + fmt(w);
    }
    const double big = std::max(std::fabs(x), std::fabs(y)) * (1.0 + std::fabs(t));
    if ((double)w.hi - (double)w.lo > 16.0 * std::ldexp(big, -23) + 1e-37) {
      if (!wide++) first_w = fmt(w);
    }
  }
  check(bad == 0, "lerp forms: x (1 - t) + y t, fused and llvmpipe's inside (" + std::to_string(n) + " cases)", first);
  check(wide == 0, "lerp forms: widening within 8 ULP of the largest term at each end", first_w);
  // the browser's case: saturation 1 of a green channel 15x dimmer than the luma
  const float luma = 0.5f, s = 0.5f / 15.0f, sat = 1.0f;
  const ts_iv a = ts_addiv(ts_muliv(ts_ivpoint(luma), ts_subiv(ts_ivpoint(1.f), ts_ivpoint(sat))),
                           ts_muliv(ts_ivpoint(s), ts_ivpoint(sat)));
  const float swiftshader = luma + (s - luma) * sat;
  check(!ts_ivcontains(a, swiftshader) || swiftshader == s, "lerp forms: the dim-channel case differs between forms",
        fmt(a));
  check(ts_ivcontains(ts_ivlerp_forms(a, ts_ivpoint(luma), ts_ivpoint(s), ts_ivpoint(sat)), swiftshader),
        "lerp forms: luma + (s - luma) t inside the widened saturation", fmt(a));
}

// the helpers the twins' generic source uses: floor, ==, !=, ||, &&, int(), neg3/max3
void check_helpers() {
  const ts_iv f = ts_flooriv(ts_ivrange(-1.5f, 2.5f));
  check(f.lo == -2 && f.hi == 2 && !f.nan, "floor of an interval", fmt(f));
  check(ts_eqiv(ts_ivpoint(1.f), ts_ivpoint(1.f)) == TS_IV_TRUE && ts_neiv(ts_ivpoint(1.f), ts_ivpoint(2.f)) == TS_IV_TRUE &&
            ts_eqiv(ts_ivrange(0, 2), ts_ivpoint(1.f)) == TS_IV_EITHER && ts_neiv(ts_ivpoint(NAN), ts_ivpoint(0)) == TS_IV_EITHER,
        "== and != are true, false or either");
  check(ts_oriv(TS_IV_FALSE, TS_IV_EITHER) == TS_IV_EITHER && ts_oriv(TS_IV_EITHER, TS_IV_TRUE) == TS_IV_TRUE &&
            ts_andiv(TS_IV_EITHER, TS_IV_FALSE) == TS_IV_FALSE && ts_andiv(TS_IV_TRUE, TS_IV_TRUE) == TS_IV_TRUE,
        "|| and && of outcomes");
  check(ts_ivtoint(ts_ivpoint(3.7f)) == 3 && ts_ivtoint(ts_ivrange(2.5f, 3.5f)) == TS_IV_UNSURE_INT &&
            ts_ivtoint(ts_ivany()) == TS_IV_UNSURE_INT,
        "int() of a point truncates; of a range over two ints, unsure");
  const ts_vec3iv m = ts_max3iv(ts_v3iv(ts_ivpoint(1), ts_ivrange(-1, 1), ts_ivpoint(0)), ts_neg3iv(ts_v3iv(ts_ivpoint(-2), ts_ivpoint(0), ts_ivpoint(1))));
  check(m.x.lo == 2 && m.y.lo == 0 && m.y.hi == 1 && m.z.lo == 0 && m.z.hi == 0, "max3 and neg3", fmt(m.y));
}

// mediump (ts_iv_set_mediump): every result a GLES implementation may give at mediump lies inside.
// Evaluated two ways on random inputs in (-2^14, 2^14) with random exponents: fp16 (_Float16: the
// inputs converted, + - * / correctly rounded in fp16, exp2 log2 inversesqrt pow in float32 then
// rounded to fp16, as llvmpipe's f2f16 code runs them) and float32 (SwiftShader computes mediump at
// fp32). Widths: * / within 2^-5 of the result where it is normal, + within 2^-5 of the larger operand (the two inputs and the
// result each rounded outward on a grid of 2^-9 relative: at most 16 of its ULPs), so the rules are
// not "anything" (a divisor past 2^12 gives any result: the CTS range rule). Then highp again.
void check_mediump(Rng &r) {
  ts_iv_set_mediump(1);
  auto rnd = [&]() {
    const float m = r.uniform(1.f, 2.f) * ((r.next() & 1) ? 1.f : -1.f);
    return std::ldexp(m, static_cast<int>(r.next() % 26) - 13);  // |x| in [2^-13, 2^13]
  };
  auto h = [](float x) { return static_cast<float>(static_cast<_Float16>(x)); };
  long bad16 = 0, bad32 = 0, wide = 0, n = 0;
  std::string first16, first32, firstw;
  struct Op {
    const char *name;
    std::function<ts_iv(ts_iv, ts_iv)> iv;
    std::function<float(float, float)> f;
    bool native16, unary, positive;
  } ops[] = {
      {"add", ts_addiv, [](float a, float b) { return a + b; }, true, false, false},
      {"mul", ts_muliv, [](float a, float b) { return a * b; }, true, false, false},
      {"div", ts_diviv, [](float a, float b) { return a / b; }, true, false, false},
      {"exp2", [](ts_iv a, ts_iv) { return ts_exp2iv(a); }, [](float a, float) { return std::exp2(a); }, false, true, false},
      {"log2", [](ts_iv a, ts_iv) { return ts_log2iv(a); }, [](float a, float) { return std::log2(a); }, false, true, true},
      {"inversesqrt", [](ts_iv a, ts_iv) { return ts_inversesqrtiv(a); }, [](float a, float) { return 1.f / std::sqrt(a); },
       false, true, true},
      {"pow", ts_powiv, [](float a, float b) { return std::pow(a, b); }, false, false, true},
  };
  for (const Op &op : ops)
    for (int i = 0; i < 20000; ++i) {
      float a = rnd(), b = rnd();
      if (op.positive) a = std::fabs(a);
      if (std::string(op.name) == "exp2") a = std::fmod(a, 13.f);
      if (std::string(op.name) == "pow") b = std::fmod(b, 4.f);
      const ts_iv v = op.iv(ts_ivpoint(a), ts_ivpoint(b));
      const float a16 = h(a), b16 = h(b);
      // fp16: the native operation (correctly rounded: exact in float32, then rounded) or float32 then rounded
      const float r16 = h(op.f(a16, b16)), r32 = op.f(a, b);
      ++n;
      if (!ts_ivcontains(v, r16) && !(std::isinf(r16) && v.hi >= 65504.f) && !v.nan) {
        if (!bad16++) first16 = std::string(op.name) + "(" + std::to_string(a) + ", " + std::to_string(b) + ") fp16 " +
                               std::to_string(r16) + " outside " + fmt(v);
      }
      if (!ts_ivcontains(v, r32) && !v.nan) {
        if (!bad32++) first32 = std::string(op.name) + "(" + std::to_string(a) + ", " + std::to_string(b) + ") f32 " +
                               std::to_string(r32) + " outside " + fmt(v);
      }
      if (op.native16 && !v.nan && std::isfinite(r32) && std::fabs(r32) >= 0x1p-12f && std::fabs(r32) <= 0x1p12f &&
          (double)v.hi - v.lo > 0x1p-5 * (std::string(op.name) == "add" ? std::fmax(std::fabs(a), std::fabs(b)) : std::fabs(r32))) {
        if (!wide++) firstw = std::string(op.name) + " " + fmt(v) + " around " + std::to_string(r32);
      }
    }
  check(bad16 == 0, "mediump: fp16 results inside (" + std::to_string(n) + " operations)", first16);
  check(bad32 == 0, "mediump: float32 results inside (an implementation may compute mediump at highp)", first32);
  check(wide == 0, "mediump: + * / within 2^-5 relative (both inputs and the result rounded outward to the 9-bit grid)", firstw);
  const ts_iv big = ts_muliv(ts_ivpoint(300.f), ts_ivpoint(300.f));
  check(big.hi == INFINITY && big.lo == 16368.f, "mediump: a product past 2^14 admits the format's largest value (2 - 2^-9) 2^13 and Inf", fmt(big));
  const ts_iv in = ts_ivpoint(1.0001f);
  check(ts_ivcontains(in, 1.f) && !ts_ivcontains(in, 1.005f), "mediump: an input is rounded to the 9-bit grid", fmt(in));
  ts_iv_set_mediump(0);
  const ts_iv back = ts_ivpoint(1.0001f);
  check(back.lo == 1.0001f && back.hi == 1.0001f && !ts_iv_mediump(), "highp again after mediump", fmt(back));
}

// the checks above can fail: a value one ULP past an end is outside, and its excess says so
void check_checker() {
  const ts_iv a = ts_addiv(ts_ivpoint(1.f), ts_ivpoint(0x1p-30f));
  check(!ts_ivcontains(a, nextafterf(a.hi, INFINITY)) && ts_ivexcess_ulp(a, nextafterf(a.hi, INFINITY)) == 1 &&
            ts_ivexcess_ulp(a, a.lo) == 0,
        "containment and excess are strict at the ends", fmt(a));
  check(std::isinf(ts_ivwidth_ulp(ts_ivany())) && ts_ivwidth_ulp(ts_ivpoint(3.f)) == 0, "widths: any is infinite, a point 0");
}

}  // namespace

int main() {
  ts_math_init();  // FTZ/DAZ like llvmpipe; the fused-mad choice as the driver makes it
  Rng r;
  check_binary(r);
  check_builtins(r);
  check_dot(r);
  check_texture(r);
  check_cube(r);
  check_texture3d(r);
  check_helpers();
  check_lerp_forms(r);
  check_mediump(r);
  check_checker();
  return unit_check::finish();
}

// tiershade tests: unit tests for c_ref/offline/light_folding.{h,c}: folding lights beyond a tier's limit
// into the ambient cube (docs/light_folding.md).  Shading is computed by the real
// C twin model_lighting_f (ps2b/ps20, OUTPUT_MODE 0 linear, tone-map scale 1,
// constant albedo 1) and integrated over the unit sphere of normals with a
// Fibonacci sphere.  Prints "PASS name" / "FAIL name: detail" per check and
// "INFO ..." lines with the measured numbers; exits 1 if any check failed.
//
// Covered: the constants 2pi/3 (cube face), pi (Lambert), 4pi/3 (half-Lambert)
// and k = 3/2, 2; per-channel sphere-integral conservation for directional,
// point and spot lights (axis-aligned and diagonal directions); non-negativity,
// which faces gain, hue per face; the pointwise value k I sum(L_j^4) at N = L;
// the first moment (dominant direction); end-to-end folding of 6 lights on
// ps2b and sm3 (keep 4) and ps20 (keep 2); selection order, ties, n == 0, max_local >= n,
// invalid lights; ts_light_pack validation and layout; ts_light_incident
// against model_lighting_d.
// Build: make build/tests/test_light_folding
#include "offline/light_folding.h"
#include "twins/model_lighting.h"
#include "unit_check.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

const double kPi = 3.14159265358979323846;
const int kSpherePoints = 40000;  // Fibonacci sphere size (>= 20000)
const float kCenter[3] = {0.5f, -1.25f, 2.0f};

std::string fmt(const char *f, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

void info(const std::string &s) { std::printf("INFO %s\n", s.c_str()); }

double rel_diff(double a, double b) {
  double den = std::fmax(std::fabs(a), std::fabs(b));
  return den == 0.0 ? 0.0 : std::fabs(a - b) / den;
}

struct V3 {
  double x, y, z;
};
V3 norm(V3 v) {
  double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / l, v.y / l, v.z / l};
}
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double comp(V3 v, int j) { return j == 0 ? v.x : (j == 1 ? v.y : v.z); }
double angle_deg(V3 a, V3 b) {
  double c = dot(norm(a), norm(b));
  c = c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c);
  return std::acos(c) * 180.0 / kPi;
}

// ---- shading set-up ----------------------------------------------------------

const float kDummyTexel[4] = {1.0f, 1.0f, 1.0f, 1.0f};
const ts_tex2d kDummyAlbedoTex = ts_tex2d_single(1, 1, kDummyTexel, TS_WRAP_REPEAT, TS_WRAP_REPEAT, TS_FILTER_NEAREST);
const ml_textures kDummyAlbedo = {&kDummyAlbedoTex, nullptr, nullptr, nullptr, nullptr, nullptr, 0};

ml_variant variant(int tier, int half_lambert, int num_lights) {
  ml_variant v = {};
  v.tier = tier;
  v.albedo_texture = 0;
  v.half_lambert = half_lambert;
  v.output_mode = 0;
  v.num_lights = num_lights;
  return v;
}

// A record at position kCenter with the given cube (may be null = black), tone-map
// scale 1, albedo 1 and no lights.
struct Record {
  ts_vec4f rec[ML_SLOTS];
  explicit Record(const float cube[6][3] = nullptr) {
    std::memset(rec, 0, sizeof rec);
    rec[ML_SLOT_POSITION] = {kCenter[0], kCenter[1], kCenter[2], 1.0f};
    for (int f = 0; f < 6; ++f)
      rec[ML_SLOT_AMBIENT + f] = cube ? ts_vec4f{cube[f][0], cube[f][1], cube[f][2], 0.0f} : ts_vec4f{0, 0, 0, 0};
    rec[ML_SLOT_PARAMS] = {1.0f, 0.0f, 0.0f, 0.0f};
    rec[ML_SLOT_ALBEDO] = {1.0f, 1.0f, 1.0f, 1.0f};
  }
  void set_light(int i, const float pk[5][4]) {
    for (int s = 0; s < 5; ++s) rec[ML_SLOT_LIGHT0 + 5 * i + s] = {pk[s][0], pk[s][1], pk[s][2], pk[s][3]};
  }
  bool add_light(int i, const ts_light &l) {
    float pk[5][4];
    char err[256];
    if (!ts_light_pack(&l, pk, err, sizeof err)) {
      check(false, "pack_for_record", err);
      return false;
    }
    set_light(i, pk);
    // ps20 takes each light's attenuation (distance x cone) from the vertex shader,
    // interpolated; every vertex here sits at the shading point, so it is the
    // attenuation at kCenter (ignored by ps2b and sm3).
    ts_light unit = l;
    unit.color[0] = unit.color[1] = unit.color[2] = 1.0f;
    double att[3], L[3];
    ts_light_incident(&unit, kCenter, att, L);
    float *va = &rec[ML_SLOT_VERTEX_ATTEN].x;
    if (i < 4) va[i] = (float)att[0];
    return true;
  }
};

struct Sphere {
  std::vector<V3> n;
  explicit Sphere(int count) {
    // Fibonacci sphere: z uniform in (-1, 1) (equal-area bands), golden-angle longitudes.
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    n.reserve(count);
    for (int i = 0; i < count; ++i) {
      double z = 1.0 - (2.0 * i + 1.0) / count;
      double r = std::sqrt(1.0 - z * z);
      double phi = golden * i;
      n.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
  }
};
const Sphere &sphere() {
  static Sphere s(kSpherePoints);
  return s;
}

struct Integral {
  double rgb[3] = {0, 0, 0};  // integral of each channel over the sphere of normals
  V3 moment = {0, 0, 0};  // first moment of the luminance: integral of lum(N) N
  bool negative = false;  // some shaded value < 0
};

ts_vec4f shade(const ml_variant &v, Record &r, V3 n) {
  r.rec[ML_SLOT_NORMAL] = {(float)n.x, (float)n.y, (float)n.z, 0.0f};
  return model_lighting_f(&v, r.rec, &kDummyAlbedo);
}

Integral integrate(const ml_variant &v, Record r) {
  Integral out;
  const double w = 4.0 * kPi / (double)sphere().n.size();
  for (const V3 &n : sphere().n) {
    ts_vec4f c = shade(v, r, n);
    double ch[3] = {c.x, c.y, c.z};
    for (int k = 0; k < 3; ++k) {
      out.rgb[k] += w * ch[k];
      if (ch[k] < 0.0) out.negative = true;
    }
    double lum = 0.2126 * ch[0] + 0.7152 * ch[1] + 0.0722 * ch[2];
    out.moment.x += w * lum * n.x;
    out.moment.y += w * lum * n.y;
    out.moment.z += w * lum * n.z;
  }
  return out;
}

// ---- lights -------------------------------------------------------------------

ts_light make_light(ts_light_type t) {
  ts_light l;
  std::memset(&l, 0, sizeof l);
  l.type = t;
  return l;
}

// Light of the given type whose direction towards it from kCenter is L.
ts_light light_towards(ts_light_type t, V3 L, const float color[3]) {
  ts_light l = make_light(t);
  for (int c = 0; c < 3; ++c) l.color[c] = color[c];
  const double dist = 3.0;
  if (t == TS_LIGHT_DIRECTIONAL) {
    l.dir[0] = (float)-L.x;
    l.dir[1] = (float)-L.y;
    l.dir[2] = (float)-L.z;
    return l;
  }
  l.pos[0] = (float)(kCenter[0] + dist * L.x);
  l.pos[1] = (float)(kCenter[1] + dist * L.y);
  l.pos[2] = (float)(kCenter[2] + dist * L.z);
  l.atten[0] = 1.0f;
  l.atten[1] = 0.2f;
  l.atten[2] = 0.05f;
  if (t == TS_LIGHT_SPOT) {
    // axis tilted away from the centre so the cone factor is fractional there
    V3 helper = std::fabs(L.x) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
    V3 perp = norm({L.y * helper.z - L.z * helper.y, L.z * helper.x - L.x * helper.z, L.x * helper.y - L.y * helper.x});
    V3 axis = norm({-L.x + 0.4 * perp.x, -L.y + 0.4 * perp.y, -L.z + 0.4 * perp.z});
    l.dir[0] = (float)axis.x;
    l.dir[1] = (float)axis.y;
    l.dir[2] = (float)axis.z;
    l.spot_exponent = 1.5f;
    l.cos_inner = 0.99f;
    l.cos_outer = 0.8f;
  }
  return l;
}

const char *type_str(ts_light_type t) {
  return t == TS_LIGHT_POINT ? "point" : (t == TS_LIGHT_SPOT ? "spot" : "directional");
}

std::vector<V3> test_directions() {
  return {{1, 0, 0},
          {0, -1, 0},
          {0, 0, 1},
          {-1, 0, 0},
          norm({1, 1, 1}),
          norm({-1, 1, -1}),
          norm({1, 1, 0}),
          norm({0.3, -0.5, 0.81}),
          norm({-0.2, 0.9, -0.4}),
          // the direction where the folded first moment turns furthest from L (16.7 deg)
          norm({0.34793, 0.34793, 0.87057})};
}

// ---- checks -----------------------------------------------------------------

// The three sphere integrals the fold constant rests on, measured with the twin.
void check_constants() {
  const double face_want = 2.0 * kPi / 3.0;
  double worst = 0.0;
  for (int f = 0; f < 6; ++f) {
    float cube[6][3] = {};
    cube[f][0] = cube[f][1] = cube[f][2] = 1.0f;
    Integral I = integrate(variant(TS_TIER_ID_PS2B, 0, 0), Record(cube));
    double e = rel_diff(I.rgb[1], face_want);
    worst = std::fmax(worst, e);
    check(e < 1e-4, fmt("constant_cube_face_%d_is_2pi/3", f), fmt("got %.8f want %.8f", I.rgb[1], face_want));
  }
  info(fmt("cube face integral: max rel error vs 2pi/3 = %.2e (%d points)", worst, kSpherePoints));

  const float white[3] = {1, 1, 1};
  for (int hl = 0; hl <= 1; ++hl) {
    const double want = hl ? 4.0 * kPi / 3.0 : kPi;
    const double k_want = hl ? 2.0 : 1.5;
    double worst_l = 0.0, worst_k = 0.0;
    for (V3 L : test_directions()) {
      Record r;
      if (!r.add_light(0, light_towards(TS_LIGHT_DIRECTIONAL, L, white))) return;
      Integral I = integrate(variant(TS_TIER_ID_PS2B, hl, 1), r);
      worst_l = std::fmax(worst_l, rel_diff(I.rgb[1], want));
      worst_k = std::fmax(worst_k, rel_diff(I.rgb[1] / face_want, k_want));
    }
    check(worst_l < 1e-4, fmt("constant_%s", hl ? "half_lambert_integral_is_4pi/3" : "lambert_integral_is_pi"),
          fmt("max rel error %.3e", worst_l));
    check(worst_k < 1e-4, fmt("constant_k_%s", hl ? "half_lambert_is_2" : "lambert_is_3/2"),
          fmt("max rel error %.3e", worst_k));
    info(fmt("%s light integral: max rel error vs %s = %.2e; measured k = light / (2pi/3) within %.2e of %.1f",
             hl ? "half-Lambert" : "Lambert", hl ? "4pi/3" : "pi", worst_l, worst_k, k_want));

    // ts_fold_lights applies exactly that k: a unit light towards +X adds k to +X only.
    float cube[6][3] = {};
    ts_light l = light_towards(TS_LIGHT_DIRECTIONAL, {1, 0, 0}, white);
    int n = ts_fold_lights(&l, 1, 0, kCenter, hl, cube, nullptr);
    bool ok = n == 0 && std::fabs(cube[0][1] - k_want) < 1e-6;
    for (int f = 1; f < 6; ++f) ok = ok && cube[f][1] == 0.0f;
    check(ok, fmt("fold_applies_k_%s", hl ? "half_lambert" : "lambert"),
          fmt("+X face %.9g, want %.1f; returned %d", cube[0][1], k_want, n));
  }
}

// Sphere integral per channel: light local vs folded, for all types, both
// diffuse models and all test directions; plus the face/hue/sign/pointwise/moment checks.
void check_conservation() {
  const float color[3] = {2.0f, 1.0f, 0.25f};
  const ts_light_type types[3] = {TS_LIGHT_DIRECTIONAL, TS_LIGHT_POINT, TS_LIGHT_SPOT};
  for (int hl = 0; hl <= 1; ++hl) {
    const double k = hl ? 2.0 : 1.5;
    for (ts_light_type t : types) {
      double worst = 0.0, worst_moment_angle = 0.0, worst_moment_model = 0.0;
      double peak_lo = 1e30, peak_hi = 0.0, worst_ptwise = 0.0, worst_mag = 0.0;
      bool faces_ok = true, hue_ok = true, nonneg_ok = true, peak_ok = true, octant_ok = true;
      std::string faces_msg, hue_msg, peak_msg, octant_msg;
      int di = 0;
      for (V3 L : test_directions()) {
        ++di;
        ts_light l = light_towards(t, L, color);
        Record local;
        if (!local.add_light(0, l)) return;
        Integral A = integrate(variant(TS_TIER_ID_PS2B, hl, 1), local);

        float cube[6][3] = {};
        int nk = ts_fold_lights(&l, 1, 0, kCenter, hl, cube, nullptr);
        if (nk != 0) check(false, "fold_single_returns_0", fmt("returned %d", nk));
        Record folded(cube);
        Integral B = integrate(variant(TS_TIER_ID_PS2B, hl, 0), folded);

        for (int c = 0; c < 3; ++c) {
          double e = rel_diff(A.rgb[c], B.rgb[c]);
          worst = std::fmax(worst, e);
          if (e >= 1e-3)
            check(false, fmt("conserve_%s_%s_dir%d_ch%d", hl ? "half_lambert" : "lambert", type_str(t), di, c),
                  fmt("local %.8g folded %.8g rel %.3e", A.rgb[c], B.rgb[c], e));
        }

        // faces: only those whose axis points towards the light gain; nothing negative; hue per face
        double I[3], Ld[3];
        ts_light_incident(&l, kCenter, I, Ld);
        for (int f = 0; f < 6; ++f) {
          int j = f / 2;
          double s = (f % 2 == 0) ? 1.0 : -1.0;
          double facing = s * Ld[j];
          for (int c = 0; c < 3; ++c) {
            if (cube[f][c] < 0.0f) nonneg_ok = false;
            bool gains = cube[f][c] > 0.0f;
            if (gains != (facing > 1e-7)) {
              faces_ok = false;
              faces_msg = fmt("dir%d face %d ch%d = %g, axis.L = %g", di, f, c, cube[f][c], facing);
            }
          }
          if (cube[f][1] > 0.0f) {
            double r0 = cube[f][0] / cube[f][1], r2 = cube[f][2] / cube[f][1];
            if (rel_diff(r0, color[0] / color[1]) > 1e-6 || rel_diff(r2, color[2] / color[1]) > 1e-6) {
              hue_ok = false;
              hue_msg = fmt("dir%d face %d ratios %g %g", di, f, r0, r2);
            }
          }
        }
        if (A.negative || B.negative) nonneg_ok = false;

        // pointwise: at N = L the folded cube gives k I sum(L_j^4), not I (Lambert) / I (half-Lambert)
        V3 Lv = {Ld[0], Ld[1], Ld[2]};
        ts_vec4f at_L = shade(variant(TS_TIER_ID_PS2B, hl, 0), folded, Lv);
        ts_vec4f at_L_local = shade(variant(TS_TIER_ID_PS2B, hl, 1), local, Lv);
        double s4 = Ld[0] * Ld[0] * Ld[0] * Ld[0] + Ld[1] * Ld[1] * Ld[1] * Ld[1] + Ld[2] * Ld[2] * Ld[2] * Ld[2];
        double want_peak = k * I[1] * s4;
        if (rel_diff(at_L.y, want_peak) > 1e-5) {
          peak_ok = false;
          peak_msg = fmt("dir%d folded(N=L) %.8g want k I sum L^4 = %.8g", di, at_L.y, want_peak);
        }
        peak_lo = std::fmin(peak_lo, at_L.y / at_L_local.y);
        peak_hi = std::fmax(peak_hi, at_L.y / at_L_local.y);
        // max pointwise difference over the sphere, relative to the local peak
        {
          Record a = local, b = folded;
          double m = 0.0;
          for (size_t i = 0; i < sphere().n.size(); i += 7) {
            double da = shade(variant(TS_TIER_ID_PS2B, hl, 1), a, sphere().n[i]).y;
            double db = shade(variant(TS_TIER_ID_PS2B, hl, 0), b, sphere().n[i]).y;
            m = std::fmax(m, std::fabs(da - db));
          }
          worst_ptwise = std::fmax(worst_ptwise, m / at_L_local.y);
        }

        // first moment (dominant direction): local is along L; folded along (L_j |L_j|)
        // magnitudes: local (2pi/3) lum(I) L for both diffuse models; folded
        // (pi/2) k lum(I) (L_j |L_j|) (docs/light_folding.md, "What is not conserved")
        V3 model = {Ld[0] * std::fabs(Ld[0]), Ld[1] * std::fabs(Ld[1]), Ld[2] * std::fabs(Ld[2])};
        double lumI = 0.2126 * I[0] + 0.7152 * I[1] + 0.0722 * I[2];
        double mag_a = 2.0 * kPi / 3.0 * lumI, mag_b = kPi / 2.0 * k * lumI * std::sqrt(dot(model, model));
        worst_mag = std::fmax(worst_mag, rel_diff(std::sqrt(dot(A.moment, A.moment)), mag_a));
        worst_mag = std::fmax(worst_mag, rel_diff(std::sqrt(dot(B.moment, B.moment)), mag_b));
        double ang = angle_deg(A.moment, B.moment);
        worst_moment_angle = std::fmax(worst_moment_angle, ang);
        worst_moment_model = std::fmax(worst_moment_model, angle_deg(B.moment, model));
        for (int j = 0; j < 3; ++j) {
          double a = comp(A.moment, j), b = comp(B.moment, j);
          double scale = std::sqrt(dot(A.moment, A.moment));
          if (std::fabs(a) > 1e-3 * scale && (a > 0) != (b > 0)) {
            octant_ok = false;
            octant_msg = fmt("dir%d axis %d: local %g folded %g", di, j, a, b);
          }
        }
      }
      std::string tag = fmt("%s_%s", hl ? "half_lambert" : "lambert", type_str(t));
      check(worst < 1e-3, "conserve_integral_per_channel_" + tag, fmt("max rel %.3e", worst));
      check(faces_ok, "faces_facing_light_gain_" + tag, faces_msg);
      check(nonneg_ok, "nothing_negative_" + tag, "a face or a shaded value is negative");
      check(hue_ok, "hue_per_face_" + tag, hue_msg);
      check(peak_ok, "pointwise_at_N_eq_L_is_k_I_sumL4_" + tag, peak_msg);
      check(octant_ok, "first_moment_same_octant_" + tag, octant_msg);
      check(worst_moment_model < 0.5, "first_moment_along_Lj_absLj_" + tag,
            fmt("angle to (L_j|L_j|) %.3f deg", worst_moment_model));
      check(worst_mag < 1e-3, "first_moment_magnitudes_as_derived_" + tag, fmt("max rel %.3e", worst_mag));
      info(
          fmt("%-25s sphere integral max rel err %.2e over %zu directions x 3 channels; "
              "folded/local at N=L in [%.3f, %.3f]; max |local-folded| = %.2f x local peak; "
              "first-moment angle up to %.2f deg",
              tag.c_str(), worst, test_directions().size(), peak_lo, peak_hi, worst_ptwise, worst_moment_angle));
    }
  }
}

// Folding adds to what is in the cube.
void check_additive() {
  const float color[3] = {0.5f, 0.75f, 1.0f};
  float base[6][3];
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) base[f][c] = 0.1f * (float)(f + 1) + 0.01f * (float)c;
  float cube[6][3], delta[6][3] = {};
  std::memcpy(cube, base, sizeof cube);
  ts_light l = light_towards(TS_LIGHT_POINT, norm({0.2, -0.7, 0.4}), color);
  ts_fold_lights(&l, 1, 0, kCenter, 1, cube, nullptr);
  ts_fold_lights(&l, 1, 0, kCenter, 1, delta, nullptr);
  double worst = 0.0;
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c)
      worst = std::fmax(worst, std::fabs((double)cube[f][c] - ((double)base[f][c] + delta[f][c])));
  check(worst < 1e-6, "fold_adds_to_existing_cube", fmt("max deviation %g", worst));
}

// Six lights: keep the tier's limit, fold the rest; the integral of the total
// shading matches all six lights shaded locally (two records summed).
void check_end_to_end() {
  std::vector<ts_light> ls;
  const float c0[3] = {1.0f, 0.9f, 0.8f}, c1[3] = {0.2f, 0.4f, 1.0f}, c2[3] = {3.0f, 0.5f, 0.5f};
  ls.push_back(light_towards(TS_LIGHT_POINT, norm({1, 0.2, 0.1}), c0));
  ls.push_back(light_towards(TS_LIGHT_DIRECTIONAL, norm({-0.3, 1, 0.2}), c1));
  ls.push_back(light_towards(TS_LIGHT_SPOT, norm({0.1, -0.2, 1}), c2));
  ls.push_back(light_towards(TS_LIGHT_POINT, norm({-1, -1, 0.5}), c1));
  ls.push_back(light_towards(TS_LIGHT_DIRECTIONAL, norm({0.5, -1, -1}), c0));
  ls.push_back(light_towards(TS_LIGHT_POINT, norm({0, 0.3, -1}), c2));
  float ambient[6][3];
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) ambient[f][c] = 0.05f + 0.02f * (float)f;

  struct Case {
    int tier, max_local;
    const char *name;
  } cases[3] = {
      {TS_TIER_ID_PS2B, 4, "ps2b_keep4"}, {TS_TIER_ID_PS20, 2, "ps20_keep2"}, {TS_TIER_ID_SM3, 4, "sm3_keep4"}};
  for (const Case &cs : cases) {
    for (int hl = 0; hl <= 1; ++hl) {
      // reference: every light local (4 + 2 in two records), ambient once
      Record r1(ambient), r2;
      for (int i = 0; i < 4; ++i) r1.add_light(i, ls[i]);
      for (int i = 4; i < 6; ++i) r2.add_light(i - 4, ls[i]);
      Integral a1 = integrate(variant(TS_TIER_ID_PS2B, hl, 4), r1);
      Integral a2 = integrate(variant(TS_TIER_ID_PS2B, hl, 2), r2);

      float cube[6][3];
      std::memcpy(cube, ambient, sizeof cube);
      int kept[6] = {-1, -1, -1, -1, -1, -1};
      int nk = ts_fold_lights(ls.data(), (int)ls.size(), cs.max_local, kCenter, hl, cube, kept);
      Record rf(cube);
      for (int i = 0; i < nk; ++i) rf.add_light(i, ls[kept[i]]);
      rf.rec[ML_SLOT_PARAMS].y = (float)nk;  // sm3's light count (ignored by ps20, ps2b)
      Integral b = integrate(variant(cs.tier, hl, nk), rf);
      double worst = 0.0;
      for (int c = 0; c < 3; ++c) worst = std::fmax(worst, rel_diff(a1.rgb[c] + a2.rgb[c], b.rgb[c]));
      std::string tag = fmt("%s_%s", cs.name, hl ? "half_lambert" : "lambert");
      check(nk == cs.max_local, "end_to_end_kept_count_" + tag, fmt("kept %d", nk));
      check(worst < 1e-3, "end_to_end_conserve_" + tag, fmt("max rel %.3e", worst));
      info(fmt("end-to-end 6 lights, %s: sphere integral max rel err %.2e", tag.c_str(), worst));
    }
  }
}

void check_selection() {
  // Six point/spot/directional lights whose order at the centre differs from
  // their colour order (a bright far light, a spot facing away).
  const float white[3] = {1, 1, 1};
  std::vector<ts_light> ls;
  auto point_at = [&](double dist, float intensity, V3 d) {
    ts_light l = make_light(TS_LIGHT_POINT);
    for (int c = 0; c < 3; ++c) l.color[c] = intensity;
    l.pos[0] = (float)(kCenter[0] + dist * d.x);
    l.pos[1] = (float)(kCenter[1] + dist * d.y);
    l.pos[2] = (float)(kCenter[2] + dist * d.z);
    l.atten[2] = 1.0f;  // inverse square
    return l;
  };
  ls.push_back(point_at(10.0, 50.0f, {1, 0, 0}));  // 0: 0.5 at centre
  ls.push_back(point_at(1.0, 2.0f, {0, 1, 0}));  // 1: 2.0  (brightest)
  ts_light sp = light_towards(TS_LIGHT_SPOT, {0, 0, 1}, white);
  sp.color[0] = sp.color[1] = sp.color[2] = 1000.0f;
  sp.dir[0] = 0;
  sp.dir[1] = 0;
  sp.dir[2] = 1;  // pointing away from the centre: cone factor pow(1e-4, 1.5) = 1e-6
  ls.push_back(sp);  // 2: ~5e-4
  ls.push_back(point_at(2.0, 4.0f, {0, 0, -1}));  // 3: 1.0
  ts_light dl = light_towards(TS_LIGHT_DIRECTIONAL, norm({1, 1, 1}), white);
  dl.color[0] = 0.0f;
  dl.color[1] = 1.5f;
  dl.color[2] = 0.0f;  // 4: lum 0.7152*1.5 = 1.0728
  ls.push_back(dl);
  ls.push_back(point_at(3.0, 9.0f, {-1, 0, 0}));  // 5: 1.0 (ties with 3)

  double lum[6];
  for (int i = 0; i < 6; ++i) {
    double I[3], L[3];
    ts_light_incident(&ls[i], kCenter, I, L);
    lum[i] = 0.2126 * I[0] + 0.7152 * I[1] + 0.0722 * I[2];
  }
  info(fmt("selection luminances at centre: %.4g %.4g %.4g %.4g %.4g %.4g", lum[0], lum[1], lum[2], lum[3], lum[4],
           lum[5]));

  auto run = [&](int max_local, std::vector<int> want, const std::string &name) {
    float cube[6][3] = {};
    int kept[8];
    for (int &k : kept) k = -7;
    int n = ts_fold_lights(ls.data(), (int)ls.size(), max_local, kCenter, 0, cube, kept);
    bool ok = n == (int)want.size();
    std::string got;
    for (int i = 0; i < n && i < 8; ++i) {
      got += fmt("%d ", kept[i]);
      if (ok && kept[i] != want[i]) ok = false;
    }
    check(ok, name, "kept " + got);
    return std::vector<int>(kept, kept + (n < 8 ? n : 8));
  };
  run(2, {1, 4}, "select_2_brightest_of_6");
  run(3, {1, 3, 4}, "select_3_tie_lower_index_wins");  // 3 and 5 tie at 1.0: index 3 wins
  run(4, {1, 3, 4, 5}, "select_4_in_original_order");
  run(6, {0, 1, 2, 3, 4, 5}, "select_max_local_eq_n_keeps_all");
  run(10, {0, 1, 2, 3, 4, 5}, "select_max_local_gt_n_keeps_all");
  run(0, {}, "select_max_local_0_keeps_none");
  run(-3, {}, "select_max_local_negative_keeps_none");

  // the tie really is a tie
  check(lum[3] == lum[5], "select_tie_is_exact", fmt("%.17g vs %.17g", lum[3], lum[5]));

  // max_local >= n folds nothing: the cube is untouched
  {
    float cube[6][3];
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) cube[f][c] = 0.25f;
    int kept[6];
    int n = ts_fold_lights(ls.data(), 6, 6, kCenter, 1, cube, kept);
    bool same = true;
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) same = same && cube[f][c] == 0.25f;
    check(n == 6 && same, "select_keep_all_folds_none", fmt("kept %d, cube changed: %d", n, (int)!same));
  }
  // folding with max_local 2 == folding lights {0, 2, 3, 5} one by one
  {
    float a[6][3] = {}, b[6][3] = {};
    int kept[2];
    ts_fold_lights(ls.data(), 6, 2, kCenter, 0, a, kept);
    const int rest[4] = {0, 2, 3, 5};
    for (int i : rest) ts_fold_lights(&ls[i], 1, 0, kCenter, 0, b, nullptr);
    double worst = 0.0;
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs((double)a[f][c] - b[f][c]));
    check(worst < 1e-6, "select_folds_exactly_the_rest", fmt("max deviation %g", worst));
  }
  // n == 0, NULL lights, NULL kept
  {
    float cube[6][3] = {};
    int kept[4] = {-7, -7, -7, -7};
    int n0 = ts_fold_lights(ls.data(), 0, 4, kCenter, 0, cube, kept);
    int n1 = ts_fold_lights(nullptr, 0, 4, kCenter, 0, cube, kept);
    int n2 = ts_fold_lights(ls.data(), -1, 4, kCenter, 0, cube, kept);
    bool zero = true;
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) zero = zero && cube[f][c] == 0.0f;
    check(n0 == 0 && n1 == 0 && n2 == 0 && zero && kept[0] == -7, "select_n_0_is_fine",
          fmt("returned %d %d %d", n0, n1, n2));
    int n3 = ts_fold_lights(ls.data(), 6, 2, kCenter, 0, cube, nullptr);
    check(n3 == 2, "select_null_kept_is_fine", fmt("returned %d", n3));
  }
  // an invalid light is neither kept nor folded
  {
    std::vector<ts_light> ls2 = ls;
    ls2[1].atten[0] = ls2[1].atten[1] = ls2[1].atten[2] = 0.0f;  // was the brightest
    float cube[6][3] = {}, ref[6][3] = {};
    int kept[3];
    int n = ts_fold_lights(ls2.data(), 6, 2, kCenter, 0, cube, kept);
    const int rest[3] = {0, 2, 5};
    for (int i : rest) ts_fold_lights(&ls[i], 1, 0, kCenter, 0, ref, nullptr);
    double worst = 0.0;
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs((double)cube[f][c] - ref[f][c]));
    check(n == 2 && kept[0] == 3 && kept[1] == 4 && worst < 1e-6, "select_invalid_light_skipped",
          fmt("kept %d: %d %d, fold deviation %g", n, kept[0], kept[1], worst));
  }
}

void check_pack() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  ts_light point = make_light(TS_LIGHT_POINT);
  point.color[0] = 1;
  point.color[1] = 2;
  point.color[2] = 3;
  point.pos[0] = 4;
  point.pos[1] = 5;
  point.pos[2] = 6;
  point.atten[0] = 1;
  point.atten[1] = 0.5f;
  point.atten[2] = 0.25f;
  ts_light spot = point;
  spot.type = TS_LIGHT_SPOT;
  spot.dir[0] = 0;
  spot.dir[1] = -2;  // not unit: packing normalises
  spot.dir[2] = 0;
  spot.spot_exponent = 3;
  spot.cos_inner = 0.9f;
  spot.cos_outer = 0.7f;
  ts_light dirl = make_light(TS_LIGHT_DIRECTIONAL);
  dirl.color[0] = dirl.color[1] = dirl.color[2] = 1;
  dirl.dir[0] = 3;
  dirl.dir[1] = 0;
  dirl.dir[2] = 4;

  struct Bad {
    std::string name;
    ts_light l;
  };
  std::vector<Bad> bad;
  const ts_light *bases[3] = {&point, &spot, &dirl};
  for (const ts_light *b : bases) {
    const char *tn = type_str(b->type);
    for (int i = 0; i < 3; ++i) {
      ts_light l = *b;
      l.color[i] = nan;
      bad.push_back({fmt("%s_color%d_nan", tn, i), l});
      l = *b;
      l.dir[i] = inf;
      bad.push_back({fmt("%s_dir%d_inf", tn, i), l});
      l = *b;
      l.pos[i] = -inf;
      bad.push_back({fmt("%s_pos%d_-inf", tn, i), l});
      l = *b;
      l.atten[i] = nan;
      bad.push_back({fmt("%s_atten%d_nan", tn, i), l});
    }
    ts_light l = *b;
    l.spot_exponent = nan;
    bad.push_back({fmt("%s_exponent_nan", tn), l});
    l = *b;
    l.cos_inner = inf;
    bad.push_back({fmt("%s_cos_inner_inf", tn), l});
    l = *b;
    l.cos_outer = nan;
    bad.push_back({fmt("%s_cos_outer_nan", tn), l});
  }
  const ts_light *attenuated[2] = {&point, &spot};
  for (const ts_light *b : attenuated) {
    const char *tn = type_str(b->type);
    for (int i = 0; i < 3; ++i) {
      ts_light l = *b;
      l.atten[i] = -0.5f;
      bad.push_back({fmt("%s_atten%d_negative", tn, i), l});
    }
    ts_light l = *b;
    l.atten[0] = l.atten[1] = l.atten[2] = 0.0f;
    bad.push_back({fmt("%s_atten_sum_zero", tn), l});
    l.atten[1] = -0.0f;
    bad.push_back({fmt("%s_atten_sum_zero_negzero", tn), l});
  }
  {
    ts_light l = spot;
    l.cos_inner = l.cos_outer;
    bad.push_back({"spot_cos_inner_eq_outer", l});
    l = spot;
    l.cos_inner = 0.5f;
    bad.push_back({"spot_cos_inner_lt_outer", l});
    l = spot;
    l.cos_outer = std::numeric_limits<float>::min();  // normal floats one ulp apart:
    l.cos_inner = std::nextafter(l.cos_outer, 1.0f);  // 1/(1.4e-45) overflows float
    bad.push_back({"spot_cone_too_narrow", l});
    l = spot;
    l.spot_exponent = -1.0f;
    bad.push_back({"spot_exponent_negative", l});
    l = spot;
    l.dir[0] = l.dir[1] = l.dir[2] = 0.0f;
    bad.push_back({"spot_dir_zero", l});
    l = dirl;
    l.dir[0] = l.dir[1] = l.dir[2] = 0.0f;
    bad.push_back({"directional_dir_zero", l});
    l = point;
    l.type = (ts_light_type)3;
    bad.push_back({"unknown_type", l});
  }
  for (const Bad &b : bad) {
    float out[5][4];
    for (auto &row : out)
      for (float &v : row) v = 42.0f;
    char err[200];
    std::strcpy(err, "");
    int r = ts_light_pack(&b.l, out, err, sizeof err);
    bool untouched = true;
    for (auto &row : out)
      for (float v : row) untouched = untouched && v == 42.0f;
    check(r == 0 && std::strlen(err) > 0 && untouched, "pack_rejects_" + b.name,
          fmt("returned %d, err \"%s\", out untouched %d", r, err, (int)untouched));
  }
  // the message survives a tiny or missing buffer
  {
    float out[5][4];
    char tiny[8];
    ts_light l = spot;
    l.cos_inner = 0.1f;
    int r1 = ts_light_pack(&l, out, tiny, sizeof tiny);
    int r2 = ts_light_pack(&l, out, nullptr, 0);
    check(r1 == 0 && r2 == 0 && std::strlen(tiny) == 7, "pack_error_buffer_truncates",
          fmt("%d %d \"%s\"", r1, r2, tiny));
    char err[200];
    ts_light l2 = point;
    l2.atten[1] = -2.0f;
    ts_light_pack(&l2, out, err, sizeof err);
    info(std::string("example message: ") + err);
  }

  // valid lights and their layout
  {
    float o[5][4];
    char err[200];
    int r = ts_light_pack(&spot, o, err, sizeof err);
    float want_w = (float)(1.0 / ((double)spot.cos_inner - (double)spot.cos_outer));
    float naive_w = 1.0f / (spot.cos_inner - spot.cos_outer);
    bool ok = r == 1 && o[3][3] == want_w && std::fabs(o[3][3] - naive_w) <= 1e-6f * naive_w && o[3][0] == 3.0f &&
        o[3][2] == 0.7f && o[1][3] == 1.0f && o[0][3] == 0.0f && o[1][0] == 0.0f && o[1][1] == -1.0f &&
        o[1][2] == 0.0f && o[2][0] == 4.0f && o[2][1] == 5.0f && o[2][2] == 6.0f && o[4][0] == 1.0f &&
        o[4][1] == 0.5f && o[4][2] == 0.25f && o[0][0] == 1.0f && o[0][1] == 2.0f && o[0][2] == 3.0f;
    check(ok, "pack_valid_spot_layout_w_is_1_over_cos_diff",
          fmt("r %d err \"%s\" w %.9g want %.9g", r, err, o[3][3], want_w));

    r = ts_light_pack(&dirl, o, err, sizeof err);
    ok = r == 1 && o[0][3] == 1.0f && o[1][3] == 0.0f && std::fabs(o[1][0] - 0.6f) < 1e-7f && o[1][1] == 0.0f &&
        std::fabs(o[1][2] - 0.8f) < 1e-7f && o[4][0] == 1.0f && o[4][1] == 0.0f && o[4][2] == 0.0f;
    check(ok, "pack_valid_directional_atten_100_dir_normalised", err);

    ts_light d2 = dirl;
    d2.atten[0] = d2.atten[1] = d2.atten[2] = 0.0f;  // ignored, so (0,0,0) is fine
    d2.atten[1] = -3.0f;  // negative too: ignored for directional
    r = ts_light_pack(&d2, o, err, sizeof err);
    check(r == 1 && o[4][0] == 1.0f && o[4][1] == 0.0f, "pack_directional_ignores_atten", err);

    ts_light p2 = point;  // point light: dir ignored, may be zero
    r = ts_light_pack(&p2, o, err, sizeof err);
    ok = r == 1 && o[0][3] == 0.0f && o[1][3] == 0.0f && o[1][0] == 0.0f && o[3][0] == 0.0f && o[3][3] == 0.0f &&
        o[4][1] == 0.5f && std::strlen(err) == 0;
    check(ok, "pack_valid_point_zero_dir_ok", err);
  }
}

// ts_light_incident equals what the double twin computes for the same light.
void check_incident() {
  const float color[3] = {0.7f, 0.4f, 0.9f};
  const ts_light_type types[3] = {TS_LIGHT_DIRECTIONAL, TS_LIGHT_POINT, TS_LIGHT_SPOT};
  for (ts_light_type t : types) {
    double worst = 0.0, unit = 0.0, spotf = 1.0;
    for (V3 L : test_directions()) {
      ts_light l = light_towards(t, L, color);
      double I[3], Ld[3];
      ts_light_incident(&l, kCenter, I, Ld);
      unit = std::fmax(unit, std::fabs(std::sqrt(Ld[0] * Ld[0] + Ld[1] * Ld[1] + Ld[2] * Ld[2]) - 1.0));
      unit = std::fmax(unit, angle_deg({Ld[0], Ld[1], Ld[2]}, L) * kPi / 180.0);
      Record r;
      r.add_light(0, l);
      ml_variant v = variant(TS_TIER_ID_PS2B, 0, 1);
      r.rec[ML_SLOT_NORMAL] = {(float)Ld[0], (float)Ld[1], (float)Ld[2], 0.0f};
      ts_vec4d s = model_lighting_d(&v, r.rec, &kDummyAlbedo);
      double sv[3] = {s.x, s.y, s.z};
      for (int c = 0; c < 3; ++c) worst = std::fmax(worst, rel_diff(sv[c], I[c]));
      if (t == TS_LIGHT_SPOT) spotf = std::fmin(spotf, I[1] / (color[1] / (1.0 + 0.2 * 3.0 + 0.05 * 9.0)));
    }
    check(worst < 1e-6, fmt("incident_matches_model_lighting_d_%s", type_str(t)), fmt("max rel %.3e", worst));
    check(unit < 1e-6, fmt("incident_direction_unit_towards_light_%s", type_str(t)), fmt("off by %.3e", unit));
    if (t == TS_LIGHT_SPOT)
      check(spotf > 0.01 && spotf < 0.99, "incident_spot_cone_fractional_in_tests", fmt("cone factor %g", spotf));
  }
  // invalid light -> zeros
  ts_light bad = make_light(TS_LIGHT_POINT);
  bad.color[0] = 1;
  double I[3] = {9, 9, 9}, L[3] = {9, 9, 9};
  ts_light_incident(&bad, kCenter, I, L);
  check(I[0] == 0 && I[1] == 0 && I[2] == 0 && L[0] == 0 && L[1] == 0 && L[2] == 0, "incident_invalid_is_zero");
}

// A light exactly at the centre: the shader's L is 0 (half-Lambert gives I/4
// everywhere, Lambert 0); the fold conserves that too.
void check_degenerate() {
  const float color[3] = {1.0f, 2.0f, 3.0f};
  for (int hl = 0; hl <= 1; ++hl) {
    ts_light l = make_light(TS_LIGHT_POINT);
    for (int c = 0; c < 3; ++c) {
      l.color[c] = color[c];
      l.pos[c] = kCenter[c];
    }
    l.atten[0] = 1.0f;
    Record local;
    local.add_light(0, l);
    Integral A = integrate(variant(TS_TIER_ID_PS2B, hl, 1), local);
    float cube[6][3] = {};
    ts_fold_lights(&l, 1, 0, kCenter, hl, cube, nullptr);
    Integral B = integrate(variant(TS_TIER_ID_PS2B, hl, 0), Record(cube));
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
      worst = std::fmax(worst, hl ? rel_diff(A.rgb[c], B.rgb[c]) : std::fabs(A.rgb[c] - B.rgb[c]));
    check(worst < 1e-3, fmt("degenerate_light_at_centre_%s", hl ? "half_lambert" : "lambert"),
          fmt("local %g folded %g (green)", A.rgb[1], B.rgb[1]));
  }
}

}  // namespace

// Both ranking paths of ts_fold_lights (its stack table up to 256 lights, re-evaluation beyond):
// 200 and 300 scattered point lights (every 7th invalid: negative attenuation), 4 kept; the kept set
// is the 4 largest incident luminances at the centre ranked here, and the folded cube equals the
// sum of fold contributions of the others (the first 200 of the 300 give the 200 case's answer).
void check_many_lights() {
  for (int n : {200, 300}) {
    std::vector<ts_light> ls;
    uint32_t r = 777;
    auto next = [&r] {
      r = r * 1664525u + 1013904223u;
      return static_cast<float>(r >> 8) / 16777216.f;
    };
    for (int i = 0; i < n; ++i) {
      ts_light l = make_light(TS_LIGHT_POINT);
      for (int c = 0; c < 3; ++c) l.color[c] = 0.5f + 4.f * next();
      for (int c = 0; c < 3; ++c) l.pos[c] = kCenter[c] + 30.f * (next() - 0.5f);
      l.atten[2] = i % 7 == 3 ? -1.f : 1.f;  // -1: rejected by ts_light_pack
      ls.push_back(l);
    }
    std::vector<std::pair<double, int>> lum;
    for (int i = 0; i < n; ++i) {
      if (i % 7 == 3) continue;
      double I[3], L[3];
      ts_light_incident(&ls[i], kCenter, I, L);
      lum.push_back({-(0.2126 * I[0] + 0.7152 * I[1] + 0.0722 * I[2]), i});
    }
    std::sort(lum.begin(), lum.end());
    std::vector<int> want;
    for (int k = 0; k < 4; ++k) want.push_back(lum[k].second);
    std::sort(want.begin(), want.end());
    float cube[6][3] = {};
    int kept[4] = {-1, -1, -1, -1};
    const int nk = ts_fold_lights(ls.data(), n, 4, kCenter, 0, cube, kept);
    bool ok = nk == 4;
    for (int k = 0; ok && k < 4; ++k) ok = kept[k] == want[k];
    // Each folded light alone (max_local 0 over a one-light list) adds what it added here.
    float sum[6][3] = {};
    for (size_t k = 4; k < lum.size(); ++k) ts_fold_lights(&ls[lum[k].second], 1, 0, kCenter, 0, sum, nullptr);
    double worst = 0;
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) worst = std::fmax(worst, rel_diff(cube[f][c], sum[f][c]));
    // Tolerance: the two sums add the same float contributions in different orders; float
    // accumulation of ~250 positive terms differs by at most ~250 ulp (1.5e-5 relative).
    check(ok && worst < 1e-4,
          fmt("fold %d lights (%s path): the 4 brightest kept, the rest folded", n, n <= 256 ? "table" : "re-evaluating"),
          fmt("kept %d: %d %d %d %d, want %d %d %d %d; cube rel diff %.3g", nk, kept[0], kept[1], kept[2], kept[3],
              want[0], want[1], want[2], want[3], worst));
  }
}

int main() {
  ts_math_init();
  check_many_lights();
  check_pack();
  check_incident();
  check_constants();
  check_conservation();
  check_additive();
  check_selection();
  check_end_to_end();
  check_degenerate();
  if (g_failed)
    std::printf("%d check(s) FAILED\n", g_failed);
  else
    std::printf("all checks passed\n");
  return g_failed ? 1 : 0;
}

// tiershade tests: the probe behind c_ref/math/ts_sampler3d.c, kept as a regression test: llvmpipe's
// 3D (volume) texture sampling of RGBA32F textures against the C twin, bit for
// bit (0 ULP; NaN compared as a class, docs/c_math_layer.md "NaN payloads").
// Coordinates come from an RGBA32F record read with texelFetch, so nothing is
// constant-folded; the output is read back from an RGBA32F framebuffer.
//
// Cases: 32^3 (Source's colour-correction size), 17x9x5 (NPOT, every axis a
// different length) and 16x8x4 (POT); LINEAR and NEAREST; CLAMP_TO_EDGE and
// REPEAT; random coordinates, a 1/2048 grid, texel centres and edges, and
// special values (NaN, +-Inf, +-tiny, huge, near-integers); texelFetch in and
// out of range. Runs on OSMesa GL 3.3 and EGL GLES 3.0 (ESSL 3.00) and checks
// that ESSL 1.00 with GL_OES_texture_3D compiles and agrees on EGL GLES 2.0.
//
// It also checks that the probe discriminates: the other lerp order
// (z first) and the other fused-mad mode each give mismatches on the LINEAR
// cases, so a 0 above is a measurement, not a tautology.
//
// Usage: build/tests/test_sampler3d   Prints PASS/FAIL lines; exit 1 on failure.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "shaderlib/assembler.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "base/image.h"
#include "color/lut_texture.h"
#include "base/image_diff.h"
#include "families/family.h"  // Rng (xorshift32; every seed below is nonzero)
#include "math/ts_sampler3d.h"
#include "unit_check.h"

namespace {

const int kW = 256, kH = 128;  // 32768 coordinates per case

struct Case {
  std::string name;
  int w, h, d;
  bool linear, repeat;
  std::vector<ts_vec3f> coords;  // kW * kH
};

std::vector<float> random_volume(int w, int h, int d, uint32_t seed) {
  Rng r(seed);
  std::vector<float> v(static_cast<size_t>(w) * h * d * 4);
  for (float &x : v) x = r.uniform(-4.f, 4.f);
  return v;
}

// Coordinate sets.
std::vector<ts_vec3f> coords_random(uint32_t seed, float lo, float hi) {
  Rng r(seed);
  std::vector<ts_vec3f> c(kW * kH);
  for (auto &p : c) p = ts_v3f(r.uniform(lo, hi), r.uniform(lo, hi), r.uniform(lo, hi));
  return c;
}
std::vector<ts_vec3f> coords_grid(uint32_t seed) {
  Rng r(seed);
  std::vector<ts_vec3f> c(kW * kH);
  auto g = [&] { return static_cast<float>(static_cast<int>(r.next() % 4097) - 1024) / 2048.f; };
  for (auto &p : c) p = ts_v3f(g(), g(), g());
  return c;
}
// Texel centres and edges of an axis of length n: k/n and (k+0.5)/n, computed in float.
std::vector<ts_vec3f> coords_centres(uint32_t seed, int w, int h, int d) {
  Rng r(seed);
  std::vector<ts_vec3f> c(kW * kH);
  auto pick = [&](int n) {
    const int k = static_cast<int>(r.next() % static_cast<uint32_t>(n + 1));
    return (r.next() & 1) ? (static_cast<float>(k) + 0.5f) / static_cast<float>(n)
                          : static_cast<float>(k) / static_cast<float>(n);
  };
  for (auto &p : c) p = ts_v3f(pick(w), pick(h), pick(d));
  return c;
}
std::vector<ts_vec3f> coords_special(uint32_t seed) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float sp[] = {nan,        inf,     -inf, 0.f,   -0.f,       1e-39f,      -1e-39f,
                      1e-30f,     -1e-30f, 1e4f, -1e4f, 1e30f,      1.f,         0.99999994f,
                      1.0000001f, 0.5f,    2.f,  -1.f,  3.0000002f, 0.49999997f, 0.50000006f};
  const int n = sizeof sp / sizeof sp[0];
  Rng r(seed);
  std::vector<ts_vec3f> c(kW * kH);
  for (auto &p : c) {
    auto one = [&] { return (r.next() % 3) ? sp[r.next() % n] : r.uniform(-2.f, 3.f); };
    p = ts_v3f(one(), one(), one());
  }
  return c;
}

bool same(float a, float b) { return (std::isnan(a) && std::isnan(b)) || ulp_distance(a, b) == 0; }

const char *kFragment330 =
    "uniform highp sampler2D ts_coords;\n"
    "uniform highp sampler3D u_vol;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  vec4 c = texelFetch(ts_coords, ivec2(gl_FragCoord.xy), 0);\n"
    "#ifdef FETCH\n"
    "  o = texelFetch(u_vol, ivec3(c.xyz), 0);\n"
    "#else\n"
    "  o = texture(u_vol, c.xyz);\n"
    "#endif\n"
    "}\n";
const char *kFragment100 =
    "#extension GL_OES_texture_3D : require\n"
    "precision highp float;\n"
    "precision highp sampler2D;\n"
    "precision highp sampler3D;\n"
    "uniform sampler2D ts_coords;\n"
    "uniform sampler3D u_vol;\n"
    "uniform vec2 u_size;\n"
    "void main() {\n"
    "  vec4 c = texture2D(ts_coords, gl_FragCoord.xy / u_size);\n"
    "  gl_FragColor = texture3D(u_vol, c.xyz);\n"
    "}\n";

struct Gl {
  std::unique_ptr<GlContext> ctx;
  std::unique_ptr<GlRenderer> r;
  Api api;
  std::string tag;
};

// Renders `coords` through the volume on one context; returns false on a GL error.
bool render(Gl &g, const TextureDesc &vol, const std::vector<ts_vec3f> &coords, bool fetch, ImageF *out,
            std::string *err) {
  Assembled vs, fs;
  const Target t = g.api == Api::GLES2 ? Target::ESSL100 : g.api == Api::GLES3 ? Target::ESSL300 : Target::GLSL330;
  if (!assemble("conform_fullscreen.vs", t, Stage::Vertex, {}, &vs, err)) return false;
  if (g.api == Api::GLES2) {
    fs.text = std::string("#version 100\n") + kFragment100;
  } else {
    fs.text = std::string(g.api == Api::GLES3 ? "#version 300 es\nprecision highp float;\n" : "#version 330 core\n") +
        (fetch ? "#define FETCH 1\n" : "") + kFragment330;
  }
  fs.files = {"test_sampler3d"};
  const GLuint prog = g.r->build_program(vs, fs, err);
  if (!prog) return false;
  TextureDesc ct;
  ct.sampler = "ts_coords";
  ct.w = kW;
  ct.h = kH;
  ct.rgba.resize(static_cast<size_t>(kW) * kH * 4);
  for (size_t i = 0; i < coords.size(); ++i) {
    ct.rgba[i * 4 + 0] = coords[i].x;
    ct.rgba[i * 4 + 1] = coords[i].y;
    ct.rgba[i * 4 + 2] = coords[i].z;
    ct.rgba[i * 4 + 3] = 0.f;
  }
  const GlFns &gl = g.r->gl();
  gl.UseProgram(prog);
  const GLint sl = gl.GetUniformLocation(prog, "u_size");
  if (sl >= 0) gl.Uniform2f(sl, static_cast<float>(kW), static_cast<float>(kH));
  std::vector<std::pair<std::string, GLuint>> texs = {{"ts_coords", g.r->upload_texture(ct)},
                                                      {"u_vol", g.r->upload_texture(vol)}};
  const bool ok = g.r->draw(prog, texs, kW, kH, out, err);
  for (auto &x : texs) g.r->delete_texture(x.second);
  g.r->delete_program(prog);
  return ok;
}

// The C twin with a lerp order of choice, for the discrimination check.
ts_vec4f lerp4(float w, ts_vec4f a, ts_vec4f b) {
  return ts_v4f(ts_madf(w, b.x - a.x, a.x), ts_madf(w, b.y - a.y, a.y), ts_madf(w, b.z - a.z, a.z),
                ts_madf(w, b.w - a.w, a.w));
}
// Trilinear with z lerped first (then y, then x): a plausible but wrong order.
// CLAMP_TO_EDGE only (the discrimination cases use it).
ts_vec4f texture3d_z_first(const ts_tex3d *t, ts_vec3f p) {
  int i0[3], i1[3];
  float w[3];
  const float u[3] = {p.x, p.y, p.z};
  const int len[3] = {t->w, t->h, t->d};
  for (int a = 0; a < 3; ++a) {
    const float lf = static_cast<float>(len[a]);
    float c = ts_lp_minf(u[a] * lf, lf) - 0.5f;
    c = ts_lp_maxf(c, 0.f);
    const float fl = ts_floorf(c);
    w[a] = c - fl;
    i0[a] = ts_lp_itruncf(fl);
    i1[a] = i0[a] + 1 < len[a] - 1 ? i0[a] + 1 : len[a] - 1;
  }
  auto T = [&](int x, int y, int z) { return ts_texelFetch3Df(t, x, y, z); };
  const ts_vec4f a0 = lerp4(w[1], lerp4(w[2], T(i0[0], i0[1], i0[2]), T(i0[0], i0[1], i1[2])),
                            lerp4(w[2], T(i0[0], i1[1], i0[2]), T(i0[0], i1[1], i1[2])));
  const ts_vec4f a1 = lerp4(w[1], lerp4(w[2], T(i1[0], i0[1], i0[2]), T(i1[0], i0[1], i1[2])),
                            lerp4(w[2], T(i1[0], i1[1], i0[2]), T(i1[0], i1[1], i1[2])));
  return lerp4(w[0], a0, a1);
}

// Compares GL against the twin (or an alternative); returns the number of mismatching channels.
template <class Fn>
long mismatches(const ImageF &img, const std::vector<ts_vec3f> &coords, Fn twin, std::string *first) {
  long bad = 0;
  for (size_t i = 0; i < coords.size(); ++i) {
    const ts_vec4f c = twin(coords[i]);
    const float cv[4] = {c.x, c.y, c.z, c.w};
    for (int ch = 0; ch < 4; ++ch) {
      if (!same(img.rgba[i * 4 + ch], cv[ch])) {
        if (!bad && first) {
          char b[256];
          snprintf(b, sizeof b, "coord (%.9g, %.9g, %.9g) ch%d: GL %.9g C %.9g", coords[i].x, coords[i].y, coords[i].z,
                   ch, img.rgba[i * 4 + ch], cv[ch]);
          *first = b;
        }
        ++bad;
      }
    }
  }
  return bad;
}

}  // namespace

int main() {
  ts_math_init();
  std::vector<Gl> gls;
  const struct {
    Backend b;
    Api a;
  } cfgs[] = {{Backend::OSMesa, Api::GL33}, {Backend::EGL, Api::GLES3}, {Backend::EGL, Api::GLES2}};
  for (const auto &c : cfgs) {
    std::string err;
    Gl g;
    g.ctx = GlContext::create(c.b, c.a, &err);
    g.api = c.a;
    g.tag = std::string(backend_name(c.b)) + "/" + api_name(c.a);
    check(g.ctx != nullptr, "sampler3d.context." + g.tag, err);
    if (!g.ctx) continue;
    g.r = std::make_unique<GlRenderer>(*g.ctx);
    gls.push_back(std::move(g));
  }

  std::vector<Case> cases;
  auto add = [&](const std::string &name, int w, int h, int d, bool linear, bool repeat, std::vector<ts_vec3f> c) {
    cases.push_back({name, w, h, d, linear, repeat, std::move(c)});
  };
  add("32^3 linear clamp random", 32, 32, 32, true, false, coords_random(11, -0.25f, 1.25f));
  add("32^3 linear clamp grid", 32, 32, 32, true, false, coords_grid(12));
  add("32^3 linear clamp centres+edges", 32, 32, 32, true, false, coords_centres(13, 32, 32, 32));
  add("17x9x5 linear clamp random", 17, 9, 5, true, false, coords_random(14, -0.25f, 1.25f));
  add("17x9x5 linear clamp centres+edges", 17, 9, 5, true, false, coords_centres(15, 17, 9, 5));
  add("17x9x5 linear repeat random", 17, 9, 5, true, true, coords_random(16, -2.f, 3.f));
  add("16x8x4 linear repeat random", 16, 8, 4, true, true, coords_random(17, -2.f, 3.f));
  add("17x9x5 linear clamp specials", 17, 9, 5, true, false, coords_special(18));
  add("16x8x4 linear repeat specials", 16, 8, 4, true, true, coords_special(19));
  add("17x9x5 nearest clamp random", 17, 9, 5, false, false, coords_random(20, -0.25f, 1.25f));
  add("17x9x5 nearest repeat random", 17, 9, 5, false, true, coords_random(21, -2.f, 3.f));
  add("16x8x4 nearest repeat specials", 16, 8, 4, false, true, coords_special(22));
  add("17x9x5 nearest clamp centres+edges", 17, 9, 5, false, false, coords_centres(23, 17, 9, 5));

  long z_first_total = 0, wrong_fused_total = 0;
  for (Gl &g : gls) {
    g.ctx->make_current();  // all contexts live at once; GL calls go to the current one
    for (size_t ci = 0; ci < cases.size(); ++ci) {
      const Case &cs = cases[ci];
      TextureDesc vol;
      vol.sampler = "u_vol";
      vol.kind = TexKind::Tex3D;
      vol.w = cs.w;
      vol.h = cs.h;
      vol.d = cs.d;
      vol.linear = cs.linear;
      vol.repeat = cs.repeat;
      vol.rgba = random_volume(cs.w, cs.h, cs.d, 100 + static_cast<uint32_t>(ci));
      const ts_tex3d t = tex3d_of(vol);  // the C sampler's view of the same texture
      ImageF img;
      std::string err;
      const std::string name = "sampler3d." + g.tag + "." + cs.name;
      if (!render(g, vol, cs.coords, false, &img, &err)) {
        check(false, name, err);
        continue;
      }
      std::string first;
      const long bad = mismatches(
          img, cs.coords, [&](ts_vec3f p) { return ts_texture3Df(&t, p); }, &first);
      check(bad == 0, name,
            std::to_string(bad) + " of " + std::to_string(cs.coords.size() * 4) + " channels differ; " + first);
      if (cs.linear && !cs.repeat && g.api != Api::GLES2 && cs.name.find("specials") == std::string::npos) {
        z_first_total += mismatches(
            img, cs.coords, [&](ts_vec3f p) { return texture3d_z_first(&t, p); }, nullptr);
        ts_math_set_fused(!ts_math_fused());
        wrong_fused_total += mismatches(
            img, cs.coords, [&](ts_vec3f p) { return ts_texture3Df(&t, p); }, nullptr);
        ts_math_init();  // back to the detected mode
      }
    }
    if (g.api == Api::GLES2) continue;  // ESSL 1.00 has no texelFetch
    // texelFetch, in and out of range: llvmpipe returns 0 outside (the twin mirrors it).
    TextureDesc vol;
    vol.sampler = "u_vol";
    vol.kind = TexKind::Tex3D;
    vol.w = 17;
    vol.h = 9;
    vol.d = 5;
    vol.rgba = random_volume(17, 9, 5, 999);
    ts_tex3d t{17, 9, 5, vol.rgba.data(), TS_WRAP_CLAMP, TS_WRAP_CLAMP, TS_WRAP_CLAMP, TS_FILTER_NEAREST};
    Rng r(77);
    std::vector<ts_vec3f> ic(kW * kH);
    for (auto &p : ic)
      p = ts_v3f(static_cast<float>(static_cast<int>(r.next() % 23) - 3),
                 static_cast<float>(static_cast<int>(r.next() % 15) - 3),
                 static_cast<float>(static_cast<int>(r.next() % 11) - 3));
    ImageF img;
    std::string err, first;
    if (!render(g, vol, ic, true, &img, &err)) {
      check(false, "sampler3d." + g.tag + ".texelFetch", err);
    } else {
      const long bad = mismatches(
          img, ic,
          [&](ts_vec3f p) {
            return ts_texelFetch3Df(&t, static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(p.z));
          },
          &first);
      check(bad == 0, "sampler3d." + g.tag + ".texelFetch in and out of range",
            std::to_string(bad) + " differ; " + first);
    }
  }
  // The probe must be able to tell the candidates apart.
  check(z_first_total > 1000, "sampler3d.discriminates lerp order",
        "z-first order differs in only " + std::to_string(z_first_total) + " channels");
  check(wrong_fused_total > 1000, "sampler3d.discriminates fused mode",
        "the other fused-mad mode differs in only " + std::to_string(wrong_fused_total) + " channels");
  printf("info: z-first lerp order: %ld mismatching channels; other fused mode: %ld\n", z_first_total,
         wrong_fused_total);
  return finish();
}

// tiershade tests: the storage conversions of c_ref/math/hdr_formats.c against llvmpipe, on every
// backend/API pair: a pass-through shader writes chosen floats into an RGBA8 and an
// RGBA16F target, and an RGBA8 texture is fetched as float. The values are the hard
// ones: every RGBA8 rounding boundary (k + 1/2) / 255 and its neighbours within 8 ULP,
// half-float boundaries across the whole exponent range (toward-zero rounding shows
// there), the top of the half range, half denormals, zeros, negatives, Inf and NaN.
// (docs/hdr.md records the exhaustive one-time measurement these cases come from.)
// No tolerance: codes and half bits must be equal; NaN compares as a class.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if anything failed.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "math/hdr_formats.h"
#include "hdr/gl_passes.h"
#include "math/ts_math.h"
#include "unit_gl.h"

namespace {


std::vector<float> test_values() {
  std::vector<float> v;
  for (int k = 0; k < 255; ++k) {  // RGBA8 rounding boundaries and their neighbours
    const uint32_t b = bits_of((k + 0.5f) / 255.f);
    for (int d = -8; d <= 8; ++d) v.push_back(float_of_bits(b + static_cast<uint32_t>(d)));
  }
  for (int e = -26; e <= 16; ++e)  // half boundaries: mantissa steps of 2^-10 and the bits below them
    for (uint32_t m : {0u, 1u, 0x1fffu, 0x2000u, 0x2001u, 0x3fffu, 0x7fe000u, 0x7fffffu}) {
      const uint32_t b = (static_cast<uint32_t>(e + 127) << 23) | m;
      v.push_back(float_of_bits(b));
      v.push_back(-float_of_bits(b));
    }
  for (float x : {0.f, -0.f, 1.f, 65504.f, 65519.f, 65520.f, 65536.f, 1e30f, 3e-6f, 6e-8f, 1e-39f, 0.5f, 2.f}) {
    v.push_back(x);
    v.push_back(-x);
  }
  v.push_back(INFINITY);
  v.push_back(-INFINITY);
  v.push_back(std::nanf(""));
  while (v.size() % 4) v.push_back(0.25f);
  return v;
}

void run(Backend b, Api api, const std::vector<float> &vals) {
  const std::string name = config_name(b, api);
  std::string err;
  auto ctx = open_context(b, api, "formats " + name);
  if (!ctx) return;
  GlRenderer r(*ctx);
  const GlFns &g = r.gl();
  // One value per channel: a W x H RGBA32F texture, passed through unchanged.
  const int W = 64, H = static_cast<int>((vals.size() / 4 + W - 1) / W);
  TextureDesc t;
  t.sampler = "u_in";
  t.w = W;
  t.h = H;
  t.rgba.assign(static_cast<size_t>(W) * H * 4, 0.25f);
  std::copy(vals.begin(), vals.end(), t.rgba.begin());
  const GLuint in = r.upload_texture(t);
  Assembled vs, fs;
  const std::string head = api == Api::GLES2 ? "#version 100\nprecision highp float;\nprecision highp sampler2D;\n"
      : api == Api::GLES3                    ? "#version 300 es\nprecision highp float;\nprecision highp sampler2D;\n"
                                             : "#version 330 core\n";
  if (api == Api::GLES2) {
    vs.text = head + "attribute vec2 a_corner; void main() { gl_Position = vec4(a_corner, 0.0, 1.0); }\n";
    fs.text = head +
        "uniform sampler2D u_in; uniform vec2 u_size;\n"
        "void main() { gl_FragColor = texture2D(u_in, gl_FragCoord.xy / u_size); }\n";
  } else {
    vs.text = head + "in vec2 a_corner; void main() { gl_Position = vec4(a_corner, 0.0, 1.0); }\n";
    fs.text = head +
        "uniform sampler2D u_in; uniform vec2 u_size; out vec4 o;\n"
        "void main() { o = texelFetch(u_in, ivec2(gl_FragCoord.xy), 0); }\n";
  }
  const GLuint prog = r.build_program(vs, fs, &err);
  if (!prog) {
    check(false, "formats " + name, err);
    return;
  }
  PassRunner run(r);
  g.UseProgram(prog);
  g.Uniform2f(g.GetUniformLocation(prog, "u_size"), static_cast<float>(W), static_cast<float>(H));
  GlTarget t8, t16;
  std::vector<uint8_t> got8;
  std::vector<float> got16;
  if (!make_target(g, TargetFormat::RGBA8, W, H, &t8, &err) ||
      !make_target(g, TargetFormat::RGBA16F, W, H, &t16, &err) ||
      !run.draw(prog, t8, {{"u_in", in, false}}, nullptr, &err) ||
      !run.draw(prog, t16, {{"u_in", in, false}}, nullptr, &err) || !read_rgba8(g, t8, &got8, &err) ||
      !read_float(g, t16, &got16, &err)) {
    check(false, "formats " + name, err);
    return;
  }
  long bad8 = 0, bad16 = 0;
  std::string why8, why16;
  for (size_t i = 0; i < vals.size(); ++i) {
    const uint8_t want8 = ts_unorm8_from_float(vals[i]);
    if (got8[i] != want8 && bad8++ == 0)
      why8 = "value " + std::to_string(vals[i]) + ": GL " + std::to_string(got8[i]) + ", C " + std::to_string(want8);
    const float want16 = ts_quantize_half(vals[i]);
    const bool same = std::isnan(want16) ? std::isnan(got16[i]) : bits_of(got16[i]) == bits_of(want16);
    if (!same && bad16++ == 0)
      why16 = "value " + std::to_string(vals[i]) + ": GL " + std::to_string(got16[i]) + ", C " + std::to_string(want16);
  }
  check(bad8 == 0,
        "formats " + name + ": RGBA8 target writes round(saturate(x) * 255) like the C (" +
            std::to_string(vals.size()) + " values)",
        std::to_string(bad8) + " differ; first " + why8);
  check(bad16 == 0,
        "formats " + name + ": RGBA16F target writes round toward zero like the C (" + std::to_string(vals.size()) +
            " values)",
        std::to_string(bad16) + " differ; first " + why16);
  // The cases must tell toward-zero from round-to-nearest: count the values whose upper half
  // neighbour is nearer than the half they are truncated to.
  long nearer_up = 0;
  for (float x : vals) {
    if (!std::isfinite(x) || x <= 0.f || x >= 65504.f) continue;
    const uint16_t h = ts_half_from_float_rz(x);
    if (x - ts_half_to_float(h) > ts_half_to_float(static_cast<uint16_t>(h + 1)) - x) ++nearer_up;
  }
  check(nearer_up > 100, "formats " + name + ": the half cases include values that rounding to nearest would round up",
        std::to_string(nearer_up));
  // RGBA8 texels fetched as float: code * (1/255).
  std::vector<uint8_t> codes(256 * 4);
  for (int k = 0; k < 256; ++k)
    for (int c = 0; c < 4; ++c) codes[k * 4 + c] = static_cast<uint8_t>(c == 1 ? 255 - k : k);
  const GLuint tex8 = upload_rgba8(g, 256, 1, codes);
  GlTarget tf;
  std::vector<float> fetched;
  g.UseProgram(prog);
  g.Uniform2f(g.GetUniformLocation(prog, "u_size"), 256.f, 1.f);
  if (!make_target(g, TargetFormat::RGBA32F, 256, 1, &tf, &err) ||
      !run.draw(prog, tf, {{"u_in", tex8, false}}, nullptr, &err) || !read_float(g, tf, &fetched, &err)) {
    check(false, "formats " + name + ": RGBA8 fetch", err);
    return;
  }
  long badf = 0;
  for (size_t i = 0; i < codes.size(); ++i) badf += bits_of(fetched[i]) != bits_of(ts_unorm8_to_float(codes[i]));
  check(badf == 0, "formats " + name + ": an RGBA8 texel reads as code * (1/255) like the C (256 codes)",
        std::to_string(badf) + " differ");
  free_target(g, &t8);
  free_target(g, &t16);
  free_target(g, &tf);
  g.DeleteTextures(1, &tex8);
  r.delete_texture(in);
  r.delete_program(prog);
}

}  // namespace

int main() {
  ts_math_init();
  const std::vector<float> vals = test_values();
  for (const BackendApi &c : all_gl_configs()) run(c.backend, c.api, vals);
  // C-only facts the GL checks rely on.
  check(ts_half_from_float_rz(65519.f) == 0x7bff && ts_half_from_float_rz(1e30f) == 0x7bff &&
            ts_half_from_float_rz(INFINITY) == 0x7c00 && ts_half_from_float_rz(5.9604645e-8f) == 0x0001 &&
            ts_half_from_float_rz(5.9604641e-8f) == 0x0000,
        "formats: half toward zero saturates finite values at 65504 and keeps the smallest denormal");
  // The RGBA8 cases must tell round-to-nearest-even from the truncating x * 255 + 0.5: they hold
  // the 130 values (of all floats in [0, 1]) where the two differ.
  long trunc_differs = 0;
  for (float x : vals) {
    if (std::isnan(x)) continue;
    const float c = std::fmin(std::fmax(x, 0.f), 1.f);
    trunc_differs += static_cast<uint8_t>(c * 255.f + 0.5f) != ts_unorm8_from_float(x);
  }
  check(trunc_differs == 130, "formats: the RGBA8 cases include every float where truncating rounding differs",
        std::to_string(trunc_differs));
  bool exact = true;
  for (uint32_t h = 0; h < 0x7c00; ++h)
    exact = exact && ts_half_from_float_rz(ts_half_to_float(static_cast<uint16_t>(h))) == h;
  check(exact, "formats: every finite half survives half -> float -> half");
  return g_failed ? 1 : 0;
}

// tiershade tests: MSAA on the integer path (glue/scene/msaa.h):
//   - msaa_resolve_unorm8 returns c for n equal codes c (n = 2, 4, 8; every code);
//   - llvmpipe offers 4 samples per pixel (GL_MAX_SAMPLES 4; a request for 2 allocates 4), the
//     count and pattern scene_render_msaa_cpu mirrors;
//   - GL's resolve (glBlitFramebuffer of a 4x RGBA8 renderbuffer) equals msaa_resolve_unorm8 on
//     every pixel of 256x256 frames whose samples hold two codes: A (the clear) and B (a draw
//     that writes code (x, y, x+y mod 256) with glSampleCoverage(k/4): samples 0..k-1), for
//     k = 1, 2, 3 and several A: the resolve's rounding, mirrored exactly (EGL GLES 3.0, OSMesa GL 3.3);
//   - the C fallback's multisampled frame equals its one-sample frame on every interior pixel
//     (one triangle robustly covers every sample: shaded once at the centre with the one-sample
//     barycentrics, so bit for bit) of the shipped model scenes.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/float_target.h"
#include "scene/frame.h"
#include "scene/msaa.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/prepare.h"
#include "shaderlib/assembler.h"
#include "unit_check.h"
#include "unit_gl.h"

namespace {

void test_equal_codes() {
  long bad = 0;
  for (int n : {2, 4, 8})
    for (int c = 0; c < 256; ++c) {
      uint8_t codes[8];
      for (int k = 0; k < n; ++k) codes[k] = static_cast<uint8_t>(c);
      bad += msaa_resolve_unorm8(codes, n, 1) != c;
    }
  check(bad == 0, "resolve of n equal codes is that code (n = 2, 4, 8; 256 codes)", std::to_string(bad) + " differ");
  check(msaa_pattern(4)[1][0] * 256 == 224 && msaa_pattern(4)[3][1] * 256 == 224 && !msaa_pattern(3),
        "4x pattern: llvmpipe's lp_sample_pos_4x in 1/256 pixel");
}

void test_gl_resolve(Backend b, Api api) {
  const std::string name = config_name(b, api);
  auto ctx = open_context(b, api, name + " MSAA resolve");
  if (!ctx) return;
  const GlFns &g = ctx->gl();
  GLint max_samples = 0;
  g.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  check(max_samples == 4, name + ": llvmpipe's GL_MAX_SAMPLES is 4", std::to_string(max_samples));
  const int W = 256, H = 256;
  GLuint rb = 0, fbo = 0, rfbo = 0;
  g.GenRenderbuffers(1, &rb);
  g.BindRenderbuffer(GL_RENDERBUFFER, rb);
  g.RenderbufferStorageMultisample(GL_RENDERBUFFER, 2, GL_RGBA8, W, H);
  GLint got = 0;
  g.GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &got);
  check(got == 4, name + ": a request for 2 samples allocates 4", std::to_string(got));
  g.GenFramebuffers(1, &fbo);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  const GLuint tex = new_target_texture(g, GL_RGBA8, GL_UNSIGNED_BYTE, W, H);
  g.GenFramebuffers(1, &rfbo);
  g.BindFramebuffer(GL_FRAMEBUFFER, rfbo);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  const std::string head = api == Api::GL33 ? "#version 330 core\n" : "#version 300 es\nprecision highp float;\n";
  Assembled vs, fs;
  vs.text = head + "void main() { vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));\n"
                   "gl_Position = vec4(p, 0.0, 1.0); }\n";
  fs.text = head + "out vec4 o;\nvoid main() { vec2 p = floor(gl_FragCoord.xy);\n"
                   "o = vec4(p.x, p.y, mod(p.x + p.y, 256.0), 255.0) / 255.0; }\n";
  vs.files = fs.files = {"test_msaa"};
  GlRenderer r(*ctx);
  std::string err;
  const GLuint prog = r.build_program(vs, fs, &err);
  if (!prog) {
    check(false, name + ": resolve program", err);
    return;
  }
  GLuint vao = 0;
  g.GenVertexArrays(1, &vao);
  g.BindVertexArray(vao);
  long bad = 0, n = 0;
  std::string first;
  std::vector<uint8_t> out(static_cast<size_t>(W) * H * 4);
  for (int a : {0, 1, 2, 3, 64, 127, 128, 200, 254, 255})
    for (int k = 1; k <= 3; ++k) {
      g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
      g.Viewport(0, 0, W, H);
      g.Disable(GL_SAMPLE_COVERAGE);
      g.ClearColor(a / 255.f, a / 255.f, a / 255.f, a / 255.f);
      g.Clear(GL_COLOR_BUFFER_BIT);
      g.Enable(GL_SAMPLE_COVERAGE);
      g.SampleCoverage(k / 4.f, GL_FALSE);
      g.UseProgram(prog);
      g.DrawArrays(GL_TRIANGLES, 0, 3);
      g.Disable(GL_SAMPLE_COVERAGE);
      g.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
      g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, rfbo);
      g.BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      g.BindFramebuffer(GL_FRAMEBUFFER, rfbo);
      g.PixelStorei(GL_PACK_ALIGNMENT, 4);
      g.ReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          const int bcode[4] = {x, y, (x + y) & 255, 255};
          for (int c = 0; c < 4; ++c) {
            uint8_t s[4];
            for (int i = 0; i < 4; ++i) s[i] = static_cast<uint8_t>(i < k ? bcode[c] : a);
            const uint8_t want = msaa_resolve_unorm8(s, 4, 1), have = out[(static_cast<size_t>(y) * W + x) * 4 + c];
            ++n;
            if (want != have && bad++ == 0)
              first = "A " + std::to_string(a) + " B " + std::to_string(bcode[c]) + " k " + std::to_string(k) +
                  ": GL " + std::to_string(have) + ", C " + std::to_string(want);
          }
        }
    }
  check(g.GetError() == GL_NO_ERROR && n > 0 && bad == 0,
        name + ": glBlitFramebuffer's 4x RGBA8 resolve == msaa_resolve_unorm8 (" + std::to_string(n) + " channels)",
        std::to_string(bad) + " differ; first " + first);
  g.DeleteVertexArrays(1, &vao);
  r.delete_program(prog);
  g.DeleteFramebuffers(1, &fbo);
  g.DeleteFramebuffers(1, &rfbo);
  g.DeleteRenderbuffers(1, &rb);
  g.DeleteTextures(1, &tex);
}

void test_cpu_interior() {
  for (const char *scene : {"scenes/model_lighting.gltf", "scenes/phong_sphere.gltf", "scenes/probe_chart.gltf"}) {
    Scene s;
    SceneSelection sel;
    PreparedScene p;
    std::string err;
    if (!load_scene(scene, &s, &err) || !select_scene_variants(s, Tier::SM3, "integer", &sel, &err) ||
        !prepare_scene(s, sel, 320, 180, Api::GL33, s.hdr.tone_map_scale, &p, &err)) {
      check(false, std::string(scene) + ": prepare", err);
      continue;
    }
    SceneRenderConfig one;
    one.backend = Backend::CPU;
    one.w = 320;
    one.h = 180;
    SceneRenderResult r1;
    if (!render_scene(s, sel, one, &r1, &err)) {
      check(false, std::string(scene) + ": one-sample frame", err);
      continue;
    }
    for (int n : {2, 4, 8}) {
      MsaaFrameC f;
      scene_render_msaa_cpu(p, n, &f, 0);
      long interior = 0, bad = 0;
      for (size_t i = 0; i < f.interior.size(); ++i) {
        if (!f.interior[i]) continue;
        ++interior;
        for (int c = 0; c < 3; ++c) bad += f.display[i * 4 + c] != r1.display[i * 4 + c];
      }
      check(interior > 100 && bad == 0,
            std::string(scene) + " " + std::to_string(n) + "x: C MSAA == C one-sample frame on " +
                std::to_string(interior) + " interior pixels",
            std::to_string(bad) + " channels differ");
    }
  }
}

}  // namespace

int main() {
  test_equal_codes();
  test_gl_resolve(Backend::EGL, Api::GLES3);
  test_gl_resolve(Backend::OSMesa, Api::GL33);
  test_cpu_interior();
  return finish();
}

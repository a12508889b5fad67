// tiershade tests: the C fallback's own rasteriser against llvmpipe, varying by varying
// (glue/scene/lp_interp.h), bit for bit. (1) Single triangles through a pass-through shader
// (the interpolated vec4 written to an RGBA32F target) against lp_setup_tri + lp_interp_span:
// orthographic and perspective, tiny, sliver and huge triangles, clipped by every plane, with
// attributes of large and small magnitudes. (2) The G-buffer records (the 6 pixel slots every
// production fragment shader receives) of the shipped scenes drawn by GL and by the C
// rasteriser, on the pixels both give to the same draw. Both must differ in 0 bits.
#include <cstdio>
#include <cstring>
#include <random>
#include <memory>
#include <string>
#include <vector>

#include "gl/float_target.h"
#include "scene/lp_interp.h"
#include "scene/cpu_renderer.h"
#include "scene/gl_renderer.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "unit_check.h"
#include "unit_gl.h"

using unit_check::check;

namespace {

struct Count {
  long cover_diff = 0, both = 0, exact = 0, floats = 0, float_diff = 0;
  long grad_nonzero = 0, grad_diff = 0;  // the uv's quad derivatives (mipmaps' level of detail)
};

// GL's and the C fallback's records of one scene at w x h.
// GL's and the C fallback's records of one scene at w x h: c[0] from the C rasteriser's
// barycentrics alone (the interpolation before lp_interp), c[1] with llvmpipe's set-up.
bool compare_scene(const char *name, int w, int h, GlContext &ctx, Count c[2], std::string *err) {
  Scene s;
  SceneSelection sel;
  PreparedScene p;
  if (!load_scene(name, &s, err) || !select_scene_variants(s, Tier::SM3, "", &sel, err) ||
      !prepare_scene(s, sel, w, h, Api::GL33, 1.f, &p, err))
    return false;
  GlRenderer r(ctx);
  SceneGl g(r, Api::GL33);
  std::vector<int> gd;
  std::vector<float> gs, gg;
  if (!g.init(p, err) || !g.gbuffer(&gd, &gs, err, &gg)) return false;
  SceneVisibility vis;
  scene_rasterize_cpu(p, &vis);
  for (int planes = 0; planes < 2; ++planes) {
    std::vector<int> cd;
    std::vector<float> cs, cg;
    vis.pixel_planes = planes == 1;
    scene_records_cpu(p, vis, &cd, &cs, 0, &cg);
    const size_t n = static_cast<size_t>(w) * h;
    for (size_t i = 0; i < n; ++i) {
      if (gd[i] != cd[i]) {
        ++c[planes].cover_diff;
        continue;
      }
      if (gd[i] < 0) continue;
      ++c[planes].both;
      bool same = true;
      for (int k = 0; k < 4; ++k) {
        c[planes].grad_nonzero += gg[i * 4 + k] != 0.f;
        c[planes].grad_diff += std::memcmp(&gg[i * 4 + k], &cg[i * 4 + k], 4) != 0;
      }
      for (int k = 0; k < 24; ++k) {
        // A slot the variant does not have is vec4(0) on GL (scene_gbuffer.fs): not compared.
        const float *slot = &gs[i * 24 + (k / 4) * 4];
        if (slot[0] == 0.f && slot[1] == 0.f && slot[2] == 0.f && slot[3] == 0.f) continue;
        ++c[planes].floats;
        if (std::memcmp(&gs[i * 24 + k], &cs[i * 24 + k], 4) != 0) {
          ++c[planes].float_diff;
          same = false;
        }
      }
      c[planes].exact += same;
    }
  }
  return true;
}

// One vertex of a test triangle: clip position and one vec4 attribute.
struct TVert {
  float clip[4], attr[4];
};

// A random test triangle of kind k (0 orthographic inside, 1 orthographic past the edges,
// 2 perspective, 3 perspective through the near and far planes, 4 tiny, 5 sliver, 6 huge).
void make_tri(std::mt19937 &rng, int k, TVert t[3]) {
  std::uniform_real_distribution<float> u(-1.f, 1.f), pos(0.f, 1.f);
  const float mag[4] = {1.f, 1e4f, 1e-3f, 3e5f};
  for (int v = 0; v < 3; ++v) {
    float x = u(rng), y = u(rng), z = u(rng) * 0.9f, w = 1.f;
    if (k == 1) x *= 1.8f, y *= 1.8f;
    if (k == 2 || k == 3) w = 0.2f + 4.f * pos(rng), x *= 1.4f * w, y *= 1.4f * w, z *= w;
    if (k == 3) z = (1.6f * u(rng)) * w;
    if (k == 4 && v > 0) x = t[0].clip[0] + 0.03f * u(rng), y = t[0].clip[1] + 0.03f * u(rng);
    if (k == 5 && v == 1) x = t[0].clip[0] + 0.002f * u(rng), y = t[0].clip[1] + 0.5f * u(rng);
    if (k == 6) x *= 60.f, y *= 60.f;
    const float c[4] = {x, y, z, w};
    std::memcpy(t[v].clip, c, sizeof c);
    for (int i = 0; i < 4; ++i) t[v].attr[i] = u(rng) * mag[i] + (i == 3 ? 1e5f : 0.f);
  }
}

void test_triangles() {
  std::unique_ptr<GlContext> ctx = open_context(Backend::EGL, Api::GL33, "raster exact triangles: EGL GL 3.3");
  if (!ctx) return;
  GlRenderer r(*ctx);
  const GlFns &g = r.gl();
  const Assembled vs{"#version 330 core\nin vec4 a_clip;\nin vec4 a_attr;\nout vec4 v_attr;\n"
                     "void main() { gl_Position = a_clip; v_attr = a_attr; }\n", {"test_vs"}};
  const Assembled fs{"#version 330 core\nin vec4 v_attr;\nout vec4 o;\nvoid main() { o = v_attr; }\n", {"test_fs"}};
  std::string err;
  const GLuint prog = r.build_program(vs, fs, &err);
  if (!prog) {
    check(false, "raster exact triangles: pass-through program", err);
    return;
  }
  const int W = 64, H = 48;
  const GLuint tex = new_target_texture(g, GL_RGBA32F, GL_FLOAT, W, H);
  GLuint fbo = 0, vao = 0, vbo = 0;
  g.GenFramebuffers(1, &fbo);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  g.GenVertexArrays(1, &vao);
  g.BindVertexArray(vao);
  g.GenBuffers(1, &vbo);
  g.BindBuffer(GL_ARRAY_BUFFER, vbo);
  const GLint lc = g.GetAttribLocation(prog, "a_clip"), la = g.GetAttribLocation(prog, "a_attr");
  g.VertexAttribPointer(static_cast<GLuint>(lc), 4, GL_FLOAT, GL_FALSE, sizeof(TVert), nullptr);
  g.VertexAttribPointer(static_cast<GLuint>(la), 4, GL_FLOAT, GL_FALSE, sizeof(TVert),
                        reinterpret_cast<const void *>(4 * sizeof(float)));
  g.EnableVertexAttribArray(static_cast<GLuint>(lc));
  g.EnableVertexAttribArray(static_cast<GLuint>(la));
  g.UseProgram(prog);
  g.Viewport(0, 0, W, H);
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_CULL_FACE);
  const float kClear = -7777.f;  // no attribute takes this value
  std::mt19937 rng(1234);
  std::vector<float> img(static_cast<size_t>(W) * H * 4);
  long pixels = 0, cover_diff = 0, float_diff = 0, clipped = 0;
  const int used[1] = {0};
  std::string first;
  for (int n = 0; n < 7 * 40; ++n) {
    const int kind = n % 7;
    TVert t[3];
    make_tri(rng, kind, t);
    g.BufferData(GL_ARRAY_BUFFER, sizeof t, t, GL_STREAM_DRAW);
    g.ClearColor(kClear, kClear, kClear, kClear);
    g.Clear(GL_COLOR_BUFFER_BIT);
    g.DrawArrays(GL_TRIANGLES, 0, 3);
    g.ReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, img.data());
    LpVert in[3];
    int m[3];
    for (int v = 0; v < 3; ++v) {
      std::memcpy(in[v].clip, t[v].clip, sizeof in[v].clip);
      lp_window_pos(in[v].clip, static_cast<float>(W), static_cast<float>(H), in[v].win);
      std::memset(in[v].attr, 0, sizeof in[v].attr);
      std::memcpy(in[v].attr, t[v].attr, sizeof t[v].attr);
      m[v] = lp_clipmask(in[v].clip);
    }
    LpTriSet set;
    lp_setup_tri(in, m, static_cast<float>(W), static_cast<float>(H), used, 1, &set);
    clipped += set.clipped;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const float *gp = &img[(static_cast<size_t>(y) * W + x) * 4];
        const bool gl_in = gp[0] != kClear;
        const int s = lp_covering(set, x, y);
        if (gl_in != (s >= 0)) {
          ++cover_diff;
          continue;
        }
        if (!gl_in) continue;
        ++pixels;
        ts_vec4f c;
        lp_interp_span(set.pl[s], x, y, 1, used, 1, &c, 1, 0);
        if (std::memcmp(&c, gp, sizeof c) != 0 && float_diff++ == 0)
          first = "triangle " + std::to_string(n) + " kind " + std::to_string(kind) + " pixel " + std::to_string(x) +
              "," + std::to_string(y) + ": GL " + std::to_string(gp[0]) + " C " + std::to_string(c.x);
      }
  }
  g.DeleteBuffers(1, &vbo);
  g.DeleteVertexArrays(1, &vao);
  g.DeleteFramebuffers(1, &fbo);
  g.DeleteTextures(1, &tex);
  r.delete_program(prog);
  printf("INFO triangles: %ld pixels (%ld triangles clipped), coverage differs on %ld, %ld differ in value\n", pixels,
         clipped, cover_diff, float_diff);
  check(pixels > 10000 && cover_diff == 0 && float_diff == 0,
        "raster exact triangles: llvmpipe's coverage and varyings, bit for bit", first);
}

void test_scenes() {
  std::unique_ptr<GlContext> ctx = open_context(Backend::EGL, Api::GL33, "raster exact: EGL GL 3.3 context");
  if (!ctx) return;
  for (const char *name : {"scenes/model_lighting.gltf", "scenes/world_lighting.gltf", "scenes/hdr_atrium.gltf",
                           "scenes/sphere_grid.gltf", "scenes/phong_sphere.gltf", "scenes/probe_chart.gltf",
                           "scenes/lightmap_charts.gltf", "scenes/hdr_daylight.gltf", "scenes/large_hall_40.gltf"}) {
    for (int sw : {96, 160}) {
      const int sh = sw * 9 / 16;
      Count c[2];
      std::string err;
      if (!compare_scene(name, sw, sh, *ctx, c, &err)) {
        check(false, std::string("raster exact: ") + name, err);
        continue;
      }
      for (int planes = 0; planes < 2; ++planes)
        printf("INFO %s %dx%d, %s: coverage differs on %ld pixels; %ld of %ld shared pixels with bit-identical records, "
               "%ld of %ld floats differ\n",
               name, sw, sh, planes ? "llvmpipe's set-up" : "barycentrics", c[planes].cover_diff, c[planes].exact, c[planes].both,
               c[planes].float_diff, c[planes].floats);
      check(c[1].both > 0 && c[1].cover_diff == 0 && c[1].float_diff == 0,
            std::string("raster exact: ") + name + " " + std::to_string(sw) + "x" + std::to_string(sh) +
                ": the C rasteriser's records are GL's, bit for bit",
            std::to_string(c[1].cover_diff) + " pixels of another draw, " + std::to_string(c[1].float_diff) +
                " floats differ");
      // The derivatives llvmpipe's sampler takes (scene_gbuffer.fs slot 6) against the C
      // fallback's from the triangles' planes (cpu_renderer.cpp uv_grad_run): 0 bits apart, and
      // not all zero (every shipped scene has textured draws).
      check(c[1].grad_nonzero > 0 && c[1].grad_diff == 0,
            std::string("raster exact: ") + name + " " + std::to_string(sw) + "x" + std::to_string(sh) +
                ": the uv's quad derivatives are llvmpipe's, bit for bit (" + std::to_string(c[1].grad_nonzero) +
                " non-zero)",
            std::to_string(c[1].grad_diff) + " of " + std::to_string(c[1].both * 4) + " derivatives differ");
    }
  }
}

}  // namespace

int main() {
  ts_math_init();
  test_triangles();
  test_scenes();
  return unit_check::finish();
}

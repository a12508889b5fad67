// tiershade tests: the HDR skybox (glue/scene/skybox_pass.h, shaders/skybox.fs):
//   * the shipped room (scenes/world_lighting.gltf, its window onto scenes/textures/day_sky.hdr):
//     GL's frame equals the C twin on GL's G-buffer bit for bit, the sky's pixels included, on
//     gl33 (LINEAR cube) and gles3 (NEAREST); the C fallback's own frame equals GL's bit for bit
//     on every pixel both leave to the sky;
//   * the sky is visible through the window, and there equals the sky's radiance in the pixel's
//     direction (the lat-long's bilinear lookup of the bake, glue/bake/sky.h, on a direction
//     unprojected from the inverse view-projection) times its scale and the tone-map scale,
//     within the stated bound;
//   * a scene without a sky selects no skybox variant, makes no cube and leaves the background 0;
//   * the camera vectors: perspective and orthographic.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "bake/sky.h"
#include "gl/float_target.h"
#include "scene/cpu_renderer.h"
#include "scene/frame.h"
#include "scene/gl_renderer.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/skybox_pass.h"
#include "unit_check.h"
#include "unit_gl.h"

using unit_check::check;

namespace {

const char kRoom[] = "scenes/world_lighting.gltf";
const int kW = 160, kH = 90;

// The world direction through pixel (x, y)'s centre, by unprojecting ndc z = -1 and 1 through
// the inverse of the view-projection (double): independent of skybox_camera_vectors.
glm::dvec3 unprojected_direction(const PreparedScene &p, int x, int y) {
  glm::dmat4 m;
  for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = p.view_proj[i];
  const glm::dmat4 inv = glm::inverse(m);
  const double nx = (x + 0.5) / p.w * 2 - 1, ny = (y + 0.5) / p.h * 2 - 1;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  return glm::dvec3(b) / b.w - glm::dvec3(a) / a.w;
}

void test_room(Api api) {
  const std::string cfg = config_name(Backend::EGL, api);
  Scene s;
  SceneSelection sel;
  std::string err;
  if (!load_scene(kRoom, &s, &err) || !select_scene_variants(s, Tier::SM3, "integer", &sel, &err)) {
    check(false, "load the room", err);
    return;
  }
  check(s.sky.image >= 0 && sel.sky != nullptr && sel.sky->shader->name == "skybox",
        "the room has a sky: the selection has its skybox variant");
  PreparedScene p;
  if (!prepare_scene(s, sel, kW, kH, api, s.hdr.tone_map_scale, &p, &err)) {
    check(false, cfg + ": prepare the room", err);
    return;
  }
  check(p.sky.present() && p.sky.cube.kind == TexKind::Cube && p.sky.cube.linear == (api == Api::GL33),
        cfg + ": the sky's cube is made (LINEAR on gl33, NEAREST on GLES)");
  auto ctx = open_context(Backend::EGL, api, cfg + ": the skybox checks");
  if (!ctx) return;
  GlRenderer r(*ctx);
  SceneGl g(r, api);
  ImageF gl_lit;
  std::vector<int> gl_draw;
  std::vector<float> slots, grads;
  if (!g.init(p, &err) || !g.frame(&gl_lit, &err) || !g.gbuffer(&gl_draw, &slots, &err, &grads)) {
    check(false, cfg + ": GL frame of the room", err);
    return;
  }
  // GL against the C twin on GL's own G-buffer: every pixel, the sky's included.
  ImageF c_on_gl;
  scene_shade_records(p, gl_draw, slots, &c_on_gl, 0, &grads);
  long diff = 0, sky_px = 0;
  for (size_t i = 0; i < gl_lit.rgba.size(); ++i)
    diff += unit_check::bits_of(gl_lit.rgba[i]) != unit_check::bits_of(c_on_gl.rgba[i]);
  for (int d : gl_draw) sky_px += d < 0;
  check(diff == 0, cfg + ": GL frame = C twin on GL's G-buffer bit for bit, sky pixels included",
        std::to_string(diff) + " channels differ");
  // The window: the sky covers a visible part of the frame (at 160x90 the window is about 8%).
  check(sky_px >= kW * kH / 50, cfg + ": the sky is visible through the window",
        std::to_string(sky_px) + " of " + std::to_string(kW * kH) + " pixels");
  // The C fallback's own frame (its rasteriser): equal to GL's on every pixel both leave to the
  // sky. On GLES the C fallback's cube is the same NEAREST one (prepared with the same api).
  SceneVisibility vis;
  scene_rasterize_cpu(p, &vis);
  ImageF c_lit;
  scene_shade_cpu(p, vis, &c_lit);
  long both = 0, same = 0, c_sky = 0;
  for (size_t i = 0; i < gl_draw.size(); ++i) {
    c_sky += vis.draw[i] < 0;
    if (gl_draw[i] >= 0 || vis.draw[i] >= 0) continue;
    ++both;
    bool eq = true;
    for (int c = 0; c < 4; ++c) eq = eq && unit_check::bits_of(gl_lit.rgba[i * 4 + c]) == unit_check::bits_of(c_lit.rgba[i * 4 + c]);
    same += eq;
  }
  // Coverage may differ on edge pixels where the two rasterisers' tie rules disagree (at most 1%
  // of the frame, test_scene_render's bound); the sky itself may not differ by one bit.
  check(same == both && both > 0 && std::abs(c_sky - sky_px) <= kW * kH / 100,
        cfg + ": C fallback's sky = GL's bit for bit",
        std::to_string(same) + " of " + std::to_string(both) + " equal; sky pixels C " + std::to_string(c_sky) +
            ", GL " + std::to_string(sky_px));
  // The sky's expected radiance. The cube's texels are bilinear lookups of the lat-long (each a
  // convex combination of the 4 lat-long texels around its direction), and the shader's lookup is
  // a bilinear (gl33) or nearest (GLES) combination of the cube texels within one cube texel of the
  // pixel's direction: so the lit value lies between the smallest and the largest lat-long texel
  // within one lat-long texel plus one cube texel of that direction, times scale and tone-map
  // scale. Bound: that envelope, widened by 0.2% (fp16 texels round to 11 bits, 0.05%; float
  // products). Window: +-2 texels in v and +-2 / cos(latitude) in u (a cube texel spans at most
  // 2 / n radians, n = face size >= w, i.e. under a third of a lat-long texel). The mean error
  // against the lat-long's own bilinear lookup (glue/bake/sky.h) is printed, not judged: the
  // window's bottom rows look at the sharp horizon of day_sky.hdr, which both filters smear.
  const SceneImage &si = s.images.at(static_cast<size_t>(s.sky.image));
  const BakeSky lat{si.rgba.data(), si.w, si.h, s.sky.scale, 1};
  const double k = static_cast<double>(s.sky.scale) * p.tone_map_scale;
  double sum_rel = 0;
  long n = 0, outside = 0;
  std::string first;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const size_t i = static_cast<size_t>(y) * kW + x;
      if (gl_draw[i] >= 0) continue;
      const glm::dvec3 d = glm::normalize(unprojected_direction(p, x, y));
      const ts_vec3d e = sky_radiance(lat, ts_v3d(d.x, d.y, d.z));
      // The lat-long texel of d (glue/bake/sky.h's convention: row 0 the bottom).
      const double u = std::atan2(d.x, -d.z) / (2 * M_PI) + 0.5, v = std::acos(std::clamp(d.y, -1.0, 1.0)) / M_PI;
      const double fx = u * si.w - 0.5, fy = (1 - v) * si.h - 0.5;
      const double coslat = std::max(1e-3, std::sqrt(std::max(0.0, 1 - d.y * d.y)));
      const int ru = static_cast<int>(std::min<double>(si.w / 2, std::ceil(2 / coslat)));
      double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {0, 0, 0};
      for (int yy = static_cast<int>(std::floor(fy)) - 2; yy <= static_cast<int>(std::floor(fy)) + 3; ++yy)
        for (int xx = static_cast<int>(std::floor(fx)) - ru; xx <= static_cast<int>(std::floor(fx)) + 1 + ru; ++xx) {
          const int cy = std::clamp(yy, 0, si.h - 1), cx = ((xx % si.w) + si.w) % si.w;
          const float *t = &si.rgba[(static_cast<size_t>(cy) * si.w + cx) * 4];
          for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], double(t[c])), hi[c] = std::max(hi[c], double(t[c]));
        }
      const double ex[3] = {e.x * p.tone_map_scale, e.y * p.tone_map_scale, e.z * p.tone_map_scale};
      for (int c = 0; c < 3; ++c) {
        const double got = gl_lit.rgba[i * 4 + c];
        sum_rel += std::fabs(got - ex[c]) / std::max(ex[c], 1e-3);
        ++n;
        if (got < lo[c] * k * (1 - 2e-3) || got > hi[c] * k * (1 + 2e-3)) {
          if (outside++ == 0)
            first = "pixel " + std::to_string(x) + "," + std::to_string(y) + " channel " + std::to_string(c) + ": " +
                std::to_string(got) + " outside [" + std::to_string(lo[c] * k) + ", " + std::to_string(hi[c] * k) + "]";
        }
      }
    }
  printf("INFO %s: %ld sky pixels; mean relative difference from the lat-long's bilinear radiance %.2f%%\n",
         cfg.c_str(), sky_px, n ? 100 * sum_rel / n : 0.0);
  check(n > 0 && outside == 0, cfg + ": the window shows the sky's radiance x scale x tone map (within the texel envelope)",
        std::to_string(outside) + " channels outside; first " + first);
}

void test_no_sky() {
  Scene s;
  SceneSelection sel;
  std::string err;
  if (!load_scene(kRoom, &s, &err)) {
    check(false, "load the room", err);
    return;
  }
  s.sky.image = -1;  // the same room without its sky
  if (!select_scene_variants(s, Tier::SM3, "integer", &sel, &err)) {
    check(false, "select the room without a sky", err);
    return;
  }
  bool any = sel.sky != nullptr;
  for (const Variant &v : sel.variants) any = any || v.shader->name == "skybox";
  for (const Variant *v : sel.all_variants) any = any || v->shader->name == "skybox";
  check(!any, "no sky: no skybox variant (selected or in the baseline)");
  PreparedScene p;
  if (!prepare_scene(s, sel, kW, kH, Api::GL33, s.hdr.tone_map_scale, &p, &err)) {
    check(false, "prepare the room without a sky", err);
    return;
  }
  check(!p.sky.present() && p.sky.cube.rgba.empty(), "no sky: no cube map, no skybox record");
  SceneRenderConfig cfg;
  cfg.w = kW;
  cfg.h = kH;
  cfg.api = Api::GL33;
  cfg.check = true;
  SceneRenderResult res;
  if (!render_scene(s, sel, cfg, &res, &err)) {
    check(false, "render the room without a sky", err);
    return;
  }
  SceneVisibility vis;
  scene_rasterize_cpu(p, &vis);
  long bg = 0, nonzero = 0;
  for (size_t i = 0; i < vis.draw.size(); ++i) {
    if (vis.draw[i] >= 0) continue;
    ++bg;
    for (int k = 0; k < 4; ++k) nonzero += res.check_lit.rgba[i * 4 + k] != 0.f;
  }
  check(bg > 0 && nonzero == 0, "no sky: the window's pixels stay 0 (no skybox drawn)",
        std::to_string(nonzero) + " non-zero channels on " + std::to_string(bg) + " background pixels");
}

void test_camera_vectors() {
  // A perspective camera: the vectors reproduce the unprojected direction of any pixel.
  const glm::dmat4 proj = glm::perspective(0.9, 16.0 / 9.0, 0.1, 100.0);
  const glm::dmat4 view = glm::lookAt(glm::dvec3(1, 2, 3), glm::dvec3(-2, 1.5, -4), glm::dvec3(0, 1, 0));
  const glm::dmat4 vp = proj * view;
  float m[16];
  for (int i = 0; i < 16; ++i) m[i] = static_cast<float>(glm::value_ptr(vp)[i]);
  double f[3], r[3], u[3];
  skybox_camera_vectors(m, f, r, u);
  glm::dmat4 mf;
  for (int i = 0; i < 16; ++i) glm::value_ptr(mf)[i] = m[i];
  const glm::dmat4 inv = glm::inverse(mf);
  double worst = 0;
  for (double nx : {-1.0, -0.3, 0.0, 0.7, 1.0})
    for (double ny : {-1.0, 0.2, 1.0}) {
      const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
      const glm::dvec3 want = glm::normalize(glm::dvec3(b) / b.w - glm::dvec3(a) / a.w);
      const glm::dvec3 got = glm::normalize(glm::dvec3(f[0], f[1], f[2]) + nx * glm::dvec3(r[0], r[1], r[2]) +
                                            ny * glm::dvec3(u[0], u[1], u[2]));
      worst = std::max(worst, glm::length(got - want));
    }
  // float matrix entries: directions agree to float rounding (1e-6 of a unit vector).
  check(worst < 1e-5, "camera vectors: perspective directions = unprojected ones", std::to_string(worst));
  // Orthographic: one direction, the view axis.
  const glm::dmat4 ortho = glm::ortho(-2.0, 2.0, -1.0, 1.0, 0.1, 50.0) * view;
  for (int i = 0; i < 16; ++i) m[i] = static_cast<float>(glm::value_ptr(ortho)[i]);
  skybox_camera_vectors(m, f, r, u);
  const glm::dvec3 axis = glm::normalize(glm::dvec3(-2, 1.5, -4) - glm::dvec3(1, 2, 3));
  const glm::dvec3 got = glm::normalize(glm::dvec3(f[0], f[1], f[2]));
  check(glm::length(got - axis) < 1e-5 && r[0] == 0 && r[1] == 0 && r[2] == 0 && u[0] == 0 && u[1] == 0 && u[2] == 0,
        "camera vectors: orthographic looks along the view axis", std::to_string(glm::length(got - axis)));
}

}  // namespace

int main() {
  ts_math_init();
  test_camera_vectors();
  test_room(Api::GL33);
  test_room(Api::GLES3);
  test_no_sky();
  return unit_check::finish();
}

// tiershade scene: the HDR skybox pass (glue/scene/skybox_pass.h): the sky's cube, its record,
// the C twin on the background pixels and the GL full-screen draw.
#include "scene/skybox_pass.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "bake/sky.h"
#include "base/cube_faces.h"
#include "base/parallel_rows.h"
#include "conform/conform.h"
#include "families/family.h"
#include "gl/errors.h"
#include "math/hdr_formats.h"
#include "scene/finite_check.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "twins/skybox.h"

int skybox_face_size(int lat_long_w) { return std::clamp(lat_long_w, 16, 512); }

void skybox_camera_vectors(const float view_proj[16], double forward[3], double right[3], double up[3]) {
  // Row r of the matrix (column-major): m[r], m[4 + r], m[8 + r] on a direction (w = 0).
  auto row = [&](int r) { return glm::dvec3(view_proj[r], view_proj[4 + r], view_proj[8 + r]); };
  const glm::dvec3 rx = row(0), ry = row(1), rz = row(2), rw = row(3);
  // Perspective: the eye projects to clip (0, 0, z, 0), so a direction d from the eye lands at
  // ndc x = rx.d / rw.d, y = ry.d / rw.d: d = A^-1 (x, y, 1) with A's rows rx, ry, rw (rw.d = 1 > 0:
  // in front of the camera).
  const glm::dmat3 At(rx, ry, rw);  // glm: columns; this is A transposed
  const glm::dmat3 A = glm::transpose(At);
  const double det = glm::determinant(A);
  const double scale = glm::length(rx) * glm::length(ry) * glm::length(rw);
  glm::dvec3 f, r, u;
  if (std::fabs(det) > 1e-12 * scale) {
    const glm::dmat3 inv = glm::inverse(A);
    r = inv[0];
    u = inv[1];
    f = inv[2];
  } else {
    // Orthographic (rw = (0, 0, 0)): the view axis, the direction no pixel moves along, towards
    // increasing depth (ndc z grows away from the camera).
    f = glm::cross(rx, ry);
    if (glm::dot(f, rz) < 0) f = -f;
    r = u = glm::dvec3(0.0);
  }
  for (int k = 0; k < 3; ++k) forward[k] = f[k], right[k] = r[k], up[k] = u[k];
}

void skybox_set_camera(PreparedSky *sky, const float view_proj[16], int w, int h) {
  double f[3], r[3], u[3];
  skybox_camera_vectors(view_proj, f, r, u);
  sky->shared.resize(SB_SLOTS, ts_v4f(0, 0, 0, 0));
  sky->shared[SB_SLOT_SIZE] =
      ts_v4f(static_cast<float>(w), static_cast<float>(h), 1.0f / static_cast<float>(w), 1.0f / static_cast<float>(h));
  auto v3 = [](const double *a) {
    return ts_v4f(static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2]), 0.f);
  };
  sky->shared[SB_SLOT_FORWARD] = v3(f);
  sky->shared[SB_SLOT_RIGHT] = v3(r);
  sky->shared[SB_SLOT_UP] = v3(u);
}

bool prepare_skybox(const Scene &s, const Variant *sel_variant, Api api, PreparedScene *p, std::string *err) {
  PreparedSky &sky = p->sky;
  sky = PreparedSky();
  if (!sel_variant || s.sky.image < 0) return true;  // no sky: no cube, no record, no pass
  const SceneImage &si = s.images.at(static_cast<size_t>(s.sky.image));
  // The bake's own lookup of the lat-long (glue/bake/sky.h: bilinear, wrapping in u), unscaled:
  // the scale is the shader's (u_sky_color, Source's $color).
  const BakeSky lat{si.rgba.data(), si.w, si.h, 1.0, 1};
  const int n = skybox_face_size(si.w);
  TextureDesc &c = sky.cube;
  c.sampler = "u_sky";
  c.kind = TexKind::Cube;
  c.w = c.h = n;
  c.linear = api == Api::GL33;  // GLES cube maps are always seamless (docs/conformance.md)
  c.rgba.assign(static_cast<size_t>(6) * n * n * 4, 1.f);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::dvec3 d = cube_face_direction(f, (x + 0.5) / n * 2 - 1, (y + 0.5) / n * 2 - 1);
        const ts_vec3d rad = sky_radiance(lat, ts_v3d(d.x, d.y, d.z));
        float *t = &c.rgba[((static_cast<size_t>(f) * n + y) * n + x) * 4];
        t[0] = static_cast<float>(rad.x), t[1] = static_cast<float>(rad.y), t[2] = static_cast<float>(rad.z);
      }
  // Stored as Source's float-HDR sky is (fp16 texels): clamped to 65504, rounded to half.
  if (!clamp_texels_to_fp16(c.rgba.data(), c.rgba.size(), s.path + ": the sky's cube map", nullptr, err)) return false;
  for (float &v : c.rgba) v = ts_quantize_half(v);
  sky.shared.assign(SB_SLOTS, ts_v4f(0, 0, 0, 0));
  skybox_set_camera(&sky, p->view_proj, p->w, p->h);
  const float k = s.sky.scale;
  sky.shared[SB_SLOT_COLOR] = ts_v4f(k, k, k, p->tone_map_scale);
  if (!check_finite(&sky.shared.data()->x, sky.shared.size() * 4, "the skybox's uniforms", err)) return false;
  sky.variant = sel_variant;
  return true;
}

void skybox_set_tone_map_scale(PreparedSky *sky, float scale) {
  if (sky->present()) sky->shared[SB_SLOT_COLOR].w = scale;
}

void skybox_record(const PreparedSky &sky, int x, int y, ts_vec4f rec[]) {
  std::copy(sky.shared.begin(), sky.shared.end(), rec);
  rec[SB_SLOT_POS] = ts_v4f(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, 0.f, 0.f);
}

void skybox_shade_row(const PreparedSky &sky, int w, int y, const int *draw_row, float *rgba_row) {
  if (!sky.present()) return;
  const ts_texcube cube = texcube_of(sky.cube);
  const sb_variant v = {tier_id(sky.variant->tier)};
  ts_vec4f rec[SB_SLOTS];
  for (int x = 0; x < w; ++x) {
    if (draw_row[x] >= 0) continue;
    skybox_record(sky, x, y, rec);
    const ts_vec4f c = skybox_f(&v, rec, &cube);
    float *o = rgba_row + static_cast<size_t>(x) * 4;
    o[0] = c.x, o[1] = c.y, o[2] = c.z, o[3] = c.w;
  }
}

void skybox_shade_background(const PreparedSky &sky, int w, int h, const int *draw, float *rgba, int threads) {
  if (!sky.present()) return;
  parallel_rows(h, threads, [&](int y) {
    const size_t row = static_cast<size_t>(y) * w;
    skybox_shade_row(sky, w, y, draw + row, rgba + row * 4);
  });
}

SkyboxGl::~SkyboxGl() {
  if (program_) r_.delete_program(program_);
  if (tex_) r_.delete_texture(tex_);
}

bool SkyboxGl::init(const PreparedSky &sky, std::string *err) {
  program_ = build_production_program(r_, api_, *sky.variant, err);
  if (!program_) {
    *err = "skybox " + sky.variant->name() + ": " + *err;
    return false;
  }
  tex_ = r_.upload_texture(sky.cube);
  return gl_no_error(r_.gl(), "while uploading the skybox", err);
}

bool SkyboxGl::draw(const PreparedSky &sky, std::string *err) {
  const GlFns &g = r_.gl();
  const ShaderFamily *f = find_family("skybox");
  if (!f) {
    *err = "no family skybox";
    return false;
  }
  g.UseProgram(program_);
  f->bind_uniforms(g, program_, sky.shared);
  g.ActiveTexture(GL_TEXTURE0);
  g.BindTexture(GL_TEXTURE_CUBE_MAP, tex_);
  const GLint loc = g.GetUniformLocation(program_, "u_sky");
  if (loc >= 0) g.Uniform1i(loc, 0);
  g.Disable(GL_DEPTH_TEST);
  g.DepthMask(GL_FALSE);
  r_.bind_fullscreen_triangle();
  g.DrawArrays(GL_TRIANGLES, 0, 3);
  g.Enable(GL_DEPTH_TEST);
  g.DepthMask(GL_TRUE);
  return gl_no_error(g, "while drawing the skybox", err);
}

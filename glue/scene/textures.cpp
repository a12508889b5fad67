// tiershade scene: procedural demo textures and probe-derived cube maps (see scene_textures.h).
#include "scene/textures.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "bake/ambient_fit.h"
#include "base/cube_faces.h"
#include "base/image.h"
#include "families/family.h"
#include "io/exr.h"
#include "io/radiance_hdr.h"
#include "scene/finite_check.h"

TextureDesc make_bump_normal_map(const char *sampler, int n) {
  // A grid of round dimples (height h = -cos^2 bumps), normals from the height gradient;
  // alpha: a spec mask with glossy stripes.
  TextureDesc t = blank_texture(sampler, n, n, true, true);
  const int cells = 8;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double u = (x + 0.5) / n * cells, v = (y + 0.5) / n * cells;
      const double fu = u - std::floor(u) - 0.5, fv = v - std::floor(v) - 0.5;
      const double r = std::sqrt(fu * fu + fv * fv);
      double gx = 0, gy = 0;
      if (r < 0.4 && r > 1e-9) {
        const double dh = -0.9 * std::sin(r / 0.4 * glm::pi<double>());  // slope of the dimple
        gx = dh * fu / r;
        gy = dh * fv / r;
      }
      const glm::dvec3 nrm(-gx, -gy, 1.0);
      const double l = glm::length(nrm);
      float *p = &t.rgba[(static_cast<size_t>(y) * n + x) * 4];
      p[0] = static_cast<float>(0.5 + 0.5 * nrm.x / l);
      p[1] = static_cast<float>(0.5 + 0.5 * nrm.y / l);
      p[2] = static_cast<float>(0.5 + 0.5 * nrm.z / l);
      p[3] = ((x * 4 / n) & 1) ? 1.f : 0.35f;
    }
  }
  return t;
}

TextureDesc make_exponent_map(const char *sampler, int n) {
  TextureDesc t = blank_texture(sampler, n, n, true, true);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      float *p = &t.rgba[(static_cast<size_t>(y) * n + x) * 4];
      p[0] =
          static_cast<float>(0.05 + 0.6 * (0.5 + 0.5 * std::cos(2 * glm::pi<double>() * y / n * 2)));  // exponent 8..97
      p[1] = static_cast<float>(x) / n;  // albedo-tint mask
      p[2] = 0.f;
      p[3] = 1.f;  // rim mask
    }
  }
  return t;
}

TextureDesc make_warp_ramp(const char *sampler) {
  TextureDesc t = blank_texture(sampler, 64, 1, true, false);
  for (int x = 0; x < 64; ++x) {
    const double s = (x + 0.5) / 64;  // half-Lambert term, 0 (back) .. 1 (lit)
    float *p = &t.rgba[x * 4];
    p[0] = static_cast<float>(0.5 * std::pow(s, 1.6) + 0.02);
    p[1] = static_cast<float>(0.5 * std::pow(s, 2.0) + 0.01);
    p[2] = static_cast<float>(0.45 * std::pow(s, 2.4) + 0.04 * (1 - s));
    p[3] = 1.f;
  }
  return t;
}

TextureDesc make_sky_cube(const char *sampler, int size) {
  TextureDesc t;
  t.sampler = sampler;
  t.kind = TexKind::Cube;
  t.w = t.h = size;
  t.linear = true;
  t.rgba.resize(static_cast<size_t>(6) * size * size * 4);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const glm::dvec3 d = cube_face_direction(f, (x + 0.5) / size * 2 - 1, (y + 0.5) / size * 2 - 1);
        const double up = std::max(0.0, d[1]), down = std::max(0.0, -d[1]);
        float *p = &t.rgba[((static_cast<size_t>(f) * size + y) * size + x) * 4];
        p[0] = static_cast<float>(0.3 + 0.6 * up + 0.2 * down);
        p[1] = static_cast<float>(0.35 + 0.8 * up + 0.15 * down);
        p[2] = static_cast<float>(0.45 + 1.4 * up + 0.1 * down);
        p[3] = 1.f;
      }
  return t;
}

bool cube_from_probe(const std::string &path, const char *sampler, int size, TextureDesc *cube, float ambient[6][3],
                     std::string *err) {
  ImageF probe;
  // The reader the scene loader chose (gltf_extras.cpp: .exr or Radiance .hdr, docs/scenes.md).
  const bool exr = path.size() > 4 && path.compare(path.size() - 4, 4, ".exr") == 0;
  if (!(exr ? read_exr(path, &probe, err) : read_hdr(path, &probe, err))) return false;
  // Lat-long lookup: u = atan2(x, -z) / 2pi + 0.5, v = acos(y) / pi (row 0 = bottom in ImageF).
  auto sample = [&](const double d[3], double rgb[3]) {
    const double u = std::atan2(d[0], -d[2]) / (2 * glm::pi<double>()) + 0.5;
    const double v = std::acos(std::max(-1.0, std::min(1.0, d[1]))) / glm::pi<double>();
    const double fx = u * probe.w - 0.5, fy = (1 - v) * probe.h - 0.5;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    const double wx = fx - x0, wy = fy - y0;
    for (int c = 0; c < 3; ++c) rgb[c] = 0;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const int xx = ((x0 + i) % probe.w + probe.w) % probe.w;
        const int yy = std::min(probe.h - 1, std::max(0, y0 + j));
        const double w = (i ? wx : 1 - wx) * (j ? wy : 1 - wy);
        for (int c = 0; c < 3; ++c) rgb[c] += w * probe.rgba[(static_cast<size_t>(yy) * probe.w + xx) * 4 + c];
      }
  };
  cube->sampler = sampler;
  cube->kind = TexKind::Cube;
  cube->w = cube->h = size;
  cube->linear = true;
  cube->rgba.assign(static_cast<size_t>(6) * size * size * 4, 1.f);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        double rgb[3];
        const glm::dvec3 d = cube_face_direction(f, (x + 0.5) / size * 2 - 1, (y + 0.5) / size * 2 - 1);
        sample(glm::value_ptr(d), rgb);
        float *p = &cube->rgba[((static_cast<size_t>(f) * size + y) * size + x) * 4];
        for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(rgb[c]);
      }
  // Ambient cube from the probe's texels: least squares against the probe's irradiance, solid-angle
  // weighted, non-negative (glue/bake/ambient_fit.h; Source's per-axis mean is AmbientFit::Mean).
  fit_probe_cube(probe, AmbientFit::Lsq, ambient);
  // The host contract (scene/finite_check.h): RGBE reaches 2^127, beyond fp16; clamped to 65504.
  return clamp_texels_to_fp16(cube->rgba.data(), cube->rgba.size(), path + ": the cube map from the probe", nullptr,
                              err) &&
         clamp_texels_to_fp16(&ambient[0][0], 18, path + ": the ambient cube from the probe", nullptr, err);
}

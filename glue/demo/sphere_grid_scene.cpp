// tiershade demo: the sphere-grid scene of the legacy analytic frames (see sphere_grid_scene.h).
#include "demo/sphere_grid_scene.h"

#include <algorithm>
#include <cmath>

#include "twins/model_lighting.h"
#include "scene/scene.h"
#include "scene/textures.h"

namespace {

// A 64x64 colourful albedo: hue bands across u, a soft checker across v.
TextureDesc albedo_texture() {
  TextureDesc t;
  t.sampler = "u_albedo";
  t.w = t.h = 64;
  t.linear = t.repeat = true;
  t.rgba.resize(64 * 64 * 4);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const float u = x / 64.f, v = y / 64.f;
      const float check = ((x / 8 + y / 8) & 1) ? 1.0f : 0.75f;
      float *p = &t.rgba[(y * 64 + x) * 4];
      p[0] = check * (0.5f + 0.3f * std::cos(6.2831853f * (u + 0.0f)));
      p[1] = check * (0.5f + 0.3f * std::cos(6.2831853f * (u + 0.33f)));
      p[2] = check * (0.5f + 0.3f * std::cos(6.2831853f * (u + 0.67f))) * (0.8f + 0.2f * v);
      p[3] = 1.f;
    }
  }
  return t;
}

// Distance x cone attenuation of a light at p, as shaders/common_lights.glsl defines it (double).
double light_attenuation_at(const ts_light &L, const double p[3]) {
  if (L.type == TS_LIGHT_DIRECTIONAL) return 1.0;
  double v[3] = {L.pos[0] - p[0], L.pos[1] - p[1], L.pos[2] - p[2]};
  const double d = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  double att = 1.0 / (L.atten[0] + L.atten[1] * d + L.atten[2] * d * d);
  if (L.type == TS_LIGHT_SPOT && d > 0) {
    const double cos_a = -(v[0] * L.dir[0] + v[1] * L.dir[1] + v[2] * L.dir[2]) / d;
    const double t = std::max(1e-4, (cos_a - L.cos_outer) / (static_cast<double>(L.cos_inner) - L.cos_outer));
    att *= std::min(1.0, std::pow(t, static_cast<double>(L.spot_exponent)));
  }
  return att;
}

// ps20 takes the attenuation interpolated from the vertices. The spheres are drawn
// as UV spheres of kSegPhi x kSegTheta quads; a pixel's value is the bilinear blend
// of its quad's four vertex values (Gouraud over quads).
const int kSegPhi = 24, kSegTheta = 12;
double vertex_interpolated_attenuation(const ts_light &L, const double center[3], double nx, double ny, double nz) {
  const double pi = 3.14159265358979323846;
  const double theta = std::acos(std::max(-1.0, std::min(1.0, ny)));  // 0 at +Y
  const double phi = std::atan2(nx, nz);                               // 0 at +Z
  const double ft = theta / pi * kSegTheta, fp = (phi + pi) / (2 * pi) * kSegPhi;
  const int it = std::min(kSegTheta - 1, static_cast<int>(ft)), ip = std::min(kSegPhi - 1, static_cast<int>(fp));
  const double wt = ft - it, wp = fp - ip;
  double a[2][2];
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      const double th = (it + j) * pi / kSegTheta, ph = (ip + i) * 2 * pi / kSegPhi - pi;
      const double q[3] = {center[0] + std::sin(th) * std::sin(ph), center[1] + std::cos(th),
                           center[2] + std::sin(th) * std::cos(ph)};
      a[j][i] = light_attenuation_at(L, q);
    }
  }
  return (a[0][0] * (1 - wp) + a[0][1] * wp) * (1 - wt) + (a[1][0] * (1 - wp) + a[1][1] * wp) * wt;
}

}  // namespace

const char *const kSphereGridGltf = "scenes/sphere_grid.gltf";
const char *const kSphereGridLights = "scenes/sphere_grid.lights";

std::vector<TextureDesc> sphere_grid_textures() {
  return {albedo_texture(), make_bump_normal_map("u_normal_map", 128), make_exponent_map("u_exponent_map", 64),
          make_warp_ramp("u_light_warp"), make_sky_cube("u_envmap", 32)};
}

bool sphere_grid_scene(SphereScene *out, std::string *err) {
  Scene g;
  if (!load_scene(kSphereGridGltf, &g, err)) return false;
  if (g.ambient.size() != 1 || g.ambient[0].from_probe >= 0) {
    *err = std::string(kSphereGridGltf) + ": extras.tiershade.ambient: expected one explicit ambient cube";
    return false;
  }
  SphereScene s;
  std::copy(&g.ambient[0].cube[0][0], &g.ambient[0].cube[0][0] + 18, &s.ambient[0][0]);
  for (const SceneLight &l : g.lights) s.lights.push_back(l.light);
  s.tone_map_scale = g.hdr.tone_map_scale;
  s.textures = sphere_grid_textures();
  *out = s;
  return true;
}

bool phong_sphere_scene(const std::string &probe_path, SphereScene *out, std::string *note, std::string *err) {
  SphereScene s;
  if (!sphere_grid_scene(&s, err)) return false;
  s.cols = s.rows = 1;
  s.lights.resize(4);  // every tier above ps20 keeps all four local
  s.lights[1].color[0] = 0.6f; s.lights[1].color[1] = 0.8f; s.lights[1].color[2] = 1.8f;
  s.tone_map_scale = 0.8f;
  s.phong.rim_boost = 2.f;
  s.phong.boost = 4.f;
  s.phong.albedo_tint = true;
  float ambient[6][3];
  TextureDesc cube;
  std::string probe_err;  // a missing probe is not an error: the procedural sky stands in
  if (!probe_path.empty() && cube_from_probe(probe_path, "u_envmap", 32, &cube, ambient, &probe_err)) {
    s.textures[4] = cube;
    for (int i = 0; i < 6; ++i)
      for (int c = 0; c < 3; ++c) s.ambient[i][c] = 0.35f * ambient[i][c];
    *note = "envmap and ambient cube from " + probe_path;
  } else {
    *note = "procedural sky envmap (" + (probe_path.empty() ? std::string("no probe given") : probe_err) + ")";
  }
  *out = s;
  return true;
}

bool sphere_frame(const SphereScene &scene, int w, int h, int max_local, SphereFrame *out, std::string *err) {
  FamilyInputs &in = out->in;
  in.resize(w, h, ML_PIXEL_SLOTS);
  out->hit.assign(static_cast<size_t>(w) * h, 0);
  // Orthographic camera looking down -Z at a cols x rows grid of unit spheres, 2.4 apart.
  const float spacing = 2.4f;
  const float half_w = scene.cols * spacing * 0.5f, half_h = scene.rows * spacing * 0.5f;
  const float scale = std::fmax(2.f * half_w / w, 2.f * half_h / h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float wx = (x + 0.5f - w * 0.5f) * scale, wy = (y + 0.5f - h * 0.5f) * scale;
      const int col = static_cast<int>(std::floor((wx + half_w) / spacing));
      const int row = static_cast<int>(std::floor((wy + half_h) / spacing));
      if (col < 0 || col >= scene.cols || row < 0 || row >= scene.rows) continue;
      const float cx = -half_w + (col + 0.5f) * spacing, cy = -half_h + (row + 0.5f) * spacing;
      const float dx = wx - cx, dy = wy - cy, r2 = dx * dx + dy * dy;
      if (r2 >= 1.f) continue;
      const float dz = std::sqrt(1.f - r2);
      out->hit[static_cast<size_t>(y) * w + x] = 1;
      in.set_slot(x, y, ML_SLOT_NORMAL, ts_v4f(dx, dy, dz, 0));
      in.set_slot(x, y, ML_SLOT_POSITION, ts_v4f(wx, wy, dz, 1));
      const float u = std::atan2(dx, dz) * 0.15915494f + 0.5f + 0.17f * col;
      const float v = std::acos(std::fmax(-1.f, std::fmin(1.f, dy))) * 0.31830989f + 0.29f * row;
      in.set_slot(x, y, ML_SLOT_UV, ts_v4f(2.f * u, v, 0, 0));
      // Tangent along +u (around the vertical axis), bitangent = N x T.
      const float tl = std::sqrt(dz * dz + dx * dx);
      const float tx = tl > 1e-6f ? dz / tl : 1.f, tz = tl > 1e-6f ? -dx / tl : 0.f;
      in.set_slot(x, y, ML_SLOT_TANGENT, ts_v4f(tx, 0, tz, 0));
      in.set_slot(x, y, ML_SLOT_BITANGENT, ts_v4f(dy * tz, dz * tx - dx * tz, -dy * tx, 0));
    }
  }

  // Shared slots: the ambient cube with the folded lights, and the kept local lights.
  in.shared.assign(ML_SLOTS, ts_v4f(0, 0, 0, 0));
  float cube[6][3];
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c) cube[i][c] = scene.ambient[i][c];
  std::vector<int> kept(scene.lights.size() + 1);
  const float center[3] = {0, 0, 0};
  const int n = static_cast<int>(scene.lights.size());
  const int nk = ts_fold_lights(scene.lights.data(), n, max_local, center, 1, cube, kept.data());
  out->lights_kept = nk;
  out->lights_folded = n - nk;
  for (int i = 0; i < 6; ++i) in.shared[ML_SLOT_AMBIENT + i] = ts_v4f(cube[i][0], cube[i][1], cube[i][2], 0);
  in.shared[ML_SLOT_PARAMS] = ts_v4f(scene.tone_map_scale, static_cast<float>(nk), 0, 0);
  in.shared[ML_SLOT_ALBEDO] = ts_v4f(1, 1, 1, 1);
  for (int i = 0; i < nk && i < ML_MAX_LIGHTS; ++i) {
    float packed[5][4];
    char msg[200];
    if (!ts_light_pack(&scene.lights[kept[i]], packed, msg, sizeof msg)) {
      *err = "light " + std::to_string(kept[i]) + ": " + msg;
      return false;
    }
    for (int k = 0; k < 5; ++k)
      in.shared[ML_SLOT_LIGHT0 + 5 * i + k] = ts_v4f(packed[k][0], packed[k][1], packed[k][2], packed[k][3]);
  }
  // Per-vertex attenuation of the kept lights, interpolated (read by the ps20 tier only).
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!out->hit[static_cast<size_t>(y) * w + x]) continue;
      const ts_vec4f n = in.slot(x, y, ML_SLOT_NORMAL), p = in.slot(x, y, ML_SLOT_POSITION);
      const double center[3] = {p.x - n.x, p.y - n.y, p.z - n.z};
      float va[4] = {0, 0, 0, 0};
      for (int i = 0; i < nk && i < 4; ++i)
        va[i] = static_cast<float>(vertex_interpolated_attenuation(scene.lights[kept[i]], center, n.x, n.y, n.z));
      in.set_slot(x, y, ML_SLOT_VERTEX_ATTEN, ts_v4f(va[0], va[1], va[2], va[3]));
    }
  }
  // Episode One material (PHONG variants): eye on +Z, far away (orthographic view).
  const PhongMaterial &m = scene.phong;
  in.shared[ML_SLOT_EYE] = ts_v4f(0, 0, 60, 1);
  in.shared[ML_SLOT_PHONG] = ts_v4f(m.exponent, m.exponent_factor, m.boost, 0);
  in.shared[ML_SLOT_FRESNEL] = ts_v4f((m.fresnel_mid - m.fresnel_min) * 2, m.fresnel_mid,
                                      (m.fresnel_max - m.fresnel_mid) * 2, 0);
  in.shared[ML_SLOT_PHONG_TINT] = ts_v4f(m.tint[0], m.tint[1], m.tint[2], m.albedo_tint ? 1.f : 0.f);
  in.shared[ML_SLOT_RIM] = ts_v4f(m.rim_exponent, m.rim_boost, m.rim_mask, 0);
  in.shared[ML_SLOT_ENVMAP] = ts_v4f(m.envmap_scale, m.envmap_fresnel, 0, 0);
  in.shared[ML_SLOT_ENVMAP_TINT] = ts_v4f(m.envmap_tint[0], m.envmap_tint[1], m.envmap_tint[2], 0);
  in.shared[ML_SLOT_SELF_ILLUM] = ts_v4f(m.self_illum[0], m.self_illum[1], m.self_illum[2], m.self_illum[3]);
  in.textures = scene.textures;
  return true;
}

void sphere_mask(const SphereFrame &frame, ImageF *img) {
  for (size_t p = 0; p < frame.hit.size(); ++p) {
    if (frame.hit[p]) continue;
    img->rgba[p * 4 + 0] = img->rgba[p * 4 + 1] = img->rgba[p * 4 + 2] = 0.f;
    img->rgba[p * 4 + 3] = 1.f;
  }
}

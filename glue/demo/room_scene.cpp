// tiershade demo: the world_lighting room scene (see scene_world.h).
#include "demo/room_scene.h"

#include <cmath>

namespace {

ts_vec3d add(ts_vec3d a, ts_vec3d b) { return ts_v3d(a.x + b.x, a.y + b.y, a.z + b.z); }
ts_vec3d sub(ts_vec3d a, ts_vec3d b) { return ts_v3d(a.x - b.x, a.y - b.y, a.z - b.z); }
ts_vec3d mul(ts_vec3d a, double s) { return ts_v3d(a.x * s, a.y * s, a.z * s); }
double dot(ts_vec3d a, ts_vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
ts_vec3d cross(ts_vec3d a, ts_vec3d b) {
  return ts_v3d(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
ts_vec3d unit(ts_vec3d a) { return mul(a, 1.0 / std::sqrt(dot(a, a))); }

// The inward normal of a room face: u x v, oriented so that it faces the room's centre.
ts_vec3d inward_normal(const WorldFace &f) {
  ts_vec3d n = unit(cross(f.u, f.v));
  const ts_vec3d centre = ts_v3d(0, 1.5, -2.25);
  const ts_vec3d mid = add(f.origin, add(mul(f.u, f.su / 2), mul(f.v, f.sv / 2)));
  if (dot(n, sub(centre, mid)) < 0) n = mul(n, -1);
  return n;
}

// Procedural tiles, 1 per world unit: a height field of bevelled tiles in a mortar grid.
const int kMatSize = 128;
double tile_height(double u, double v) {
  const double fu = u - std::floor(u), fv = v - std::floor(v);
  const double edge = std::min(std::min(fu, 1 - fu), std::min(fv, 1 - fv));  // 0 at the grout line
  const double bevel = std::min(1.0, edge / 0.08);
  const double bumps = 0.03 * std::sin(6.283 * 3 * u) * std::sin(6.283 * 2 * v);
  return 0.06 * bevel + (edge > 0.04 ? bumps : 0.0);
}

void make_materials(std::vector<TextureDesc> *out) {
  TextureDesc base = wl_texture("u_base", kMatSize, kMatSize, true, true);
  TextureDesc nm = wl_texture("u_normalmap", kMatSize, kMatSize, true, true);
  TextureDesc mask = wl_texture("u_envmap_mask", kMatSize, kMatSize, true, true);
  const double h = 1.0 / kMatSize;
  for (int y = 0; y < kMatSize; ++y) {
    for (int x = 0; x < kMatSize; ++x) {
      const double u = (x + 0.5) * h, v = (y + 0.5) * h;
      const double fu = u - std::floor(u), fv = v - std::floor(v);
      const double edge = std::min(std::min(fu, 1 - fu), std::min(fv, 1 - fv));
      const bool grout = edge < 0.04;
      const double dhdu = (tile_height(u + h, v) - tile_height(u - h, v)) / (2 * h);
      const double dhdv = (tile_height(u, v + h) - tile_height(u, v - h)) / (2 * h);
      const ts_vec3d n = unit(ts_v3d(-dhdu * 0.25, -dhdv * 0.25, 1));
      const size_t p = (static_cast<size_t>(y) * kMatSize + x) * 4;
      const double shade = grout ? 0.35 : 0.72 + 0.06 * std::sin(13 * u + 7 * v);
      base.rgba[p + 0] = static_cast<float>(shade * 0.95);
      base.rgba[p + 1] = static_cast<float>(shade * 0.88);
      base.rgba[p + 2] = static_cast<float>(shade * 0.78);
      base.rgba[p + 3] = grout ? 1.f : 0.3f;  // inverted: the grout is matte
      nm.rgba[p + 0] = static_cast<float>(0.5 * n.x + 0.5);
      nm.rgba[p + 1] = static_cast<float>(0.5 * n.y + 0.5);
      nm.rgba[p + 2] = static_cast<float>(0.5 * n.z + 0.5);
      nm.rgba[p + 3] = grout ? 0.05f : 0.8f;  // envmap mask: glazed tiles, matte grout
      for (int c = 0; c < 3; ++c) mask.rgba[p + c] = grout ? 0.05f : 0.8f;
      mask.rgba[p + 3] = 1.f;
    }
  }
  *out = {base, nm, mask};
}

}  // namespace

WorldScene default_world_scene() {
  WorldScene s;
  // Room: x in [-3, 3], y in [0, 3], z in [-6, 1.5]; open at the front (z = 1.5).
  s.faces = {
      {"floor", ts_v3d(-3, 0, 1.5), ts_v3d(1, 0, 0), ts_v3d(0, 0, -1), 6, 7.5, -1},
      {"ceiling", ts_v3d(-3, 3, -6), ts_v3d(1, 0, 0), ts_v3d(0, 0, 1), 6, 7.5, 1},  // assigned to probe 1
      {"left wall", ts_v3d(-3, 0, 1.5), ts_v3d(0, 0, -1), ts_v3d(0, 1, 0), 7.5, 3, -1},
      {"right wall", ts_v3d(3, 0, -6), ts_v3d(0, 0, 1), ts_v3d(0, 1, 0), 7.5, 3, -1},
      {"back wall", ts_v3d(-3, 0, -6), ts_v3d(1, 0, 0), ts_v3d(0, 1, 0), 6, 3, -1},
  };
  for (WorldFace &f : s.faces) f.normal = inward_normal(f);
  auto point = [](double x, double y, double z, double r, double g, double b) {
    rnm_light l{};
    l.pos = ts_v3d(x, y, z);
    l.color = ts_v3d(r, g, b);
    l.atten[0] = 0.2;  // 1 / (0.2 + d^2): no singularity at a wall
    l.atten[2] = 1.0;
    return l;
  };
  s.lights = {point(-2.0, 2.3, -4.6, 9.0, 5.0, 2.0),  // warm, back left
              point(2.2, 0.9, -2.0, 1.5, 3.0, 8.0),  // blue, low right
              point(0.3, 2.6, -0.5, 3.0, 5.5, 3.0)};  // green, near the ceiling
  s.probes = {ts_v3d(0, 1.4, -1.0), ts_v3d(0, 1.4, -4.5)};
  s.eye = ts_v3d(0, 1.6, 3.0);
  s.target = ts_v3d(0, 1.2, -6);
  return s;
}

bool world_frame(const WorldScene &s, const WorldBake &b, int w, int h, WorldFrame *out, std::string *err) {
  if (w < 1 || h < 1) {
    *err = "world frame of " + std::to_string(w) + "x" + std::to_string(h) + " pixels";
    return false;
  }
  FamilyInputs &in = out->in;
  in.resize(w, h, WL_PIXEL_SLOTS);
  out->probe.assign(static_cast<size_t>(w) * h, -1);
  const ts_vec3d fwd = unit(sub(s.target, s.eye));
  const ts_vec3d right = unit(cross(fwd, ts_v3d(0, 1, 0)));
  const ts_vec3d up = cross(right, fwd);
  const double ty = std::tan(s.fov_y_deg * 3.14159265358979323846 / 360.0), tx = ty * w / h;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double px = (2 * (x + 0.5) / w - 1) * tx, py = (2 * (y + 0.5) / h - 1) * ty;  // y: bottom row first
      const ts_vec3d d = unit(add(fwd, add(mul(right, px), mul(up, py))));
      double t, a, bb;
      const int f = world_cast(s.faces, s.eye, d, &t, &a, &bb);
      if (f < 0) continue;  // background: record of zeros, masked after shading
      const WorldFace &face = s.faces[f];
      const ts_vec3d p = add(s.eye, mul(d, t)), n = world_face_normal(face), e = sub(s.eye, p);
      float lm[2];
      lm_page_uv(&b.place[f], s.page_w, s.page_h, a, bb, lm);
      // Base uv: one tile per world unit along the face's S and T axes.
      in.set_slot(x, y, WL_SLOT_UV,
                  ts_v4f(static_cast<float>(a * face.su), static_cast<float>(bb * face.sv), lm[0], lm[1]));
      in.set_slot(x, y, WL_SLOT_LM_OFFSET,
                  ts_v4f(b.place[f].offset[0], b.place[f].offset[1], static_cast<float>(t * dot(d, fwd)), 0));
      in.set_slot(x, y, WL_SLOT_NORMAL,
                  ts_v4f(static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z), 0));
      in.set_slot(x, y, WL_SLOT_TANGENT,
                  ts_v4f(static_cast<float>(face.u.x), static_cast<float>(face.u.y), static_cast<float>(face.u.z), 0));
      in.set_slot(x, y, WL_SLOT_BINORMAL,
                  ts_v4f(static_cast<float>(face.v.x), static_cast<float>(face.v.y), static_cast<float>(face.v.z), 0));
      in.set_slot(x, y, WL_SLOT_EYE,
                  ts_v4f(static_cast<float>(e.x), static_cast<float>(e.y), static_cast<float>(e.z), 0));
      out->probe[static_cast<size_t>(y) * w + x] = b.face_probe[f];
    }
  }
  in.shared.assign(WL_SLOTS, ts_v4f(0, 0, 0, 0));
  wl_defaults(in.shared.data());
  // c12: the three bumped lightmaps reconstruct a flat normal's irradiance as 1/sqrt3 of
  // the flat lightmap (sum of b_k = sqrt3 n): a lightmap scale of sqrt3 makes bumped and flat agree.
  const float lm_scale = 1.7320508f;
  in.shared[WL_SLOT_TINT_SCALE] = ts_v4f(lm_scale, lm_scale, lm_scale, s.tone_map_scale);
  in.shared[WL_SLOT_ENV_TINT] = ts_v4f(0.5f, 0.5f, 0.5f, 1.f);
  in.shared[WL_SLOT_ENV_PARAMS] = ts_v4f(0.f, 1.f, 0.85f, 0.15f);  // R0 = 0.15
  in.shared[WL_SLOT_FOG_COLOR] = ts_v4f(0.05f, 0.05f, 0.06f, 0.5f);
  in.shared[WL_SLOT_FOG_PARAMS] = ts_v4f(1.f / 12.f, 3.f / 12.f, 0, 0);  // start 3, range 12
  make_materials(&out->materials);
  return true;
}

std::vector<TextureDesc> world_pass_textures(const WorldFrame &f, const TextureDesc &page, const WorldBake &b, int p,
                                             bool white_base, bool nearest_cube) {
  std::vector<TextureDesc> t = f.materials;
  if (white_base) {
    t[0] = wl_texture("u_base", 1, 1, false, true);
    t[0].rgba = {1.f, 1.f, 1.f, 1.f};
  }
  t.push_back(page);
  TextureDesc cube = b.cubes.at(static_cast<size_t>(p));
  if (nearest_cube) cube.linear = false;
  t.push_back(cube);
  return t;
}

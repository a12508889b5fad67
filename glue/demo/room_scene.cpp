// tiershade glue: the world_lighting room scene (see scene_world.h).
#include "demo/room_scene.h"

#include <cmath>

#include "offline/envmap_probes.h"
#include "offline/lightmap_encoding.h"

namespace {

ts_vec3d add(ts_vec3d a, ts_vec3d b) { return ts_v3d(a.x + b.x, a.y + b.y, a.z + b.z); }
ts_vec3d sub(ts_vec3d a, ts_vec3d b) { return ts_v3d(a.x - b.x, a.y - b.y, a.z - b.z); }
ts_vec3d mul(ts_vec3d a, double s) { return ts_v3d(a.x * s, a.y * s, a.z * s); }
double dot(ts_vec3d a, ts_vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
ts_vec3d cross(ts_vec3d a, ts_vec3d b) {
  return ts_v3d(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
ts_vec3d unit(ts_vec3d a) { return mul(a, 1.0 / std::sqrt(dot(a, a))); }

// The inward normal of a face: u x v, oriented so that it faces the room's centre.
ts_vec3d face_normal(const WorldFace &f) {
  if (dot(f.normal, f.normal) > 0) return unit(f.normal);
  ts_vec3d n = unit(cross(f.u, f.v));
  const ts_vec3d centre = ts_v3d(0, 1.5, -2.25);
  const ts_vec3d mid = add(f.origin, add(mul(f.u, f.su / 2), mul(f.v, f.sv / 2)));
  if (dot(n, sub(centre, mid)) < 0) n = mul(n, -1);
  return n;
}

ts_vec3d face_point(const WorldFace &f, double a, double b) {
  return add(f.origin, add(mul(f.u, a * f.su), mul(f.v, b * f.sv)));
}

// Nearest face hit from the front by the ray o + t d (t > 1e-6): face index, t, and (a, b).
int cast(const WorldScene &s, ts_vec3d o, ts_vec3d d, double *t_out, double *a_out, double *b_out) {
  int best = -1;
  double best_t = 1e30;
  for (size_t i = 0; i < s.faces.size(); ++i) {
    const WorldFace &f = s.faces[i];
    const ts_vec3d n = face_normal(f);
    const double dn = dot(d, n);
    if (dn >= 0) continue;  // parallel, or from behind
    const double t = dot(sub(f.origin, o), n) / dn;
    if (!(t > 1e-6) || t >= best_t) continue;
    const ts_vec3d q = sub(add(o, mul(d, t)), f.origin);
    const double a = dot(q, f.u) / f.su, b = dot(q, f.v) / f.sv;
    if (a < 0 || a > 1 || b < 0 || b > 1) continue;
    best = static_cast<int>(i);
    best_t = t;
    *a_out = a;
    *b_out = b;
  }
  *t_out = best_t;
  return best;
}

int luxels(double len, double per_unit) { return std::max(2, static_cast<int>(std::lround(len * per_unit)) + 1); }

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
  auto point = [](double x, double y, double z, double r, double g, double b) {
    rnm_light l{};
    l.pos = ts_v3d(x, y, z);
    l.color = ts_v3d(r, g, b);
    l.atten[0] = 0.2;  // 1 / (0.2 + d^2): no singularity at a wall
    l.atten[2] = 1.0;
    return l;
  };
  s.lights = {point(-2.0, 2.3, -4.6, 9.0, 5.0, 2.0),   // warm, back left
              point(2.2, 0.9, -2.0, 1.5, 3.0, 8.0),    // blue, low right
              point(0.3, 2.6, -0.5, 3.0, 5.5, 3.0)};   // green, near the ceiling
  s.probes = {ts_v3d(0, 1.4, -1.0), ts_v3d(0, 1.4, -4.5)};
  s.eye = ts_v3d(0, 1.6, 3.0);
  s.target = ts_v3d(0, 1.2, -6);
  return s;
}

bool bake_world(const WorldScene &s, WorldBake *out, std::string *err) {
  std::vector<lm_face_size> sizes;
  for (const WorldFace &f : s.faces)
    sizes.push_back({luxels(f.su, s.luxels_per_unit), luxels(f.sv, s.luxels_per_unit), 1});
  out->place.resize(s.faces.size());
  char msg[256];
  if (lm_page_pack(s.page_w, s.page_h, sizes.data(), static_cast<int>(sizes.size()), out->place.data(), msg,
                   sizeof msg) != 0) {
    *err = msg;
    return false;
  }
  out->page.assign(static_cast<size_t>(s.page_w) * s.page_h * 4, 0.f);
  for (size_t i = 0; i < out->page.size(); i += 4) out->page[i + 3] = 1.f;
  for (size_t fi = 0; s.bake_luxels && fi < s.faces.size(); ++fi) {
    const WorldFace &f = s.faces[fi];
    const ts_vec3d n = face_normal(f);
    ts_vec3d bump[3];
    if (rnm_bump_basis(f.u, f.v, n, n, bump, msg, sizeof msg) != 0) {
      *err = std::string(f.name) + ": " + msg;
      return false;
    }
    const lm_face_size &sz = sizes[fi];
    for (int j = 0; j < sz.luxels_h; ++j) {
      for (int i = 0; i < sz.luxels_w; ++i) {
        const ts_vec3d p = face_point(f, static_cast<double>(i) / (sz.luxels_w - 1), static_cast<double>(j) / (sz.luxels_h - 1));
        ts_vec3d v4[4];
        if (rnm_bake_texel(p, n, bump, s.lights.data(), static_cast<int>(s.lights.size()), v4, msg, sizeof msg) != 0) {
          *err = std::string(f.name) + ": " + msg;
          return false;
        }
        for (int k = 0; k < 4; ++k) {
          int tx, ty;
          lm_page_texel(&out->place[fi], k, i, j, &tx, &ty);
          float *t = &out->page[(static_cast<size_t>(ty) * s.page_w + tx) * 4];
          t[0] = static_cast<float>(v4[k].x);
          t[1] = static_cast<float>(v4[k].y);
          t[2] = static_cast<float>(v4[k].z);
        }
      }
    }
    lm_page_fill_borders(&out->place[fi], s.page_w, out->page.data());
  }
  // Probes: each face's, then each probe's cube, ray cast from the probe: a wall shows its
  // flat lightmap value times its mean albedo, a light shows as a small bright sphere.
  out->face_probe.clear();
  for (const WorldFace &f : s.faces) {
    const int p = env_pick_probe(face_point(f, 0.5, 0.5), s.probes.data(), static_cast<int>(s.probes.size()), f.probe,
                                 msg, sizeof msg);
    if (p < 0) {
      *err = std::string(f.name) + ": " + msg;
      return false;
    }
    out->face_probe.push_back(p);
  }
  out->cubes.clear();
  const int N = s.cube_size;
  for (const ts_vec3d &pos : s.probes) {
    TextureDesc c = wl_texture("u_envmap", N, N * 6, true, false);
    c.kind = TexKind::Cube;
    c.h = N;
    for (int face = 0; face < 6; ++face) {
      for (int j = 0; j < N; ++j) {
        for (int i = 0; i < N; ++i) {
          const double sc = 2 * (i + 0.5) / N - 1, tc = 2 * (j + 0.5) / N - 1;
          // GL cube face table (major axis, sc, tc): +X (-z, -y), -X (z, -y), +Y (x, z), -Y (x, -z), +Z (x, -y), -Z (-x, -y).
          const ts_vec3d dirs[6] = {ts_v3d(1, -tc, -sc), ts_v3d(-1, -tc, sc), ts_v3d(sc, 1, tc),
                                    ts_v3d(sc, -1, -tc), ts_v3d(sc, -tc, 1), ts_v3d(-sc, -tc, -1)};
          const ts_vec3d d = unit(dirs[face]);
          ts_vec3d rad = ts_v3d(0, 0, 0);
          double t, a, b;
          const int hit = cast(s, pos, d, &t, &a, &b);
          if (hit >= 0) {
            const WorldFace &f = s.faces[hit];
            const ts_vec3d n = face_normal(f);
            ts_vec3d bump[3], v4[4];
            rnm_bump_basis(f.u, f.v, n, n, bump, msg, sizeof msg);
            rnm_bake_texel(face_point(f, a, b), n, bump, s.lights.data(), static_cast<int>(s.lights.size()), v4, msg,
                           sizeof msg);
            rad = mul(v4[0], 0.6);
          }
          for (const rnm_light &l : s.lights) {  // a light bulb of radius 0.08 (not for a sun)
            if (l.directional) continue;
            const ts_vec3d lp = sub(l.pos, pos);
            const double along = dot(lp, d);
            if (along > 0 && along < t && dot(lp, lp) - along * along < 0.08 * 0.08) rad = mul(l.color, 4.0);
          }
          float *px = &c.rgba[((static_cast<size_t>(face) * N + j) * N + i) * 4];
          px[0] = static_cast<float>(rad.x);
          px[1] = static_cast<float>(rad.y);
          px[2] = static_cast<float>(rad.z);
          px[3] = 1.f;
        }
      }
    }
    out->cubes.push_back(c);
  }
  return true;
}

TextureDesc encode_page(const WorldScene &s, const WorldBake &b, int encoding) {
  TextureDesc t = wl_texture("u_lightmap", s.page_w, s.page_h, encoding != WL_LM_RGBE, false);
  for (size_t i = 0; i < b.page.size(); i += 4) {
    const float *in = &b.page[i];
    float *o = &t.rgba[i];
    o[3] = 1.f;
    if (encoding == WL_LM_RGBE) {
      ts_rgbe e;
      ts_rgbe_encode(in, &e);  // the page is finite (the baker refuses anything else)
      ts_rgbe_texel(e, o);
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      switch (encoding) {
        case WL_LM_FLOAT: o[c] = ts_half_quantize(in[c]); break;
        case WL_LM_412: o[c] = ts_u16_412_quantize(in[c]); break;
        case WL_LM_LDR: o[c] = ts_ldr_quantize(in[c]); break;
        default: o[c] = in[c]; break;  // float32, unquantised
      }
    }
  }
  return t;
}

void decode_texel(int encoding, const float t[4], double rgb[3]) {
  for (int c = 0; c < 3; ++c) {
    switch (encoding) {
      case WL_LM_412: rgb[c] = 16.0 * t[c]; break;
      case WL_LM_LDR: rgb[c] = std::pow(2.0 * t[c], 2.2); break;
      case WL_LM_RGBE: rgb[c] = t[c] * std::ldexp(1.0, static_cast<int>(std::lround(t[3] * 255.0)) - 128); break;
      default: rgb[c] = t[c]; break;
    }
  }
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
      const int f = cast(s, s.eye, d, &t, &a, &bb);
      if (f < 0) continue;  // background: record of zeros, masked after shading
      const WorldFace &face = s.faces[f];
      const ts_vec3d p = add(s.eye, mul(d, t)), n = face_normal(face), e = sub(s.eye, p);
      float lm[2];
      lm_page_uv(&b.place[f], s.page_w, s.page_h, a, bb, lm);
      // Base uv: one tile per world unit along the face's S and T axes.
      in.set_slot(x, y, WL_SLOT_UV, ts_v4f(static_cast<float>(a * face.su), static_cast<float>(bb * face.sv), lm[0], lm[1]));
      in.set_slot(x, y, WL_SLOT_LM_OFFSET,
                  ts_v4f(b.place[f].offset[0], b.place[f].offset[1], static_cast<float>(t * dot(d, fwd)), 0));
      in.set_slot(x, y, WL_SLOT_NORMAL, ts_v4f(static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z), 0));
      in.set_slot(x, y, WL_SLOT_TANGENT,
                  ts_v4f(static_cast<float>(face.u.x), static_cast<float>(face.u.y), static_cast<float>(face.u.z), 0));
      in.set_slot(x, y, WL_SLOT_BINORMAL,
                  ts_v4f(static_cast<float>(face.v.x), static_cast<float>(face.v.y), static_cast<float>(face.v.z), 0));
      in.set_slot(x, y, WL_SLOT_EYE, ts_v4f(static_cast<float>(e.x), static_cast<float>(e.y), static_cast<float>(e.z), 0));
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

// tiershade glue: the HDR demo and benchmark scene (see hdr_scene.h).
#include "demo/hdr_scene.h"

#include <cmath>
#include <cstdlib>

#include "twins/model_lighting.h"
#include "scene/textures.h"

namespace {

ts_light point_light(float r, float g, float b, float x, float y, float z, float c, float l, float q) {
  ts_light L = {};
  L.type = TS_LIGHT_POINT;
  L.color[0] = r;
  L.color[1] = g;
  L.color[2] = b;
  L.pos[0] = x;
  L.pos[1] = y;
  L.pos[2] = z;
  L.dir[2] = -1.f;
  L.atten[0] = c;
  L.atten[1] = l;
  L.atten[2] = q;
  return L;
}

}  // namespace

std::string hdr_default_probe() {
  const char *p = std::getenv("TIERSHADE_PROBE_HDR");
  return p && *p ? p : "../shared/data/probes/uffizi.hdr";
}

SphereScene hdr_daylight_scene(const std::string &probe_path, std::string *note) {
  SphereScene s;
  s.textures = sphere_grid_textures();
  s.lights.clear();
  ts_light sun = {};
  sun.type = TS_LIGHT_DIRECTIONAL;
  sun.color[0] = 0.9f;
  sun.color[1] = 0.82f;
  sun.color[2] = 0.68f;
  const float d[3] = {-0.45f, -0.55f, -0.70f};
  const float n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (int i = 0; i < 3; ++i) sun.dir[i] = d[i] / n;
  s.lights.push_back(sun);
  // A hot spot on the wall, well above 1 after any sensible exposure: the bloom's source.
  ts_light spot = point_light(250.f, 190.f, 120.f, 3.5f, 2.5f, 1.5f, 1.f, 0.f, 0.6f);
  spot.type = TS_LIGHT_SPOT;
  spot.dir[0] = 0.2f;
  spot.dir[1] = 0.1f;
  spot.dir[2] = -1.f;
  const float m = std::sqrt(spot.dir[0] * spot.dir[0] + spot.dir[1] * spot.dir[1] + 1.f);
  for (int i = 0; i < 3; ++i) spot.dir[i] /= m;
  spot.spot_exponent = 1.f;
  spot.cos_inner = std::cos(0.06f);
  spot.cos_outer = std::cos(0.20f);
  s.lights.push_back(spot);
  s.lights.push_back(point_light(0.1f, 0.15f, 0.35f, -5.f, -1.f, 3.f, 0.5f, 0.1f, 0.05f));  // cool bounce
  float ambient[6][3];
  TextureDesc cube;
  std::string err;
  if (cube_from_probe(probe_path, "u_envmap", 8, &cube, ambient, &err)) {
    for (int i = 0; i < 6; ++i)
      for (int c = 0; c < 3; ++c) s.ambient[i][c] = 0.12f * ambient[i][c];
    *note = "sky ambient cube from " + probe_path;
  } else {
    const float sky[6][3] = {{0.07f, 0.08f, 0.09f}, {0.06f, 0.07f, 0.08f}, {0.14f, 0.16f, 0.21f},
                             {0.04f, 0.03f, 0.03f}, {0.07f, 0.07f, 0.08f}, {0.05f, 0.05f, 0.06f}};
    for (int i = 0; i < 6; ++i)
      for (int c = 0; c < 3; ++c) s.ambient[i][c] = sky[i][c];
    *note = "procedural sky ambient cube (" + err + ")";
  }
  s.tone_map_scale = 1.f;
  return s;
}

SphereScene hdr_dark_room_scene() {
  SphereScene s;
  s.textures = sphere_grid_textures();
  s.lights.clear();
  s.lights.push_back(point_light(0.10f, 0.075f, 0.045f, -2.f, 2.f, 2.5f, 0.5f, 0.2f, 0.1f));  // a dim lamp
  const float room[6][3] = {{0.004f, 0.0036f, 0.0032f}, {0.003f, 0.0028f, 0.0024f}, {0.005f, 0.0045f, 0.004f},
                            {0.002f, 0.0016f, 0.0016f}, {0.004f, 0.0036f, 0.0032f}, {0.0024f, 0.002f, 0.002f}};
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c) s.ambient[i][c] = room[i][c];
  s.tone_map_scale = 1.f;
  return s;
}

bool hdr_scene_frame(const SphereScene &scene, int w, int h, SphereFrame *out, std::string *err) {
  if (!sphere_frame(scene, w, h, ML_MAX_LIGHTS, out, err)) return false;
  // The camera of sphere_frame: orthographic, spheres 2.4 apart, the grid fitted to the frame.
  const float spacing = 2.4f;
  const float half_w = scene.cols * spacing * 0.5f, half_h = scene.rows * spacing * 0.5f;
  const float scale = std::fmax(2.f * half_w / w, 2.f * half_h / h);
  FamilyInputs &in = out->in;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (out->hit[static_cast<size_t>(y) * w + x]) continue;
      const float wx = (x + 0.5f - w * 0.5f) * scale, wy = (y + 0.5f - h * 0.5f) * scale;
      in.set_slot(x, y, ML_SLOT_NORMAL, ts_v4f(0, 0, 1, 0));
      in.set_slot(x, y, ML_SLOT_POSITION, ts_v4f(wx, wy, -1.2f, 1));
      in.set_slot(x, y, ML_SLOT_UV, ts_v4f(0.25f * wx, 0.25f * wy, 0, 0));
      in.set_slot(x, y, ML_SLOT_TANGENT, ts_v4f(1, 0, 0, 0));
      in.set_slot(x, y, ML_SLOT_BITANGENT, ts_v4f(0, 1, 0, 0));
    }
  return true;
}

// tiershade demo: the volume_walk section of `tiershade demo` (issue 13, docs/irradiance_volume.md):
// a sphere (scenes/model_lighting.gltf's Lambert one, scaled to 0.3 m radius) walking at 0.8 m through
// the lightmapped room (scenes/world_lighting.gltf) from its darkest to its brightest place in view,
// lit by the irradiance volume baked with the room (trilinear, lsq fit; the room's lights beyond the
// tier's limit folded in as usual), two strips of final frames (tone-mapped, sRGB) on the C fallback at sm3: as lit, and with
// the scene's lights off (the lightmaps kept as baked with them) so that the sphere shows its cube alone. The two ends are the
// valid volume samples of least and greatest mean cube luminance that project inside the frame.
#include <cmath>
#include <cstdio>

#include "demo/scene_files.h"
#include "io/png.h"
#include "scene/frame.h"
#include "scene/prepare.h"

namespace {

const int kFrames = 5;
const double kRadius = 0.3;

// The room with the sphere centred at `at` (its material copied without textures).
Scene room_with_sphere(const Scene &room, const Scene &balls, const double at[3]) {
  Scene s = room;
  const ScenePrimitive *found = &balls.primitives.at(0);
  for (const ScenePrimitive &q : balls.primitives)
    if (balls.materials.at(static_cast<size_t>(q.material)).name == "lambert_plain") found = &q;
  const ScenePrimitive &src = *found;
  SceneMaterial m = balls.materials.at(static_cast<size_t>(src.material));
  m.base_texture = m.normal_texture = m.emissive_texture = m.phong_exponent_texture = m.light_warp_texture =
      SceneTextureRef();
  m.where = "volume_walk sphere";
  s.materials.push_back(m);
  ScenePrimitive p = scene_flattened(balls, src);  // its vertices are edited below
  p.material = static_cast<int>(s.materials.size()) - 1;
  p.instance = -1;
  p.where = "volume_walk sphere";
  double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30};
  for (size_t i = 0; i < p.position.size(); ++i) {
    lo[i % 3] = std::fmin(lo[i % 3], p.position[i]);
    hi[i % 3] = std::fmax(hi[i % 3], p.position[i]);
  }
  const double scale = kRadius / (0.5 * (hi[0] - lo[0]));
  for (size_t i = 0; i < p.position.size(); ++i)
    p.position[i] = static_cast<float>((p.position[i] - 0.5 * (lo[i % 3] + hi[i % 3])) * scale + at[i % 3]);
  s.primitives.push_back(p);
  return s;
}

double cube_luminance(const std::array<std::array<float, 3>, 6> &c) {
  double l = 0;
  for (const auto &f : c) l += (0.2126 * f[0] + 0.7152 * f[1] + 0.0722 * f[2]) / 6;
  return l;
}

bool run(const DemoOptions &opt, std::string *err) {
  Scene room, balls;
  if (!load_scene(kWorldLightingGltf, &room, err) || !load_scene(repo_file("scenes/model_lighting.gltf"), &balls, err)) return false;
  const int w = opt.w / 2, h = opt.h / 2;
  // The volume of the room with the sphere somewhere in it (the sphere's own place barely matters).
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  {
    const double mid[3] = {0, 1, 0};
    const Scene s = room_with_sphere(room, balls, mid);
    SceneSelection sel;
    PreparedScene ps;
    if (!select_scene_variants(s, Tier::SM3, "", &sel, err) || !prepare_scene(s, sel, w, h, Api::GL33, 1.f, &ps, err))
      return false;
    const IrradianceVolume &v = ps.volume;
    double dark = INFINITY, lit = -INFINITY;
    for (int k = 0; k < v.n[2]; ++k)
      for (int j = 0; j < v.n[1]; ++j)
        for (int i = 0; i < v.n[0]; ++i) {
          const size_t idx = v.index(i, j, k);
          if (!v.valid[idx]) continue;
          const glm::dvec3 p = v.position(i, j, k);
          const float *m = ps.view_proj;  // column-major
          double c[4];
          for (int r = 0; r < 4; ++r) c[r] = m[r] * p.x + m[4 + r] * p.y + m[8 + r] * p.z + m[12 + r];
          if (!(c[3] > 0) || std::fabs(c[0] / c[3]) > 0.8 || std::fabs(c[1] / c[3]) > 0.8) continue;  // in view
          const double l = cube_luminance(v.cube[idx]);
          if (l < dark) dark = l, lo[0] = p.x, lo[1] = p.y, lo[2] = p.z;
          if (l > lit) lit = l, hi[0] = p.x, hi[1] = p.y, hi[2] = p.z;
        }
    if (!std::isfinite(dark) || !std::isfinite(lit)) {
      *err = "volume_walk: no valid volume sample in view";
      return false;
    }
    printf("volume: %d x %d x %d samples; the walk from (%.2f, %.2f, %.2f), cube luminance %.3f, to (%.2f, %.2f, "
           "%.2f), %.3f\n",
           v.n[0], v.n[1], v.n[2], lo[0], lo[1], lo[2], dark, hi[0], hi[1], hi[2], lit);
  }
  // Top row: the final frame; bottom row: the same with the scene's lights off, the lightmaps as
  // baked with them (the page handed over as lightmaps.image), so the sphere shows its cube alone.
  std::vector<ImageF> finals, ambient;
  SceneRenderConfig cfg;
  cfg.backend = Backend::CPU;
  cfg.w = w;
  cfg.h = h;
  auto display = [](const SceneRenderResult &res) {
    ImageF im;  // the final frame (RGBA8 display codes, rows bottom-up as ImageF's)
    im.w = res.w;
    im.h = res.h;
    im.rgba.resize(res.display.size());
    for (size_t q = 0; q < res.display.size(); ++q) im.rgba[q] = res.display[q] / 255.f;
    return im;
  };
  for (int f = 0; f < kFrames; ++f) {
    const double t = f / static_cast<double>(kFrames - 1);
    const double at[3] = {lo[0] + t * (hi[0] - lo[0]), 0.8, lo[2] + t * (hi[2] - lo[2])};
    Scene s = room_with_sphere(room, balls, at);
    SceneSelection sel;
    SceneRenderResult res;
    PreparedScene ps;
    if (!select_scene_variants(s, Tier::SM3, "", &sel, err) || !render_scene(s, sel, cfg, &res, err) ||
        !prepare_scene(s, sel, w, h, Api::GL33, 1.f, &ps, err))
      return false;
    finals.push_back(display(res));
    float cube[6][3];
    const double c[3] = {at[0], at[1], at[2]};
    volume_cube_at(ps.volume, c, VolumeLookup::Trilinear, cube, nullptr);
    s.lights.clear();
    s.lightmaps.image = "(the page baked with the lights)";
    s.lightmaps.image_rgba = ps.lightmap_page;
    SceneSelection sel2;
    SceneRenderResult res2;
    if (!select_scene_variants(s, Tier::SM3, "", &sel2, err) || !render_scene(s, sel2, cfg, &res2, err)) return false;
    ambient.push_back(display(res2));
    printf("frame %d: sphere at (%.2f, %.2f, %.2f), its cube +X %.3f -X %.3f +Y %.3f -Y %.3f +Z %.3f -Z %.3f (green)\n", f,
           at[0], at[1], at[2], cube[0][1], cube[1][1], cube[2][1], cube[3][1], cube[4][1], cube[5][1]);
  }
  std::vector<const ImageF *> top, bottom;
  for (const ImageF &i : finals) top.push_back(&i);
  for (const ImageF &i : ambient) bottom.push_back(&i);
  const ImageF a = hstack(bottom, 4, 1.f), b = hstack(top, 4, 1.f);
  ImageF strip;  // rows bottom-up: the ambient-only row below, the final row above, 4 px apart
  strip.w = a.w;
  strip.h = a.h + 4 + b.h;
  strip.rgba.assign(static_cast<size_t>(strip.w) * strip.h * 4, 1.f);
  std::copy(a.rgba.begin(), a.rgba.end(), strip.rgba.begin());
  std::copy(b.rgba.begin(), b.rgba.end(), strip.rgba.begin() + static_cast<long>(a.h + 4) * strip.w * 4);
  const std::string out = opt.dir + "/volume_walk.png";
  if (!write_png(out, strip, Encode::Linear, err)) return false;
  printf("wrote %s (a sphere from the room's darkest to its brightest place in view, lit by the volume; top: "
         "final, bottom: the scene's lights off, the volume's cube alone)\n",
         out.c_str());
  return true;
}

const DemoSection kSection = {"volume_walk", run};
const DemoRegistrar kRegister(&kSection);

}  // namespace

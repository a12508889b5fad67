// tiershade tests: three features of the scene renderer, on scenes/sphere_grid.gltf (the demo's sphere grid):
//   - orthographic cameras: the loader reads xmag/ymag/znear/zfar and refuses bad values with the
//     place; the view-projection maps the view's corners to the clip cube with square pixels; the
//     C rasteriser covers each sphere's centre and leaves the gaps between spheres empty;
//   - the C renderer's G-buffer (scene_records_cpu): shading its records with the C twin
//     (scene_shade_records) gives the C fallback's frame (scene_shade_cpu) bit for bit, per tier;
//   - deferred frames (scene_deferred_frame): the family's C twin over the frame's records equals
//     the C renderer's frame bit for bit; a scene of several draws is refused;
//   - the double reference (scene_reference_linear): 0 on the background, equal to the float
//     frame within float rounding when no light is folded, and away from the folded sm3 frame
//     by the folding's approximation when 2 of the 6 lights are folded.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene/camera_ortho.h"
#include "conform/family_frame.h"
#include "scene/cpu_renderer.h"
#include "scene/deferred.h"
#include "scene/prepare.h"
#include "scene/reference.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "unit_check.h"

namespace {

const char *kGrid = "scenes/sphere_grid.gltf";

// The records-only paths (deferred frames, the double reference) carry no derivatives and sample
// level 0 (PrepareOptions::mipmaps false): frames compared with them are prepared the same way.
PrepareOptions no_mipmaps() {
  PrepareOptions o;
  o.mipmaps = false;
  return o;
}

// *sel must outlive *p (the prepared draws point into it). mipmaps: the samplers' chains.
bool prepared(const Scene &s, Tier tier, const std::string &hdr, int w, int h, SceneSelection *sel, PreparedScene *p,
              std::string *err, bool mipmaps = false) {
  return select_scene_variants(s, tier, hdr, sel, err) &&
      prepare_scene(s, *sel, w, h, Api::GL33, s.hdr.tone_map_scale, p, err,
                    mipmaps ? PrepareOptions() : no_mipmaps());
}

void test_camera(const Scene &s) {
  check(s.cameras.size() == 1 && s.cameras[0].orthographic && s.cameras[0].xmag == 6.0 && s.cameras[0].ymag == 3.6 &&
            s.cameras[0].znear == 1.0 && s.cameras[0].zfar == 120.0,
        "ortho: the grid's camera is orthographic, xmag 6, ymag 3.6, znear 1, zfar 120");
  // 2:1 output: ymag x aspect (7.2) is the wider: x spans +-7.2, y +-3.6.
  double m[16];
  ortho_view_projection(s.cameras[0], 2.0, m);
  auto clip = [&](double x, double y, double z, double out[4]) {
    for (int r = 0; r < 4; ++r) out[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r];
  };
  double a[4], b[4], c[4];
  clip(-7.2, -3.6, 0, a);
  clip(7.2, 3.6, 0, b);
  clip(0, 0, -59, c);  // 119 in front of the eye at z = 60: just inside zfar
  const bool corners = std::fabs(a[0] + 1) < 1e-12 && std::fabs(a[1] + 1) < 1e-12 && std::fabs(b[0] - 1) < 1e-12 &&
      std::fabs(b[1] - 1) < 1e-12 && a[3] == 1 && b[3] == 1;
  check(corners, "ortho: the view's corners map to clip -1 and +1, w = 1 (2:1 output)");
  check(std::fabs(a[2] - (2.0 * 59 / 119 - 1)) < 1e-12 && c[2] < 1 && c[2] > 0.98,
        "ortho: depth is linear from znear (-1) to zfar (+1)");
  ortho_view_projection(s.cameras[0], 1.0, m);  // square output: xmag (6) is the wider
  clip(6, 6, 0, a);
  check(std::fabs(a[0] - 1) < 1e-12 && std::fabs(a[1] - 1) < 1e-12, "ortho: square output fits xmag, square pixels");
}

void test_camera_errors() {
  std::ifstream f(kGrid);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string text = ss.str();
  char tmpl[] = "/tmp/test_scene_ortho.XXXXXX";
  if (!mkdtemp(tmpl)) return check(false, "mkdtemp");
  const std::string dir = tmpl;
  char cwd[4096];
  if (!getcwd(cwd, sizeof cwd)) cwd[0] = 0;
  for (const char *l : {"sphere_grid.bin", "textures"}) {
    const std::string target = std::string(cwd) + "/scenes/" + l, link = dir + "/" + l;
    if (symlink(target.c_str(), link.c_str()) != 0) check(false, "symlink " + link);
  }
  struct Case {
    const char *from, *to, *expect;
  } cases[] = {
      {"\"xmag\": 6.0", "\"xmag\": 0", "cameras[0] (\"front\").orthographic.xmag: must be > 0"},
      {"\"ymag\": 3.6", "\"ymag\": -1", "cameras[0] (\"front\").orthographic.ymag: must be > 0"},
      {"\"zfar\": 120.0", "\"zfar\": 0.5", "cameras[0] (\"front\").orthographic.zfar: must be > znear"},
      {"\"type\": \"orthographic\"", "\"type\": \"fisheye\"", "Invalid camera type"},
  };
  for (const Case &c : cases) {
    const size_t at = text.find(c.from);
    if (at == std::string::npos) {
      check(false, std::string("ortho error case: ") + c.from, "not found in " + std::string(kGrid));
      continue;
    }
    std::string t = text;
    t.replace(at, strlen(c.from), c.to);
    const std::string path = dir + "/mutant.gltf";
    std::ofstream(path) << t;
    Scene s;
    std::string err;
    const bool ok = load_scene(path, &s, &err);
    check(!ok && err.find(path) == 0 && err.find(c.expect) != std::string::npos,
          std::string("ortho: refused: ") + c.expect, ok ? "loaded" : err);
  }
  if (system(("rm -rf '" + dir + "'").c_str()) != 0) check(false, "rm " + dir);
}

void test_coverage_and_records(const Scene &s) {
  const int w = 160, h = 80;  // 0.09 world units per pixel
  for (Tier tier : {Tier::PS20, Tier::PS2B, Tier::SM3}) {
    SceneSelection sel;
    PreparedScene p;
    std::string err;
    if (!prepared(s, tier, "", w, h, &sel, &p, &err, true)) return check(false, "prepare the grid", err);
    SceneVisibility vis;
    scene_rasterize_cpu(p, &vis, 2);
    const std::string tn = tier_name(tier);
    if (tier == Tier::SM3) {
      // Sphere (col, row) has its centre at ((col - 2) 2.4, (row - 1) 2.4): pixel x = (X / 7.2 + 1) w / 2.
      auto px = [&](double X, double Y) {
        const int x = static_cast<int>((X / 7.2 + 1) * w / 2), y = static_cast<int>((Y / 3.6 + 1) * h / 2);
        return vis.draw[static_cast<size_t>(y) * w + x];
      };
      int centres = 0, gaps = 0;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 5; ++c) {
          centres += px((c - 2) * 2.4, (r - 1) * 2.4) >= 0;
          if (c < 4) gaps += px((c - 2) * 2.4 + 1.2, (r - 1) * 2.4) < 0;
        }
      check(centres == 15 && gaps == 12, "ortho: C rasteriser covers the 15 sphere centres, not the 12 gaps",
            std::to_string(centres) + " centres, " + std::to_string(gaps) + " gaps");
    }
    ImageF direct, via;
    scene_shade_cpu(p, vis, &direct, 2);
    std::vector<int> draw;
    std::vector<float> slots, grads;
    scene_records_cpu(p, vis, &draw, &slots, 2, &grads);
    scene_shade_records(p, draw, slots, &via, 2, &grads);
    long lit = 0;
    for (int d : draw) lit += d >= 0;
    check(direct.rgba == via.rgba && draw == vis.draw && lit > w * h / 3,
          "records: " + tn + ": the C G-buffer shaded by scene_shade_records = the C frame bit for bit",
          std::to_string(lit) + " lit pixels");
  }
}

void test_deferred(const Scene &s) {
  const int w = 120, h = 60;
  std::vector<ShaderDecl> decls;
  std::string err;
  if (!load_shader_decls(&decls, &err)) return check(false, "deferred: shader declarations", err);
  const ShaderFamily *fam = find_family("model_lighting");
  for (Tier tier : {Tier::PS20, Tier::SM3}) {
    const std::string tn = tier_name(tier);
    SceneDeferredFrame f;
    PreparedScene p;
    SceneSelection sel;
    if (!scene_deferred_frame(s, tier, w, h, &f, &err) || !select_scene_variants(s, tier, "", &sel, &err) ||
        !prepare_scene(s, sel, w, h, Api::GL33, s.hdr.tone_map_scale, &p, &err, no_mipmaps()))
      return check(false, "deferred: " + tn, err);
    SceneVisibility vis;
    scene_rasterize_cpu(p, &vis, 2);
    ImageF scene_frame, family_frame;
    scene_shade_cpu(p, vis, &scene_frame, 2);
    cpu_render_frame(*fam, sel.variants.at(0), f.in, &family_frame, 2);
    long lit = 0, differ = 0;
    for (size_t q = 0; q < f.hit.size(); ++q) {
      if (!f.hit[q]) continue;
      ++lit;
      differ += std::memcmp(&scene_frame.rgba[q * 4], &family_frame.rgba[q * 4], 4 * sizeof(float)) != 0;
    }
    check(differ == 0 && lit > w * h / 3 && f.lights_local == (tier == Tier::PS20 ? 2 : 4) &&
              f.lights_local + f.lights_folded == 6,
          "deferred: " + tn + ": the family's C twin over the frame = the C renderer's frame bit for bit",
          std::to_string(differ) + " of " + std::to_string(lit) + " lit pixels differ");
  }
  Scene five;
  SceneDeferredFrame f;
  const bool loaded = load_scene("scenes/model_lighting.gltf", &five, &err);
  const bool ok = loaded && scene_deferred_frame(five, Tier::SM3, 64, 32, &f, &err);
  check(loaded && !ok && err.find("needs one model_lighting draw") != std::string::npos,
        "deferred: a scene of several draws is refused", ok ? "accepted" : err);
}

double max_rel(const std::vector<double> &ref, const ImageF &img, const std::vector<int> &draw) {
  double m = 0;
  for (size_t q = 0; q < draw.size(); ++q) {
    if (draw[q] < 0) continue;
    for (int c = 0; c < 3; ++c)
      m = std::max(m, std::fabs(ref[q * 3 + c] - img.rgba[q * 4 + c]) / std::max(1e-3, std::fabs(ref[q * 3 + c])));
  }
  return m;
}

void test_reference(const Scene &grid) {
  const int w = 160, h = 80;
  std::string err;
  // Four lights, the float path (OUTPUT_MODE 0, scale 1): nothing is folded at sm3.
  Scene s4 = grid;
  s4.lights.resize(4);
  s4.hdr.tone_map_scale = 1.f;
  SceneSelection sel4, sel6;
  PreparedScene p4;
  if (!prepared(s4, Tier::SM3, "float", w, h, &sel4, &p4, &err)) return check(false, "prepare 4 lights", err);
  SceneVisibility vis;
  scene_rasterize_cpu(p4, &vis, 2);
  std::vector<int> draw;
  std::vector<float> slots;
  scene_records_cpu(p4, vis, &draw, &slots, 2);
  ImageF f4;
  scene_shade_cpu(p4, vis, &f4, 2);
  std::vector<double> ref4;
  if (!scene_reference_linear(s4, p4, draw, slots, &ref4, &err, 2)) return check(false, "reference 4 lights", err);
  bool bg = true;
  for (size_t q = 0; q < draw.size(); ++q)
    if (draw[q] < 0) bg = bg && ref4[q * 3] == 0 && ref4[q * 3 + 1] == 0 && ref4[q * 3 + 2] == 0;
  check(bg, "reference: 0 on the background");
  const double e4 = max_rel(ref4, f4, draw);
  check(e4 < 2e-5, "reference: 4 lights, none folded: = the float frame within float rounding",
        "max relative difference " + std::to_string(e4));
  // Six lights at sm3: the frame folds 2 into the ambient cube, the reference shades all 6.
  Scene s6 = grid;
  s6.hdr.tone_map_scale = 1.f;
  PreparedScene p6;
  if (!prepared(s6, Tier::SM3, "float", w, h, &sel6, &p6, &err)) return check(false, "prepare 6 lights", err);
  scene_rasterize_cpu(p6, &vis, 2);
  scene_records_cpu(p6, vis, &draw, &slots, 2);
  ImageF f6;
  scene_shade_cpu(p6, vis, &f6, 2);
  std::vector<double> ref6;
  if (!scene_reference_linear(s6, p6, draw, slots, &ref6, &err, 2)) return check(false, "reference 6 lights", err);
  const double e6 = max_rel(ref6, f6, draw);
  check(e6 > 1e-3 && e6 < 1.0, "reference: 6 lights, 2 folded at sm3: the folding shows, within 100%",
        "max relative difference " + std::to_string(e6));
  // The reference of 6 lights = the reference of the first 4 + that of the last 2 without the
  // ambient cube (the groups of ML_MAX_LIGHTS add up).
  Scene s2 = s6;
  s2.lights.erase(s2.lights.begin(), s2.lights.begin() + 4);
  PreparedScene p2 = p6;
  for (PreparedDraw &d : p2.draws) std::memset(d.ambient, 0, sizeof d.ambient);
  std::vector<double> ref2;
  if (!scene_reference_linear(s2, p2, draw, slots, &ref2, &err, 2)) return check(false, "reference 2 lights", err);
  Scene s4b = s6;
  s4b.lights.resize(4);
  std::vector<double> ref4b;
  if (!scene_reference_linear(s4b, p6, draw, slots, &ref4b, &err, 2)) return check(false, "reference 4 lights", err);
  double worst = 0;
  for (size_t i = 0; i < ref6.size(); ++i) worst = std::max(worst, std::fabs(ref6[i] - (ref4b[i] + ref2[i])));
  check(worst < 1e-12, "reference: 6 lights = first 4 (with the ambient cube) + last 2 (without)",
        "max difference " + std::to_string(worst));
}

}  // namespace

int main() {
  ts_math_init();
  Scene grid;
  std::string err;
  if (!load_scene(kGrid, &grid, &err)) {
    check(false, "load " + std::string(kGrid), err);
  } else {
    test_camera(grid);
    test_camera_errors();
    test_coverage_and_records(grid);
    test_deferred(grid);
    test_reference(grid);
  }
  return finish();
}

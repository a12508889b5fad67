// tiershade tests: the colour-correction frame, scenes/probe_chart.gltf, through the scene renderer
// (glue/demo/color_correction_scene.h; docs/scenes.md, docs/color_correction.md): what the scene
// selects (the chart on the Phong path for $selfillum, no envmap; the mirrors with ENVMAP and
// their explicit probes); that the C fallback draws the chart texture as stored (self-illumination
// with tint 1 and no light: display code = texture code); that the mirror spheres carry
// natural-image content (many colours, clipped highlights, dark areas); and that on every GL
// backend the frame equals the C twins run on GL's own inputs.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if anything failed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "demo/color_correction_scene.h"
#include "demo/scene_files.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "math/ts_math.h"
#include "unit_check.h"

namespace {

int code(float v) { return static_cast<int>(std::lround(v * 255.f)); }

void selection() {
  Scene s;
  SceneSelection sel;
  std::string err;
  if (!load_scene(kProbeChartGltf, &s, &err) || !select_scene_variants(s, Tier::SM3, "", &sel, &err)) {
    check(false, "probe_chart: load and select", err);
    return;
  }
  check(s.lights.empty() && s.probes.size() == 2 && s.hdr.luts.empty() && s.hdr.path == "integer" &&
            s.hdr.tone_map_scale == 1.f,
        "probe_chart: no lights, two probes, integer path at scale 1, no LUTs");
  int chart = 0, mirrors = 0;
  std::set<int> probes;
  std::string why;
  for (const SceneDrawChoice &d : sel.draws) {
    const SceneMaterial &m = s.materials.at(s.primitives.at(d.primitive).material);
    const Variant &v = *d.variant;
    if (m.self_illum)
      chart += v.value("PHONG") == 1 && v.value("ENVMAP") == 0 && v.value("ALBEDO_TEXTURE") == 1 &&
          v.value("OUTPUT_MODE") == 2 && !m.base_texture.repeat;
    if (m.envmap) {
      mirrors += v.value("ENVMAP") == 1 && m.base_color[0] == 0.f && m.phong_boost == 0.f;
      probes.insert(m.probe);
    }
    why += m.name + ": " + v.name() + " probe " + std::to_string(m.probe) + "; ";
  }
  check(chart == 1, "probe_chart: the chart runs the Phong path for $selfillum, its texture clamped", why);
  check(mirrors == 3 && probes == std::set<int>{0, 1}, "probe_chart: three black mirrors sample both probes", why);
}

// 384 x 384: the chart band (the bottom third) is 384 x 128 pixels on its 384 x 128 texture, every
// pixel centre on a texel centre.
void chart_as_stored(const ImageF &f, const SceneImage &tex) {
  const int band = f.h / 3;
  if (tex.w != f.w || tex.h != band) {
    check(false, "probe_chart: chart texture size", std::to_string(tex.w) + "x" + std::to_string(tex.h));
    return;
  }
  // Texture v runs down the image in glTF; which way the frame's rows meet the texture's rows is
  // the loader's business (docs/scenes.md, "Images"): both are tried, the better one counts.
  long exact[2] = {0, 0}, off[2] = {0, 0};
  int worst[2] = {0, 0};
  for (int flip = 0; flip < 2; ++flip)
    for (int y = 0; y < band; ++y)
      for (int x = 0; x < f.w; ++x) {
        const int ty = flip ? band - 1 - y : y;
        int d = 0;
        for (int k = 0; k < 3; ++k)
          d = std::max(d, std::abs(code(f.rgba[(static_cast<size_t>(y) * f.w + x) * 4 + k]) -
                                   code(tex.rgba[(static_cast<size_t>(ty) * tex.w + x) * 4 + k])));
        exact[flip] += d == 0;
        off[flip] += d > 1;
        worst[flip] = std::max(worst[flip], d);
      }
  const int b = exact[1] > exact[0] ? 1 : 0;
  const long n = static_cast<long>(band) * f.w;
  check(off[b] == 0 && exact[b] * 100 >= n * 99, "probe_chart: the C fallback draws the chart texture as stored",
        std::to_string(exact[b]) + " of " + std::to_string(n) + " pixels exact, " + std::to_string(off[b]) +
            " off by more than one code (at most " + std::to_string(worst[b]) + ")");
  printf("# chart: %ld of %ld pixels equal the texture, at most %d code off (rows %s)\n", exact[b], n, worst[b],
         b ? "reversed" : "in texture order");
}

// The big mirror (Grace Cathedral): the disc of radius h/3 centred at (w/3, 2h/3) (rows bottom-up).
void natural_content(const ImageF &f) {
  std::set<int> colours;
  std::vector<int> value;  // max channel code, per pixel
  long clipped = 0;
  const double r = f.h / 3.0 - 1, cx = f.w / 3.0, cy = f.h * 2 / 3.0;
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) > r) continue;
      const float *p = &f.rgba[(static_cast<size_t>(y) * f.w + x) * 4];
      const int r = code(p[0]), g = code(p[1]), b = code(p[2]);
      colours.insert((r << 16) | (g << 8) | b);
      clipped += r == 255 || g == 255 || b == 255;
      value.push_back(std::max(r, std::max(g, b)));
    }
  std::sort(value.begin(), value.end());
  const long n = static_cast<long>(value.size());
  const int p10 = value[n / 10], p50 = value[n / 2];
  check(colours.size() > 5000 && clipped * 100 > n && p10 < 96 && p50 > 80 && p50 < 230,
        "probe_chart: the Grace mirror holds a natural image (many colours, clipped highlights, dark areas)",
        std::to_string(colours.size()) + " colours, " + std::to_string(clipped) + " clipped of " + std::to_string(n) +
            " pixels, value 10th percentile " + std::to_string(p10) + ", median " + std::to_string(p50));
  printf("# Grace mirror: %zu colours, %ld clipped of %ld pixels, value 10th percentile %d, median %d\n",
         colours.size(), clipped, n, p10, p50);
}

void gl_equals_c_twins(const BackendApi &b) {
  const std::string name = std::string("probe_chart: ") + backend_name(b.backend) + "/" + api_name(b.api);
  SceneRenderConfig cfg;
  cfg.backend = b.backend;
  cfg.api = b.api;
  cfg.w = cfg.h = 48;
  cfg.check = true;
  ImageF f;
  SceneRenderResult res;
  std::string note, err;
  if (!cc_scene_frame(cfg, &f, &res, &note, &err)) {
    check(false, name, err);
    return;
  }
  check(res.check_mismatched == 0 && res.check_post_mismatched == 0 && res.check_pixels == 48 * 48,
        name + ": GL's lit pass and display equal the C twins on GL's own inputs",
        std::to_string(res.check_mismatched) + " lit pixels and " + std::to_string(res.check_post_mismatched) +
            " display channels differ, " + std::to_string(res.check_pixels) + " pixels drawn");
}

}  // namespace

int main() {
  ts_math_init();
  selection();
  ImageF f;
  std::string note, err;
  Scene s;
  if (!cc_frame_c(384, &f, &note, &err) || !load_scene(kProbeChartGltf, &s, &err)) {
    check(false, "probe_chart: the C fallback's frame", err);
    return 1;
  }
  printf("# %s\n", note.c_str());
  for (const SceneMaterial &m : s.materials)
    if (m.self_illum) chart_as_stored(f, s.images.at(m.base_texture.image));
  natural_content(f);
  for (const BackendApi &c : all_gl_configs()) gl_equals_c_twins(c);
  return g_failed ? 1 : 0;
}

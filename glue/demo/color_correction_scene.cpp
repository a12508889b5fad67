// tiershade demo: the frame (scenes/probe_chart.gltf through the scene renderer) and the example
// corrections of the colour-correction demo and benchmark (color_correction_scene.h).
#include "demo/color_correction_scene.h"

#include <algorithm>
#include <cmath>

#include "color/ciede2000.h"
#include "base/srgb.h"
#include "demo/scene_files.h"
#include "scene/scene.h"
#include "scene/selection.h"

bool cc_scene_frame(const SceneRenderConfig &cfg, ImageF *frame, SceneRenderResult *res, std::string *note,
                    std::string *err) {
  Scene s;
  SceneSelection sel;
  if (!load_scene(kProbeChartGltf, &s, err) || !select_scene_variants(s, Tier::SM3, "integer", &sel, err))
    return false;
  if (!s.hdr.luts.empty()) {
    *err = std::string(kProbeChartGltf) + ": extras.tiershade.hdr.luts: the colour-correction frame is taken before " +
        "colour correction: the scene must have no LUTs";
    return false;
  }
  if (!render_scene(s, sel, cfg, res, err)) return false;
  *frame = display_image(*res);
  *note = std::string(kProbeChartGltf) + " (mirror spheres of the Grace Cathedral and Uffizi probes above a colour " +
      "chart; scene renderer, " + (cfg.backend == Backend::CPU ? "C fallback" : backend_name(cfg.backend)) +
      ", sm3, integer path, " + std::to_string(sel.variants.size()) + " variants)";
  return true;
}

bool cc_frame_c(int size, ImageF *frame, std::string *note, std::string *err, double *frame_ms) {
  SceneRenderConfig cfg;
  cfg.backend = Backend::CPU;
  cfg.w = cfg.h = size;
  SceneRenderResult res;
  if (!cc_scene_frame(cfg, frame, &res, note, err)) return false;
  if (frame_ms) *frame_ms = res.frame_ms;
  return true;
}

bool cc_examples(std::vector<CcExample> *out, std::string *err) {
  out->clear();
  const char *const files[][2] = {{"day_for_night", "scenes/luts/day_for_night.cube"},
                                  {"desaturate", "scenes/luts/desaturate.cube"},
                                  {"warm", "scenes/luts/warm.cc"}};
  for (const auto &f : files) {
    CcExample e;
    e.name = f[0];
    e.file = f[1];
    TransformSpec s;
    s.kind = TransformSpec::Kind::File;
    s.file = repo_file(f[1]);
    if (!e.transform.open(s, err)) return false;
    out->push_back(std::move(e));
  }
  return true;
}

ImageF cc_apply_reference(const ColorTransform &t, const ImageF &frame) {
  ImageF out = frame;
  const size_t n = static_cast<size_t>(frame.w) * frame.h;
  std::vector<float> rgb(n * 3);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) rgb[i * 3 + k] = std::min(1.f, std::max(0.f, frame.rgba[i * 4 + k]));
  t.apply(rgb.data(), n);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const float v = rgb[i * 3 + k];
      out.rgba[i * 4 + k] = std::isnan(v) ? 0.f : std::min(1.f, std::max(0.f, v));
    }
  return out;
}

void cc_frame_difference(const ImageF &a, const ImageF &b, double *max, double *mean) {
  const size_t n = static_cast<size_t>(a.w) * a.h;
  double m = 0, s = 0;
  for (size_t i = 0; i < n; ++i) {
    const float *p = &a.rgba[i * 4], *q = &b.rgba[i * 4];
    const double d = ciede2000(srgb_to_lab(p[0], p[1], p[2]), srgb_to_lab(q[0], q[1], q[2]));
    m = std::max(m, d);
    s += d;
  }
  *max = m;
  *mean = n ? s / static_cast<double>(n) : 0;
}

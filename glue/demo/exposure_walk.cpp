// tiershade demo: the exposure adaptation sequence (see hdr_adaptation.h).
#include "demo/exposure_walk.h"

#include <algorithm>

#include "math/hdr_formats.h"

AdaptationSpec default_adaptation_spec() {
  AdaptationSpec s;
  // env_tonemap_controller-style overrides (fact sheet section 8): the dark room may be
  // exposed up to 16x, daylight down to 0.05; outside both boxes the defaults [0.5, 2] hold.
  s.regions.push_back({{-1e9, -1e9, -1e9}, {0.0 - 1e-9, 1e9, 1e9}, 0.5, 16.0, -1.0});
  s.regions.push_back({{0.0, -1e9, -1e9}, {1e9, 1e9, 1e9}, 0.05, 2.0, -1.0});
  return s;
}

void adaptation_camera(const AdaptationSpec &spec, int f, double pos[3]) {
  pos[0] = (f - spec.door_frame) * 0.1;
  pos[1] = 0.0;
  pos[2] = 5.0;
}

namespace {

// One step of the loop shared by both runs: the settings at the camera and the controller.
void control(const AdaptationSpec &spec, int f, const ae_histogram &h, ae_state *st) {
  ae_settings def, s;
  ae_default_settings(&def);
  double pos[3];
  adaptation_camera(spec, f, pos);
  ae_settings_at(&def, spec.regions.data(), static_cast<int>(spec.regions.size()), pos, &s);
  ae_update(st, &h, &s, 1.0 / spec.fps);
}

HistogramConfig histogram_config(const AdaptationScenes &sc, const AdaptationSpec &spec) {
  HistogramConfig c;
  c.w = sc.room.w;
  c.h = sc.room.h;
  c.input_encoding = 1;  // the integer path's sRGB-encoded RGBA8 frame
  c.alpha = spec.alpha;
  return c;
}

bool kept(const std::vector<int> &keep, int f) { return std::find(keep.begin(), keep.end(), f) != keep.end(); }

}  // namespace

bool run_adaptation_gl(PassRunner &run, Backend b, Api api, const AdaptationScenes &sc, const AdaptationSpec &spec,
                       const std::vector<int> &keep, std::vector<AdaptationFrame> *out,
                       std::vector<HistogramMeasurement> *measured, int *late_reads, std::string *err) {
  HdrPipelineGl gl(run, api);
  // The float-path variant is not used here; the display variant stands in for both.
  if (!gl.init(*sc.lit, sc.lit_display, sc.lit_display, sc.room, err)) return false;
  LuminanceHistogramGl hist(run, b, api, histogram_config(sc, spec));
  if (!hist.init(err)) return false;
  ae_state st;
  ae_state_init(&st, spec.initial_scale, 0.0);
  out->clear();
  for (int f = 0; f < spec.frames; ++f) {
    const FamilyInputs &scene = f < spec.door_frame ? sc.room : sc.daylight;
    AdaptationFrame fr;
    fr.scale = st.scale;
    if (!gl.integer_frame(scene.shared, static_cast<float>(st.scale), err)) return false;
    if (!hist.frame(gl.display().tex, 1.0f, f, measured, err)) return false;
    if (kept(keep, f) && !read_rgba8(run.gl(), gl.display(), &fr.display, err)) return false;
    control(spec, f, hist.histogram(), &st);
    fr.goal = st.goal;
    fr.hist = hist.histogram();
    out->push_back(fr);
  }
  *late_reads = hist.late_reads();
  return true;
}

void run_adaptation_c(const AdaptationScenes &sc, const AdaptationSpec &spec, const std::vector<int> &keep,
                      std::vector<AdaptationFrame> *out, std::vector<HistogramMeasurement> *measured) {
  LuminanceHistogramCpu hist(histogram_config(sc, spec));
  ae_state st;
  ae_state_init(&st, spec.initial_scale, 0.0);
  out->clear();
  std::vector<float> texels;
  for (int f = 0; f < spec.frames; ++f) {
    const FamilyInputs &scene = f < spec.door_frame ? sc.room : sc.daylight;
    AdaptationFrame fr;
    fr.scale = st.scale;
    HdrFrameC c;
    hdr_integer_frame_c(*sc.lit, sc.lit_display, scene, static_cast<float>(st.scale), &c);
    texels.resize(c.display.size());
    for (size_t i = 0; i < c.display.size(); ++i) texels[i] = ts_unorm8_to_float(c.display[i]);
    hist.frame(texels.data(), 1.0f, f, measured);
    if (kept(keep, f)) fr.display = c.display;
    control(spec, f, hist.histogram(), &st);
    fr.goal = st.goal;
    fr.hist = hist.histogram();
    out->push_back(fr);
  }
}

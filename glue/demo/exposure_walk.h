// tiershade demo: the exposure adaptation sequence: the camera walks from a dark room
// through a door into daylight while the auto exposure runs in a closed loop (integer
// path: RGBA8 frames, the running histogram one bucket per frame, the controller of
// c_ref/exposure/exposure_control.h with designer overrides per region). The same sequence runs
// on GL (the GPU histogram) and in C (the exact twin); with equal counts, the two give
// the same exposure in every frame.
#pragma once
#include <string>
#include <vector>

#include "exposure/exposure_control.h"
#include "hdr/paths.h"
#include "hdr/luminance_histogram.h"

struct AdaptationSpec {
  int frames = 120;
  int door_frame = 24;  // the first frame outside
  double fps = 30.0;
  double initial_scale = 1.0;
  double alpha = 0.0625;  // the histogram's temporal prefilter
  std::vector<ae_region> regions;  // designer overrides (camera x < 0: the room; x >= 0: outdoors)
};

// Room and outdoor overrides: the room allows exposures up to 16, outdoors down to 0.05.
AdaptationSpec default_adaptation_spec();
// Camera position of frame f: x = (f - door_frame) * 0.1, so x < 0 inside the room.
void adaptation_camera(const AdaptationSpec &spec, int f, double pos[3]);

struct AdaptationScenes {
  const ShaderFamily *lit = nullptr;
  Variant lit_display;  // integer path: OUTPUT_MODE 2
  FamilyInputs room, daylight;  // same G-buffer, the two lightings in the shared slots
};

struct AdaptationFrame {
  double scale = 0, goal = 0;  // the exposure the frame was rendered with, and the goal after it
  ae_histogram hist;  // the running histogram after the frame
  std::vector<uint8_t> display;  // RGBA8 codes (kept for the frames asked for)
};

// keep: which frames keep their RGBA8 image. The GL run also returns its histogram
// measurements (for the equality check) and the reads that had to wait.
bool run_adaptation_gl(PassRunner &run, Backend b, Api api, const AdaptationScenes &sc, const AdaptationSpec &spec,
                       const std::vector<int> &keep, std::vector<AdaptationFrame> *out,
                       std::vector<HistogramMeasurement> *measured, int *late_reads, std::string *err);
void run_adaptation_c(const AdaptationScenes &sc, const AdaptationSpec &spec, const std::vector<int> &keep,
                      std::vector<AdaptationFrame> *out, std::vector<HistogramMeasurement> *measured);

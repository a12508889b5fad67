// tiershade browser: the WebGL 2 demo page of a scene (issue 14; docs/bundles.md, "The WebGL 2 demo
// page"). `tiershade web --bundle B --dump D -o DIR` joins an essl300 bundle (tiershade variants
// SCENE --target essl300) and the draw dump of the same scene (tiershade render SCENE --dump-draws)
// into a page that needs nothing else: DIR/index.html, webgl_scene.js (glue/browser, embedded) and
// scene.js (the programs, every draw's geometry, uniform values and textures, the camera). The page
// replays the draws in WebGL 2 into an RGBA32F target with the bundle's programs, with an orbit
// camera (drag: orbit, wheel: distance) whose u_view_proj / u_eye / u_eye_position are recomputed in
// JavaScript as glue/scene/prepare.cpp computes them (double, then float). Opened with `?check`, it
// draws the dump's camera once and writes the frame's floats into <pre id="out">: the check below.
#pragma once
#include <string>
#include <vector>

struct WebScenePage {
  int w = 0, h = 0;
  size_t programs = 0, draws = 0, textures = 0;
  size_t bytes = 0;  // scene.js
};

// Writes the page (atomically: DIR.tmp.<pid>, renamed; an existing DIR is replaced only if it holds
// scene.js). False with *err naming the file and place: a bundle that is not essl300, a draw whose
// variant the bundle lacks, a dump without a camera, missing or short data files.
bool webgl_scene_write_page(const std::string &bundle_dir, const std::string &dump_dir, const std::string &dir,
                            WebScenePage *info, std::string *err);

// A pixel is within when every channel's |browser - llvmpipe| <= abs + rel * |llvmpipe|; the check
// passes when at most `share` of the pixels are not (and the camera uniforms are bit-exact). The
// default and its justification: docs/bundles.md, "The WebGL 2 demo page".
struct WebSceneTolerance {
  double abs = 1.0 / 64, rel = 1.0 / 16, share = 0.005;
};

struct WebSceneCheck {
  std::string renderer;
  int view_proj_differ = -1, view_proj_compared = 0;  // JS-computed camera uniforms against the dump's, bit for bit
  size_t pixels = 0, equal = 0;  // pixels whose four channels equal frame.f32's bit for bit
  size_t within = 0;  // pixels within the tolerance
  double median_diff = 0, p99_diff = 0, max_diff = 0;  // per pixel: the largest channel difference, absolute
  int worst_x = 0, worst_y = 0;
  bool pass = false;
};

// Opens DIR/index.html?check in headless Chromium (ANGLE on SwiftShader) and compares its first
// frame with the dump's frame.f32 (what tiershade render drew on llvmpipe): *out has the numbers and
// whether they are inside the tolerance. False with *err when the page or the browser fails.
bool webgl_scene_check(const std::string &dir, const std::string &dump_dir, int timeout_s,
                       const WebSceneTolerance &tol, WebSceneCheck *out, std::string *err);

// tiershade scene: one rendered frame of a scene, end to end: the variant selection's draws
// (glue/scene/prepare.h), the lit pass on GL (glue/scene/gl_renderer.h) or by the C fallback
// (glue/scene/cpu_renderer.h), then the HDR path the scene asks for: integer (the shaders' tone-map
// scale and sRGB, RGBA8) or float (fp16 frame, auto exposure from the running histogram,
// bloom, tone map; glue/hdr/paths.h), then colour correction with the scene's LUTs
// (color_correction family). GL frames run every pass on GL; the C fallback runs their
// bit-exact twins.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/fns.h"
#include "base/image.h"
#include "scene/scene.h"
#include "scene/selection.h"

struct PreparedDraw;
struct PreparedScene;

struct SceneRenderConfig {
  Backend backend = Backend::EGL;  // Backend::CPU: the C fallback alone
  Api api = Api::GLES3;
  int w = 1280, h = 720;
  int threads = 0;  // C fallback workers (0 = all cores)
  bool check = false;  // GL: also shade GL's own G-buffer with the C twin and compare bit for bit
  bool mipmaps = true;  // the samplers' mip chains (PrepareOptions::mipmaps; false: level 0 only)
  // MSAA samples per pixel (0 or 1: none; 2, 4, 8: the integer path's multisampled RGBA8
  // target, glue/scene/msaa.h).
  int msaa = 0;
  // GL frames: the world probes' cube maps rendered on GL (glue/scene/probe_render.h); false: by
  // the C fallback while preparing, as on every backend (the same cubes for GL and C frames).
  bool gl_probe_cubes = false;
  int exposure_frames = 300;  // auto exposure: frames (at 30 fps) of the running histogram on the still frame
  // Progress of long stages: (stage, fraction done).
  std::function<void(const char *, double)> progress;
  // GL: called for each draw after its program, uniforms and textures are bound (draw capture).
  std::function<void(const GlFns &, const PreparedScene &, const PreparedDraw &, GLuint program)> on_draw;
  // Called with the lit pass as drawn (before the float path stores it as fp16).
  std::function<void(const ImageF &lit)> on_lit;
};

struct SceneRenderResult {
  ImageF lit;  // the lit pass (RGBA32F; linear, or display-encoded by the shader)
  std::vector<uint8_t> display;  // the final frame, RGBA8 codes, rows bottom-up
  int w = 0, h = 0;
  double tone_map_scale = 1;  // the exposure the frame was tone-mapped with
  bool auto_exposure = false;
  // Times (ms): preparing draws (bake, textures), compiling the selected variants (GL), the lit
  // pass, post-processing, the whole frame (first frame: compile included).
  double prepare_ms = 0, compile_ms = 0, lit_ms = 0, post_ms = 0, frame_ms = 0;
  // The draws' vertex arrays (PreparedScene::geometry_bytes, each shared DrawGeometry once).
  size_t geometry_bytes = 0;
  int geometries = 0, draws = 0;
  // --check: channels where GL's frame differs from the C twin on GL's G-buffer (-1: not run).
  long check_mismatched = -1, check_pixels = 0;
  uint32_t check_max_ulp = 0;
  ImageF check_lit;  // --check: the C twin's lit pass on GL's G-buffer (what GL is compared with)
  // --check: display channels where GL's HDR path and colour correction differ from their C twins
  // run on GL's lit frame (-1: not run).
  long check_post_mismatched = -1, check_post_channels = 0;
  // --check with gl_probe_cubes: cube texels where GL differs from the C twin on GL's G-buffer (-1: not run).
  long check_cube_mismatched = -1, check_cube_texels = 0;
  // MSAA: the samples per pixel the frame was rendered with (0: none); --check: interior
  // pixels against the C twin on GL's G-buffer, edge pixels against the C fallback's MSAA frame.
  int msaa_samples = 0;
  long check_msaa_interior = -1, check_msaa_edge = 0, check_msaa_edge_over_1 = 0, check_msaa_edge_over_64 = 0;
  int check_msaa_edge_max = 0, check_msaa_interior_max = 0;
  long check_msaa_background = 0, check_msaa_background_mismatched = 0;
  std::vector<std::string> notes;
};

// A renderer kept across frames (benchmarks): init() prepares the draws and, on GL, compiles
// the selected variants and uploads everything; frame() renders one frame (the first one
// also JIT-compiles the shaders on llvmpipe).
class SceneRenderer {
 public:
  SceneRenderer();
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer &) = delete;
  SceneRenderer &operator=(const SceneRenderer &) = delete;
  bool init(const Scene &s, const SceneSelection &sel, const SceneRenderConfig &cfg, std::string *err);
  bool frame(SceneRenderResult *out, std::string *err);
  double prepare_ms() const;
  double compile_ms() const;

 private:
  struct Impl;
  Impl *impl_;
};

// One frame: init + frame; res->frame_ms includes both.
bool render_scene(const Scene &s, const SceneSelection &sel, const SceneRenderConfig &cfg, SceneRenderResult *out,
                  std::string *err);

// The display frame as an image (codes / 255, rows bottom-up), for PNG/EXR writers.
ImageF display_image(const SceneRenderResult &r);

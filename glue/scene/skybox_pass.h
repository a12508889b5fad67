// tiershade scene: the HDR skybox of a scene with a sky (extras.tiershade.sky; talk: the HDR
// skybox): the sky's lat-long image resampled on the host into six cube faces (as Source's sky is
// six faces), its skybox variant's shared slots (the camera's direction vectors, the radiance
// scale, the tone-map scale), and the pass that draws it where no geometry covers a pixel: on GL a
// full-screen draw of shaders/skybox.fs before the geometry (no depth test or write; the geometry
// then overwrites what it covers), in C the twin c_ref/twins/skybox.c on the background pixels.
// Both shade exactly the pixels whose draw is -1, with the same record: the frames stay bit-identical.
// A scene without a sky has no skybox variant (glue/scene/selection.cpp), no cube and no pass.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gl/float_target.h"
#include "math/ts_math.h"
#include "shaderlib/variants.h"

struct Scene;
struct PreparedScene;
class GlRenderer;

struct PreparedSky {
  const Variant *variant = nullptr;  // the selection's skybox variant; nullptr: no sky, no pass
  TextureDesc cube;  // u_sky: six faces of fp16 values (LINEAR; NEAREST on GLES, as the envmaps)
  std::vector<ts_vec4f> shared;  // the SB_SLOTS record, the pixel slot (the position) set per pixel
  bool present() const { return variant != nullptr; }
};

// The cube face size made from a w x h lat-long sky: w / 2 (each face spans a quarter of the
// longitudes at twice the image's own texel density, so bilinear resampling loses little), in 16..1024.
int skybox_face_size(int lat_long_w);

// The camera's direction vectors of a view-projection matrix (column-major): the world direction
// through the pixel at ndc (x, y) is forward + x * right + y * up (not normalised). Perspective:
// the inverse of the matrix's x, y and w rows on directions; orthographic: every pixel looks along
// the view axis (right = up = 0).
void skybox_camera_vectors(const float view_proj[16], double forward[3], double right[3], double up[3]);

// Fills p->sky from the scene's sky and the selection's skybox variant (sel_variant; nullptr: none).
// api: cube maps are NEAREST on GLES (Mesa forces seamless filtering there; docs/conformance.md).
bool prepare_skybox(const Scene &s, const Variant *sel_variant, Api api, PreparedScene *p, std::string *err);

// The camera slots of the sky's record (its size and direction vectors) for a view-projection matrix and
// a w x h target (a probe's cube face, glue/scene/probe_render.h, draws the sky from the probe).
void skybox_set_camera(PreparedSky *sky, const float view_proj[16], int w, int h);

// The tone-map scale of the sky's record (set_scene_tone_map_scale calls it).
void skybox_set_tone_map_scale(PreparedSky *sky, float scale);

// The record of pixel (x, y): the shared slots and its position (x + 0.5, y + 0.5), gl_FragCoord.
void skybox_record(const PreparedSky &sky, int x, int y, ts_vec4f rec[]);

// C: shades every pixel whose draw is < 0 with the twin (skybox_f), rows in parallel. No sky: nothing.
void skybox_shade_background(const PreparedSky &sky, int w, int h, const int *draw, float *rgba, int threads);
// The same for row y alone (draw_row, rgba_row: the row's w pixels), on the calling thread.
void skybox_shade_row(const PreparedSky &sky, int w, int y, const int *draw_row, float *rgba_row);

// GL: the skybox's program and cube texture, and its full-screen draw into the bound framebuffer.
class SkyboxGl {
 public:
  SkyboxGl(GlRenderer &r, Api api) : r_(r), api_(api) {}
  ~SkyboxGl();
  bool init(const PreparedSky &sky, std::string *err);
  // Draws the sky over the whole target (depth test off, no depth write; state restored to the
  // scene pass's: depth test LESS with writes). The caller rebinds its vertex array.
  bool draw(const PreparedSky &sky, std::string *err);

 private:
  GlRenderer &r_;
  Api api_;
  GLuint program_ = 0, tex_ = 0;
};

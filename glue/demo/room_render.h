// tiershade demo: renders world_lighting frames of the room scene (scene_world.h) in GL
// (deferred passes, one per cube-map probe, composited per pixel by the probe of each
// pixel's wall) and with the C twin (float32, bit-exact; or the double reference).
// Shared by the demo (demo_world_lighting.cpp) and the benchmark (bench_world_lighting.cpp).
#pragma once
#include <string>
#include <vector>

#include "conform/family_frame.h"
#include "demo/room_scene.h"

struct WorldPass {
  const Variant *variant;
  const TextureDesc *page;  // the encoded lightmap page
  bool white_base = false;  // "lightmaps only": base texture 1
  bool nearest_cube = false;
};

// GL programs and textures of every probe pass, set up once for repeated draws (timing).
struct WorldGl {
  std::vector<GlFrameProgram> programs;
  std::vector<FamilyInputs> inputs;
};
bool world_gl_setup(GlRenderer &r, Api api, const WorldFrame &f, const WorldBake &b, const WorldPass &p, WorldGl *g,
                    std::string *err);
// *draw_ms (optional) receives the summed draw time of the passes.
bool world_gl_draw(GlRenderer &r, const WorldGl &g, const WorldFrame &f, ImageF *out, std::string *err,
                   double *draw_ms = nullptr);
void world_gl_release(GlRenderer &r, WorldGl *g);
// Setup, one draw, release.
bool world_render_gl(GlRenderer &r, Api api, const WorldFrame &f, const WorldBake &b, const WorldPass &p, ImageF *out,
                     std::string *err, double *draw_ms = nullptr);
// C float32 twin (threads: 0 = all cores).
void world_render_cpu(const WorldFrame &f, const WorldBake &b, const WorldPass &p, ImageF *out, int threads = 0);
// C double reference, rgb as doubles (4 per pixel).
void world_render_double(const WorldFrame &f, const WorldBake &b, const WorldPass &p, std::vector<double> *out);

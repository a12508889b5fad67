// tiershade scene: world probes' cube maps rendered in-engine (talk: "cube maps are pre-computed
// in-engine from the level data using rendering ... especially interesting for HDR"). Six 90-degree
// faces from the probe (GL's cube-face axes, glue/base/cube_faces.h), each one frame of the scene
// renderer: the world draws of the prepared scene with their baked lightmaps (world_lighting, the
// same variants without the envmap: a cube does not see specular, so no cube depends on another;
// the fp16 lightmap encoding, the HDR page as Source holds it at run time; tone-map scale 1: linear
// HDR radiance), the HDR sky where no geometry covers a pixel (glue/scene/skybox_pass.h), and
// emitting faces with their exitant radiance (world_lighting has no emission term: an emitter is
// drawn flat on a white base with emission + reflectivity x its flat lightmap in its page block).
// Models are not drawn (the cube is the static world's). On GL into the RGBA32F target and read
// back (glue/scene/gl_renderer.h), or by the C fallback's rasteriser and twins
// (glue/scene/cpu_renderer.h); the C twin on GL's G-buffer gives GL's texels bit for bit, the C
// fallback's own rasteriser differs from llvmpipe's interpolation by rounding (docs/world_lighting.md).
#pragma once
#include <deque>
#include <string>
#include <vector>

#include "gl/context.h"
#include "scene/prepare.h"

class GlRenderer;
class SceneGl;

// The world as a probe sees it, built once from a prepared scene (its world draws, textures, sky).
struct ProbeView {
  PreparedScene p;
  std::deque<Variant> variants;  // the draws' cube variants (p.draws point into it)
  int max_size = 0;  // the largest cube edge it renders (GL's target)
};
bool make_probe_view(const Scene &s, const PreparedScene &ps, ProbeView *v, std::string *err);

// Sets the view to face `face` (0..5, +X -X +Y -Y +Z -Z) of a cube of edge `size` at `pos`: the
// camera there looking along the face's axis, 90 degrees, near plane kProbeNear, no far plane;
// pixel (x, y) is the cube texel (x, y) of the face (the direction cube_face_direction(face,
// 2 (x + 0.5) / size - 1, 2 (y + 0.5) / size - 1)).
const double kProbeNear = 0.01;
void probe_view_face(ProbeView *v, const double pos[3], int size, int face);

// One cube's six faces (6 x size x size RGBA, faces one after another as TextureDesc holds a cube,
// alpha 1, unscaled); `draw` (optional): each texel's draw (index into v->p.draws, -1: the sky). GL:
// `check` (optional) receives the texels whose rgb differ from the C twin run on GL's own G-buffer
// of each face (scene_shade_records).
void render_probe_cube_cpu(ProbeView *v, const double pos[3], int size, int threads, std::vector<float> *rgba,
                           std::vector<int> *draw = nullptr);
bool render_probe_cube_gl(ProbeView *v, SceneGl *g, const double pos[3], int size, std::vector<float> *rgba,
                          std::string *err, long *check = nullptr, std::vector<int> *draw = nullptr);

// Renders every pending cube of ps->probe_cubes (source "pending") into its texture (times the
// probe's scale, clamped to fp16's range), each once, and sets its source and time; a scene
// without pending cubes renders nothing. GL: on `r` (its context current), `gl_name` naming it in
// the source ("GL egl/gles3"); check: each face also against the C twin on GL's G-buffer.
bool render_probe_cubes_cpu(const Scene &s, PreparedScene *ps, int threads, std::string *err);
bool render_probe_cubes_gl(const Scene &s, PreparedScene *ps, GlRenderer &r, Api api, const std::string &gl_name,
                           bool check, std::string *err);

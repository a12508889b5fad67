// tiershade bundle: the draw dump, a neutral capture of a rendered frame that a bare GL program
// (tests/bundle/bare_gl_render.cpp) replays with a shader bundle and no tiershade code: per
// draw its variant, geometry, the values of its active uniforms and its textures, plus the
// frame tiershade rendered. Format: docs/bundles.md ("The draw dump").
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/fns.h"
#include "gl/float_target.h"

// One active non-sampler uniform as set: every array element, in element order; float, vecN
// and matN (column-major) as their floats; int/ivecN/bool/bvecN converted to float.
struct DumpUniform {
  std::string name;  // base name ("u_lights", not "u_lights[0]")
  std::string type;  // GLSL type name: "vec4", "mat4", "int", ...
  int array_size = 0;  // 0 = not an array
  std::vector<float> values;
};

struct DumpDraw {
  std::string shader, variant;  // ShaderDecl name and Variant::name(): the manifest's "shader"/"name"
  std::vector<float> position, normal, uv, tangent;  // per vertex 3, 3, 2, 4 (tangent may be empty)
  std::vector<float> lightmap;  // per vertex 4: world_lighting's a_lightmap (may be empty)
  std::vector<uint32_t> indices;  // triangles
  std::vector<DumpUniform> uniforms;  // from dump_capture_uniforms
  // Sampler name = TextureDesc::sampler. Shared, not copied: the draws of a scene of hundreds of
  // models bind the same few textures (the dump hashes and writes each one once).
  std::vector<std::shared_ptr<const TextureDesc>> textures;
};

// The camera the frame was rendered from, as the scene gives it (docs/bundles.md, "The draw dump"):
// an engine or the WebGL demo page recomputes u_view_proj, u_eye and u_eye_position from it.
struct DumpCamera {
  bool present = false;
  bool orthographic = false;
  double eye[3] = {0, 0, 0}, forward[3] = {0, 0, -1}, up[3] = {0, 1, 0};  // world space, unit forward/up
  double yfov = 0, znear = 0, zfar = 0;  // perspective (radians; zfar 0: infinite)
  double xmag = 0, ymag = 0;  // orthographic half extents
};

struct DumpFrame {
  int w = 0, h = 0;
  DumpCamera camera;
  float clear[4] = {0, 0, 0, 0};
  std::string depth_format = "DEPTH_COMPONENT24";  // or "DEPTH_COMPONENT32F"
  std::vector<DumpDraw> draws;
  std::vector<float> rgba;  // the colour target after the last draw: w*h*4, rows bottom-up, RGBA32F
};

// Reads every active non-sampler uniform's current value from a linked program (call it after
// setting a draw's uniforms, before the draw). Sorted by name.
bool dump_capture_uniforms(const GlFns &gl, GLuint program, std::vector<DumpUniform> *out, std::string *err);

// Writes dir/draws.json, dir/*.f32 / *.u32 (geometry, textures, shared when equal) and
// dir/frame.f32 atomically (dir.tmp.<pid>, then renamed; an existing dir is replaced only
// when it holds draws.json). Checks sizes and index ranges first; *err names the draw.
bool write_draw_dump(const std::string &dir, const DumpFrame &f, std::string *err);

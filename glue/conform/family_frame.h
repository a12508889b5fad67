// tiershade conform: whole frames of a shader family: deferred-style GL frames
// (per-pixel G-buffer record + production uniforms) and the C fallback renderer,
// which shades the same frame with the bit-exact twin on every core.
#pragma once
#include <string>
#include <vector>

#include "families/family.h"
#include "gl/float_target.h"

struct GlFrameProgram {
  GLuint program = 0;
  std::vector<std::pair<std::string, GLuint>> textures;
};

// Builds the deferred program and uploads the frame's textures (kept for repeated draws).
bool gl_frame_setup(GlRenderer &r, Api api, const ShaderFamily &f, const Variant &v, const FamilyInputs &in,
                    GlFrameProgram *fp, std::string *err, const std::string &float_precision = "highp");
bool gl_frame_draw(GlRenderer &r, const GlFrameProgram &fp, const FamilyInputs &in, ImageF *out, double *draw_ms,
                   std::string *err);
void gl_frame_release(GlRenderer &r, GlFrameProgram *fp);

// The C fallback: float32 twin, bit-exact with llvmpipe; `threads` workers (0 = all cores).
void cpu_render_frame(const ShaderFamily &f, const Variant &v, const FamilyInputs &in, ImageF *out, int threads = 0);
// The double-precision reference of the same frame (rgba, 4 doubles per pixel).
void cpu_render_frame_double(const ShaderFamily &f, const Variant &v, const FamilyInputs &in, std::vector<double> *out,
                             int threads = 0);

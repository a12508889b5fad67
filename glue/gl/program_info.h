// tiershade gl: the active attributes and uniforms of a linked GL program, as the
// driver reports them (array uniforms by their base name, "u_lights[0]" -> "u_lights").
#pragma once
#include <string>
#include <vector>

#include "gl/fns.h"

struct ProgramVar {
  std::string name;  // base name, no "[0]"
  GLenum type = 0;  // GL_FLOAT_VEC4, GL_SAMPLER_2D, ...
  int array_size = 1;  // elements (1 for a non-array)
  bool is_array = false;
};

// Attributes in the order a_position, a_normal, a_uv, a_tangent, a_lightmap, a_corner, then
// the rest by name; uniforms sorted by name. Fails (with *err) on a type gl_types.h does not know.
bool program_attributes(const GlFns &gl, GLuint program, std::vector<ProgramVar> *out, std::string *err);
bool program_uniforms(const GlFns &gl, GLuint program, std::vector<ProgramVar> *out, std::string *err);

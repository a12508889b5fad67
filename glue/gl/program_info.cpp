// tiershade gl: active attributes and uniforms of a program (see program_info.h).
#include "gl/program_info.h"

#include <algorithm>

#include "gl/type_names.h"

namespace {

int attribute_rank(const std::string &n) {
  static const char *const kOrder[] = {"a_position", "a_normal", "a_uv", "a_tangent", "a_lightmap", "a_corner"};
  for (int i = 0; i < 6; ++i)
    if (n == kOrder[i]) return i;
  return 6;
}

using GetActive = void(APIENTRYP)(GLuint, GLuint, GLsizei, GLsizei *, GLint *, GLenum *, GLchar *);

bool collect(const GlFns &gl, GLuint program, GLenum count_pname, GLenum maxlen_pname, GetActive get, const char *what,
             std::vector<ProgramVar> *out, std::string *err) {
  out->clear();
  GLint n = 0, maxlen = 0;
  gl.GetProgramiv(program, count_pname, &n);
  gl.GetProgramiv(program, maxlen_pname, &maxlen);
  std::vector<GLchar> buf(static_cast<size_t>(std::max(maxlen, 1)) + 1, 0);
  for (GLint i = 0; i < n; ++i) {
    GLsizei len = 0;
    GLint size = 0;
    GLenum type = 0;
    get(program, static_cast<GLuint>(i), static_cast<GLsizei>(buf.size()), &len, &size, &type, buf.data());
    ProgramVar v;
    v.name.assign(buf.data(), static_cast<size_t>(std::max(len, 0)));
    v.type = type;
    v.array_size = size;
    const size_t br = v.name.find('[');
    if (br != std::string::npos) {
      v.name.resize(br);
      v.is_array = true;
    }
    if (!*gl_type_glsl_name(type)) {
      *err =
          std::string(what) + " '" + v.name + "' has a GL type tiershade does not know (" + std::to_string(type) + ")";
      return false;
    }
    out->push_back(v);
  }
  return true;
}

}  // namespace

bool program_attributes(const GlFns &gl, GLuint program, std::vector<ProgramVar> *out, std::string *err) {
  if (!collect(gl, program, GL_ACTIVE_ATTRIBUTES, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, gl.GetActiveAttrib, "attribute", out,
               err))
    return false;
  std::sort(out->begin(), out->end(), [](const ProgramVar &a, const ProgramVar &b) {
    const int ra = attribute_rank(a.name), rb = attribute_rank(b.name);
    return ra != rb ? ra < rb : a.name < b.name;
  });
  return true;
}

bool program_uniforms(const GlFns &gl, GLuint program, std::vector<ProgramVar> *out, std::string *err) {
  if (!collect(gl, program, GL_ACTIVE_UNIFORMS, GL_ACTIVE_UNIFORM_MAX_LENGTH, gl.GetActiveUniform, "uniform", out, err))
    return false;
  std::sort(out->begin(), out->end(), [](const ProgramVar &a, const ProgramVar &b) { return a.name < b.name; });
  return true;
}

// tiershade gl: GL type names and sizes (see gl_types.h).
#include "gl/type_names.h"

namespace {
struct TypeInfo {
  GLenum type;
  const char *name;
  int components;
  bool is_float, is_sampler;
};
const TypeInfo kTypes[] = {
    {GL_FLOAT, "float", 1, true, false},          {GL_FLOAT_VEC2, "vec2", 2, true, false},
    {GL_FLOAT_VEC3, "vec3", 3, true, false},      {GL_FLOAT_VEC4, "vec4", 4, true, false},
    {GL_FLOAT_MAT2, "mat2", 4, true, false},      {GL_FLOAT_MAT3, "mat3", 9, true, false},
    {GL_FLOAT_MAT4, "mat4", 16, true, false},     {GL_INT, "int", 1, false, false},
    {GL_INT_VEC2, "ivec2", 2, false, false},      {GL_INT_VEC3, "ivec3", 3, false, false},
    {GL_INT_VEC4, "ivec4", 4, false, false},      {GL_BOOL, "bool", 1, false, false},
    {GL_BOOL_VEC2, "bvec2", 2, false, false},     {GL_BOOL_VEC3, "bvec3", 3, false, false},
    {GL_BOOL_VEC4, "bvec4", 4, false, false},     {GL_SAMPLER_2D, "sampler2D", 1, false, true},
    {GL_SAMPLER_3D, "sampler3D", 1, false, true}, {GL_SAMPLER_CUBE, "samplerCube", 1, false, true},
};
const TypeInfo *find(GLenum t) {
  for (const auto &i : kTypes)
    if (i.type == t) return &i;
  return nullptr;
}
}  // namespace

const char *gl_type_glsl_name(GLenum type) {
  const TypeInfo *i = find(type);
  return i ? i->name : "";
}
int gl_type_components(GLenum type) {
  const TypeInfo *i = find(type);
  return i ? i->components : 0;
}
bool gl_type_is_sampler(GLenum type) {
  const TypeInfo *i = find(type);
  return i && i->is_sampler;
}
bool gl_type_is_float(GLenum type) {
  const TypeInfo *i = find(type);
  return i && i->is_float;
}

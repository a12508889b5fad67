// tiershade gl: names and sizes of the GL types that glGetActiveUniform/Attrib report,
// as GLSL spells them (bundle manifests and draw dumps).
#pragma once
#include <string>

#include "gl/fns.h"

const char *gl_type_glsl_name(GLenum type);  // "vec4", "mat4", "sampler2D", ... or "" if unknown
int gl_type_components(GLenum type);  // floats/ints per element (mat4: 16); 0 if unknown
bool gl_type_is_sampler(GLenum type);
bool gl_type_is_float(GLenum type);  // float, vecN, matN (else int/bool/sampler)

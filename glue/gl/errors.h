// tiershade gl: the checks a GL step ends with (glGetError, framebuffer completeness, shader and
// program info logs), each failure naming what was being done.
#pragma once
#include <string>

#include "gl/fns.h"

// "0x506": a GL enum in a message, as the GL headers spell it.
std::string gl_hex(unsigned v);
// true when glGetError reports nothing; else false and *err = "GL error 0x... <doing>".
bool gl_no_error(const GlFns &g, const std::string &doing, std::string *err);
// true when the bound GL_FRAMEBUFFER is complete; else false and
// *err = "<what> incomplete (status 0x...)".
bool gl_framebuffer_complete(const GlFns &g, const std::string &what, std::string *err);
// The info log of a shader (GetShaderiv, GetShaderInfoLog) or of a program (GetProgramiv,
// GetProgramInfoLog: the same signatures).
std::string gl_info_log(const GlFns &g, GLuint object, bool program);

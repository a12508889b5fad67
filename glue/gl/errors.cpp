// tiershade gl: GL error, framebuffer and info-log checks (see errors.h).
#include "gl/errors.h"

#include <cstdio>

std::string gl_hex(unsigned v) {
  char b[16];
  snprintf(b, sizeof b, "0x%x", v);
  return b;
}

bool gl_no_error(const GlFns &g, const std::string &doing, std::string *err) {
  const GLenum e = g.GetError();
  if (e == GL_NO_ERROR) return true;
  *err = "GL error " + gl_hex(e) + " " + doing;
  return false;
}

bool gl_framebuffer_complete(const GlFns &g, const std::string &what, std::string *err) {
  const GLenum status = g.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return true;
  *err = what + " incomplete (status " + gl_hex(status) + ")";
  return false;
}

std::string gl_info_log(const GlFns &g, GLuint object, bool program) {
  const PFNGLGETSHADERIVPROC get_iv = program ? g.GetProgramiv : g.GetShaderiv;
  const PFNGLGETSHADERINFOLOGPROC get_log = program ? g.GetProgramInfoLog : g.GetShaderInfoLog;
  GLint len = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &len);
  std::string log(len > 0 ? len : 1, '\0');
  get_log(object, static_cast<GLsizei>(log.size()), nullptr, &log[0]);
  return log.c_str();
}

// tiershade gl: libOSMesa, loaded at run time (dlopen) the first time an OSMesa context is
// asked for, instead of linked: linking it maps and relocates Mesa and LLVM at process start
// (about 52 MiB resident before main), which the EGL backend, the C fallback and every command
// without GL would pay for nothing. The EGL driver brings its own copy when EGL is used.
#pragma once
#include <GL/osmesa.h>

#include <string>

struct OsmesaApi {
  OSMesaContext (*CreateContextAttribs)(const int *attribList, OSMesaContext sharelist);
  void (*DestroyContext)(OSMesaContext ctx);
  GLboolean (*MakeCurrent)(OSMesaContext ctx, void *buffer, GLenum type, GLsizei width, GLsizei height);
  OSMESAproc (*GetProcAddress)(const char *funcName);
};

// The library's entry points (loaded once, thread-safe, never unloaded), or nullptr with *err
// naming the library and dlopen's reason.
const OsmesaApi *osmesa_api(std::string *err);

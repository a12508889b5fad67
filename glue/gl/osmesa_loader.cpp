// tiershade gl: libOSMesa loaded at run time (glue/gl/osmesa_loader.h).
#include "gl/osmesa_loader.h"

#include <dlfcn.h>

#include <mutex>

namespace {

OsmesaApi g_api;
std::string g_err;
std::once_flag g_once;

template <typename F>
bool sym(void *lib, const char *name, F *out) {
  *out = reinterpret_cast<F>(dlsym(lib, name));
  if (!*out) g_err = std::string("libOSMesa has no ") + name;
  return *out != nullptr;
}

void load() {
  // RTLD_LOCAL: OSMesa's gl* symbols stay out of the global namespace (every GL call goes
  // through OSMesaGetProcAddress; glue/gl/fns.h).
  void *lib = nullptr;
  std::string why;
  for (const char *name : {"libOSMesa.so.8", "libOSMesa.so"}) {
    lib = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (lib) break;
    const char *e = dlerror();
    why += std::string(why.empty() ? "" : "; ") + (e ? e : name);
  }
  if (!lib) {
    g_err = "cannot load libOSMesa (the osmesa backend; `make deps` installs libosmesa6): " + why;
    return;
  }
  OsmesaApi a;
  if (!sym(lib, "OSMesaCreateContextAttribs", &a.CreateContextAttribs) ||
      !sym(lib, "OSMesaDestroyContext", &a.DestroyContext) || !sym(lib, "OSMesaMakeCurrent", &a.MakeCurrent) ||
      !sym(lib, "OSMesaGetProcAddress", &a.GetProcAddress))
    return;
  g_api = a;
}

}  // namespace

const OsmesaApi *osmesa_api(std::string *err) {
  std::call_once(g_once, load);
  if (!g_api.GetProcAddress) {
    if (err) *err = g_err;
    return nullptr;
  }
  return &g_api;
}

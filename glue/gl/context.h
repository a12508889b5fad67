// tiershade gl: headless GL contexts on Mesa's CPU rasterizer (llvmpipe).
// Two first-class backends: OSMesa (desktop GL 3.3 core) and EGL surfaceless
// (EGL_PLATFORM_SURFACELESS_MESA) with GLES 2.0, GLES 3.0 or desktop GL 3.3.
// OSMesa was removed from Mesa in 25.1, so EGL must stay first-class.
#pragma once
#include <memory>
#include <string>
#include <vector>
#include "gl/fns.h"

enum class Backend { OSMesa, EGL, CPU };
enum class Api { GL33, GLES2, GLES3 };

const char *backend_name(Backend b);
const char *api_name(Api a);
bool parse_backend(const std::string &s, Backend *out);
bool parse_api(const std::string &s, Api *out);

// The backend/API pairs that tiershade supports (OSMesa only does desktop GL).
struct BackendApi {
  Backend backend;
  Api api;
};
std::vector<BackendApi> all_gl_configs();
bool config_supported(Backend b, Api a, std::string *why);

class GlContext {
 public:
  virtual ~GlContext() = default;
  static std::unique_ptr<GlContext> create(Backend b, Api a, std::string *err);
  virtual bool make_current() = 0;
  const GlFns &gl() const { return gl_; }
  Backend backend() const { return backend_; }
  Api api() const { return api_; }
  std::string renderer() const;  // GL_RENDERER + GL_VERSION

 protected:
  GlFns gl_;
  Backend backend_ = Backend::OSMesa;
  Api api_ = Api::GL33;
  bool load(void *(*getproc)(const char *), std::string *err);
};

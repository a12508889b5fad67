// tiershade gl: OSMesa and EGL-surfaceless context creation and the per-backend
// GL entry-point table (facts: ../shared/docs/platform_notes.md sections 2 and 3).
#include "gl/context.h"
#include "gl/osmesa_loader.h"
#include "base/enum_names.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

static const EnumName<Backend> kBackendNames[] = {
    {Backend::OSMesa, "osmesa"}, {Backend::EGL, "egl"}, {Backend::CPU, "cpu"}};
static const EnumName<Api> kApiNames[] = {{Api::GL33, "gl33"}, {Api::GLES2, "gles2"}, {Api::GLES3, "gles3"}};

const char *backend_name(Backend b) { return enum_name(kBackendNames, b); }
const char *api_name(Api a) { return enum_name(kApiNames, a); }
bool parse_backend(const std::string &s, Backend *out) { return enum_parse(kBackendNames, s, out); }
bool parse_api(const std::string &s, Api *out) { return enum_parse(kApiNames, s, out); }
std::vector<BackendApi> all_gl_configs() {
  return {
      {Backend::OSMesa, Api::GL33}, {Backend::EGL, Api::GLES2}, {Backend::EGL, Api::GLES3}, {Backend::EGL, Api::GL33}};
}
bool config_supported(Backend b, Api a, std::string *why) {
  if (b == Backend::OSMesa && a != Api::GL33) {
    if (why) *why = std::string("the osmesa backend offers desktop GL only (--api gl33), not ") + api_name(a);
    return false;
  }
  return true;
}

std::string GlContext::renderer() const {
  const char *r = reinterpret_cast<const char *>(gl_.GetString(GL_RENDERER));
  const char *v = reinterpret_cast<const char *>(gl_.GetString(GL_VERSION));
  return std::string(r ? r : "?") + " / " + (v ? v : "?");
}

bool GlContext::load(void *(*getproc)(const char *), std::string *err) {
  std::string missing;
#define TS_GL_LOAD(name, type)                            \
  gl_.name = reinterpret_cast<type>(getproc("gl" #name)); \
  if (!gl_.name) missing += " gl" #name;
  TS_GL_FUNCTIONS(TS_GL_LOAD)
#undef TS_GL_LOAD
  if (!missing.empty()) {
    *err = "GL entry points missing:" + missing;
    return false;
  }
  if (!gl_.GetString(GL_VERSION)) {
    *err = "the context answers no GL_VERSION (is libGL linked before libOSMesa?)";
    return false;
  }
  return true;
}

namespace {

void *osmesa_getproc(const char *name) {
  const OsmesaApi *os = osmesa_api(nullptr);
  return os ? reinterpret_cast<void *>(os->GetProcAddress(name)) : nullptr;
}
void *egl_getproc(const char *name) { return reinterpret_cast<void *>(eglGetProcAddress(name)); }

class OSMesaContextImpl : public GlContext {
 public:
  ~OSMesaContextImpl() override {
    if (ctx_) os_->DestroyContext(ctx_);
  }
  bool init(std::string *err) {
    backend_ = Backend::OSMesa;
    api_ = Api::GL33;
    os_ = osmesa_api(err);
    if (!os_) return false;
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    ctx_ = os_->CreateContextAttribs(attribs, nullptr);
    if (!ctx_) {
      *err = "OSMesaCreateContextAttribs failed (GL 3.3 core)";
      return false;
    }
    if (!make_current()) {
      *err = "OSMesaMakeCurrent failed";
      return false;
    }
    return load(osmesa_getproc, err);
  }
  bool make_current() override {
    // Rendering goes to FBOs; the window buffer is a 1x1 placeholder.
    return os_->MakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, 1, 1) == GL_TRUE;
  }

 private:
  const OsmesaApi *os_ = nullptr;
  OSMesaContext ctx_ = nullptr;
  unsigned char buffer_[4] = {0, 0, 0, 0};
};

class EglContextImpl : public GlContext {
 public:
  ~EglContextImpl() override {
    if (dpy_ != EGL_NO_DISPLAY) {
      eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (ctx_ != EGL_NO_CONTEXT) eglDestroyContext(dpy_, ctx_);
      eglTerminate(dpy_);
    }
  }
  bool init(Api api, std::string *err) {
    backend_ = Backend::EGL;
    api_ = api;
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) {
      *err = "eglGetPlatformDisplayEXT is not available";
      return false;
    }
    dpy_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy_ == EGL_NO_DISPLAY || !eglInitialize(dpy_, &major, &minor)) {
      dpy_ = EGL_NO_DISPLAY;
      *err = "EGL surfaceless display could not be initialised";
      return false;
    }
    const bool desktop = api == Api::GL33;
    const EGLint renderable = desktop ? EGL_OPENGL_BIT : api == Api::GLES3 ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_ES2_BIT;
    const EGLint cfg_attribs[] = {EGL_SURFACE_TYPE,
                                  EGL_PBUFFER_BIT,
                                  EGL_RENDERABLE_TYPE,
                                  renderable,
                                  EGL_RED_SIZE,
                                  8,
                                  EGL_GREEN_SIZE,
                                  8,
                                  EGL_BLUE_SIZE,
                                  8,
                                  EGL_NONE};
    EGLConfig cfg;
    EGLint n = 0;
    if (!eglChooseConfig(dpy_, cfg_attribs, &cfg, 1, &n) || n < 1) {
      *err = std::string("no EGL config for ") + api_name(api);
      return false;
    }
    if (!eglBindAPI(desktop ? EGL_OPENGL_API : EGL_OPENGL_ES_API)) {
      *err = "eglBindAPI failed";
      return false;
    }
    std::vector<EGLint> ctx_attribs;
    if (desktop) {
      ctx_attribs = {
          EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
          EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    } else {
      ctx_attribs = {EGL_CONTEXT_MAJOR_VERSION, api == Api::GLES3 ? 3 : 2, EGL_NONE};
    }
    ctx_ = eglCreateContext(dpy_, cfg, EGL_NO_CONTEXT, ctx_attribs.data());
    if (ctx_ == EGL_NO_CONTEXT) {
      *err = std::string("eglCreateContext failed for ") + api_name(api);
      return false;
    }
    if (!make_current()) {
      *err = "eglMakeCurrent (surfaceless) failed";
      return false;
    }
    return load(egl_getproc, err);
  }
  bool make_current() override { return eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_) == EGL_TRUE; }

 private:
  EGLDisplay dpy_ = EGL_NO_DISPLAY;
  EGLContext ctx_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> GlContext::create(Backend b, Api a, std::string *err) {
  std::string why;
  if (b == Backend::CPU) {
    *err = "the cpu backend has no GL context";
    return nullptr;
  }
  if (!config_supported(b, a, &why)) {
    *err = why;
    return nullptr;
  }
  if (b == Backend::OSMesa) {
    auto c = std::make_unique<OSMesaContextImpl>();
    if (!c->init(err)) return nullptr;
    return c;
  }
  auto c = std::make_unique<EglContextImpl>();
  if (!c->init(a, err)) return nullptr;
  return c;
}

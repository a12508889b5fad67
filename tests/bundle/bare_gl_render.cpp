// tiershade tests: a bare GL "engine" that knows nothing of tiershade. It loads
// a shader bundle (manifest.json + .vert/.frag, docs/bundles.md) and a draw dump (draws.json +
// binary arrays), replays the draws on an EGL surfaceless context of its own, and compares its
// RGBA32F frame with the dump's frame.f32 bit for bit.
//   usage: bare_gl_render --bundle DIR --dump DIR --api gles2|gles3|gl33
// Prints "bare_gl_render: W x H, N draws, M channels differ"; exit 0 if M == 0, 1 on a
// mismatch, 2 on an error (a message naming the file and the place). Uses only EGL, GL headers,
// the C/C++ standard libraries and nlohmann json; every GL function comes from eglGetProcAddress.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using json = nlohmann::json;

namespace {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

#define BARE_GL(X)                                                                                                     \
  X(PFNGLGETSTRINGPROC, GetString)                                                                                     \
  X(PFNGLGETERRORPROC, GetError) X(PFNGLCREATESHADERPROC, CreateShader) X(PFNGLSHADERSOURCEPROC, ShaderSource) X(      \
      PFNGLCOMPILESHADERPROC,                                                                                          \
      CompileShader) X(PFNGLGETSHADERIVPROC, GetShaderiv) X(PFNGLGETSHADERINFOLOGPROC,                                 \
                                                            GetShaderInfoLog) X(PFNGLCREATEPROGRAMPROC, CreateProgram) \
      X(PFNGLATTACHSHADERPROC, AttachShader) X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation) X(                     \
          PFNGLLINKPROGRAMPROC, LinkProgram) X(PFNGLGETPROGRAMIVPROC,                                                  \
                                               GetProgramiv) X(PFNGLGETPROGRAMINFOLOGPROC,                             \
                                                               GetProgramInfoLog) X(PFNGLUSEPROGRAMPROC, UseProgram)   \
          X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation) X(PFNGLUNIFORM1FVPROC, Uniform1fv) X(                     \
              PFNGLUNIFORM2FVPROC, Uniform2fv) X(PFNGLUNIFORM3FVPROC, Uniform3fv) X(PFNGLUNIFORM4FVPROC, Uniform4fv)   \
              X(PFNGLUNIFORM1IVPROC, Uniform1iv) X(PFNGLUNIFORM2IVPROC, Uniform2iv) X(                                 \
                  PFNGLUNIFORM3IVPROC, Uniform3iv) X(PFNGLUNIFORM4IVPROC, Uniform4iv) X(PFNGLUNIFORM1IPROC, Uniform1i) \
                  X(PFNGLUNIFORMMATRIX2FVPROC, UniformMatrix2fv) X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv) X(     \
                      PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv) X(PFNGLGENTEXTURESPROC, GenTextures)                \
                      X(PFNGLBINDTEXTUREPROC, BindTexture) X(PFNGLACTIVETEXTUREPROC, ActiveTexture) X(                 \
                          PFNGLTEXIMAGE2DPROC, TexImage2D) X(PFNGLTEXIMAGE3DPROC, TexImage3D)                          \
                          X(PFNGLTEXPARAMETERIPROC, TexParameteri) X(PFNGLPIXELSTOREIPROC, PixelStorei) X(             \
                              PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers) X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)  \
                              X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D) X(                                \
                                  PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                             \
                                  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers) X(                                    \
                                      PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer) X(PFNGLRENDERBUFFERSTORAGEPROC,     \
                                                                                     RenderbufferStorage)              \
                                      X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) X(                  \
                                          PFNGLGENBUFFERSPROC, GenBuffers) X(PFNGLBINDBUFFERPROC, BindBuffer)          \
                                          X(PFNGLBUFFERDATAPROC, BufferData) X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)  \
                                              X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                     \
                                                  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) X(      \
                                                      PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray)     \
                                                      X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                     \
                                                          X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray) X(              \
                                                              PFNGLVIEWPORTPROC, Viewport) X(PFNGLENABLEPROC, Enable)  \
                                                              X(PFNGLDISABLEPROC, Disable)                             \
                                                                  X(PFNGLDEPTHFUNCPROC, DepthFunc)                     \
                                                                      X(PFNGLCLEARCOLORPROC, ClearColor)               \
                                                                          X(PFNGLCLEARPROC, Clear)                     \
                                                                              X(PFNGLDRAWELEMENTSPROC, DrawElements)   \
                                                                                  X(PFNGLREADPIXELSPROC, ReadPixels)   \
                                                                                      X(PFNGLFINISHPROC, Finish)

struct Gl {
#define BARE_DECL(type, name) type name = nullptr;
  BARE_GL(BARE_DECL)
#undef BARE_DECL
};

enum class Api { GLES2, GLES3, GL33 };

std::string read_file(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw Error(path + ": cannot open");
  std::ostringstream s;
  s << f.rdbuf();
  if (f.bad()) throw Error(path + ": read error");
  return s.str();
}

json read_json(const std::string &path) {
  try {
    return json::parse(read_file(path));
  } catch (const json::exception &e) {
    throw Error(path + ": not valid JSON: " + e.what());
  }
}

// A binary array of `count` 4-byte elements.
template <class T>
std::vector<T> read_array(const std::string &path, size_t count) {
  const std::string s = read_file(path);
  if (s.size() != count * sizeof(T))
    throw Error(path + ": " + std::to_string(s.size()) + " bytes, expected " + std::to_string(count * sizeof(T)));
  std::vector<T> v(count);
  if (count) memcpy(v.data(), s.data(), s.size());
  return v;
}

// json field access with errors that name the file and the place.
const json &field(const json &j, const char *key, const std::string &where) {
  if (!j.is_object() || !j.contains(key)) throw Error(where + ": missing \"" + key + "\"");
  return j.at(key);
}
std::string str(const json &j, const char *key, const std::string &where) {
  const json &v = field(j, key, where);
  if (!v.is_string()) throw Error(where + "." + key + ": not a string");
  return v.get<std::string>();
}
long num(const json &j, const char *key, const std::string &where, long lo, long hi) {
  const json &v = field(j, key, where);
  if (!v.is_number_integer() || v.get<long>() < lo || v.get<long>() > hi)
    throw Error(where + "." + key + ": not an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v.get<long>();
}
const json &arr(const json &j, const char *key, const std::string &where) {
  const json &v = field(j, key, where);
  if (!v.is_array()) throw Error(where + "." + key + ": not an array");
  return v;
}
bool boolean(const json &j, const char *key, const std::string &where) {
  const json &v = field(j, key, where);
  if (!v.is_boolean()) throw Error(where + "." + key + ": not true/false");
  return v.get<bool>();
}
// A file name inside a directory: no path separators, no "..".
std::string file_in(const std::string &dir, const std::string &rel, const std::string &where, bool allow_subdir) {
  if (rel.empty() || rel[0] == '/' || rel.find("..") != std::string::npos ||
      (!allow_subdir && rel.find('/') != std::string::npos))
    throw Error(where + ": bad file name \"" + rel + "\"");
  return dir + "/" + rel;
}

class EglContext {
 public:
  EglContext(Api api, Gl *gl) {
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) throw Error("EGL: eglGetPlatformDisplayEXT is not available");
    dpy_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy_ == EGL_NO_DISPLAY || !eglInitialize(dpy_, &major, &minor)) {
      dpy_ = EGL_NO_DISPLAY;
      throw Error("EGL: the surfaceless display could not be initialised");
    }
    const EGLint bit = api == Api::GL33 ? EGL_OPENGL_BIT : api == Api::GLES3 ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_ES2_BIT;
    const EGLint cfg_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, bit, EGL_NONE};
    EGLConfig cfg;
    EGLint n = 0;
    if (!eglChooseConfig(dpy_, cfg_attribs, &cfg, 1, &n) || n < 1) throw Error("EGL: no config for the API");
    if (!eglBindAPI(api == Api::GL33 ? EGL_OPENGL_API : EGL_OPENGL_ES_API)) throw Error("EGL: eglBindAPI failed");
    std::vector<EGLint> a;
    if (api == Api::GL33)
      a = {EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
           EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    else
      a = {EGL_CONTEXT_MAJOR_VERSION, api == Api::GLES3 ? 3 : 2, EGL_NONE};
    ctx_ = eglCreateContext(dpy_, cfg, EGL_NO_CONTEXT, a.data());
    if (ctx_ == EGL_NO_CONTEXT) throw Error("EGL: eglCreateContext failed");
    if (!eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_)) throw Error("EGL: eglMakeCurrent failed");
    std::string missing;
#define BARE_LOAD(type, name)                                       \
  gl->name = reinterpret_cast<type>(eglGetProcAddress("gl" #name)); \
  if (!gl->name) missing += " gl" #name;
    BARE_GL(BARE_LOAD)
#undef BARE_LOAD
    if (!missing.empty()) throw Error("GL entry points missing:" + missing);
  }
  ~EglContext() {
    if (dpy_ == EGL_NO_DISPLAY) return;
    eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (ctx_ != EGL_NO_CONTEXT) eglDestroyContext(dpy_, ctx_);
    eglTerminate(dpy_);
  }

 private:
  EGLDisplay dpy_ = EGL_NO_DISPLAY;
  EGLContext ctx_ = EGL_NO_CONTEXT;
};

GLuint compile(const Gl &gl, GLenum type, const std::string &path) {
  const std::string src = read_file(path);
  const GLuint s = gl.CreateShader(type);
  const char *text = src.c_str();
  gl.ShaderSource(s, 1, &text, nullptr);
  gl.CompileShader(s);
  GLint ok = 0;
  gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {0};
    gl.GetShaderInfoLog(s, sizeof log - 1, nullptr, log);
    throw Error(path + ": does not compile: " + log);
  }
  return s;
}

// Whether the manifest entry says a driver may trim `name` from `kind` ("attributes" and
// "samplers": a list of names; "uniforms": objects whose array_size 0 means the whole uniform).
bool trimmed(const json &entry, const char *kind, const std::string &name, const std::string &where) {
  if (!entry.contains("may_trim")) return false;
  const json &t = entry["may_trim"];
  if (!t.is_object() || !t.contains(kind) || !t[kind].is_array()) throw Error(where + ": malformed may_trim." + kind);
  for (const auto &x : t[kind]) {
    if (x.is_string() && x == name) return true;
    if (x.is_object() && x.contains("name") && x["name"] == name && x.contains("array_size") && x["array_size"] == 0)
      return true;
  }
  return false;
}

// One bundle variant, linked with its attributes at locations 0..n-1 in manifest order.
struct Program {
  GLuint id = 0;
  json entry;  // the manifest's variant object
  std::vector<std::string> attributes;
};

Program link(const Gl &gl, const std::string &bundle, const json &entry, const std::string &where) {
  Program p;
  p.entry = entry;
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, file_in(bundle, str(entry, "vertex", where), where, true));
  const GLuint fs = compile(gl, GL_FRAGMENT_SHADER, file_in(bundle, str(entry, "fragment", where), where, true));
  p.id = gl.CreateProgram();
  gl.AttachShader(p.id, vs);
  gl.AttachShader(p.id, fs);
  const json &attrs = arr(entry, "attributes", where);
  for (size_t i = 0; i < attrs.size(); ++i) {
    p.attributes.push_back(str(attrs[i], "name", where + ".attributes[" + std::to_string(i) + "]"));
    gl.BindAttribLocation(p.id, static_cast<GLuint>(i), p.attributes.back().c_str());
  }
  gl.LinkProgram(p.id);
  GLint ok = 0;
  gl.GetProgramiv(p.id, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {0};
    gl.GetProgramInfoLog(p.id, sizeof log - 1, nullptr, log);
    throw Error(where + ": does not link: " + log);
  }
  return p;
}

void set_uniform(const Gl &gl, GLuint prog, const json &u, const std::string &where) {
  const std::string name = str(u, "name", where), type = str(u, "type", where);
  const long array_size = num(u, "array_size", where, 0, 1 << 20);
  const json &bits = arr(u, "bits", where);
  std::vector<float> f(bits.size());
  for (size_t i = 0; i < bits.size(); ++i) {
    if (!bits[i].is_number_unsigned()) throw Error(where + ".bits: not float32 bit patterns");
    const uint32_t b = bits[i].get<uint32_t>();
    memcpy(&f[i], &b, 4);
  }
  static const std::map<std::string, int> kComps = {
      {"float", 1}, {"vec2", 2},  {"vec3", 3},  {"vec4", 4}, {"mat2", 4},  {"mat3", 9},  {"mat4", 16}, {"int", 1},
      {"ivec2", 2}, {"ivec3", 3}, {"ivec4", 4}, {"bool", 1}, {"bvec2", 2}, {"bvec3", 3}, {"bvec4", 4}};
  auto it = kComps.find(type);
  if (it == kComps.end()) throw Error(where + ": unknown uniform type " + type);
  const GLsizei count = static_cast<GLsizei>(array_size > 0 ? array_size : 1);
  if (f.size() != static_cast<size_t>(count) * it->second) throw Error(where + ": wrong number of values");
  const GLint loc = gl.GetUniformLocation(prog, name.c_str());
  if (loc < 0) throw Error(where + ": the program has no uniform " + name);
  const float *v = f.data();
  if (type == "float")
    gl.Uniform1fv(loc, count, v);
  else if (type == "vec2")
    gl.Uniform2fv(loc, count, v);
  else if (type == "vec3")
    gl.Uniform3fv(loc, count, v);
  else if (type == "vec4")
    gl.Uniform4fv(loc, count, v);
  else if (type == "mat2")
    gl.UniformMatrix2fv(loc, count, GL_FALSE, v);
  else if (type == "mat3")
    gl.UniformMatrix3fv(loc, count, GL_FALSE, v);
  else if (type == "mat4")
    gl.UniformMatrix4fv(loc, count, GL_FALSE, v);
  else {
    std::vector<GLint> iv(f.size());
    for (size_t i = 0; i < f.size(); ++i) iv[i] = static_cast<GLint>(f[i]);
    const int c = it->second;
    if (c == 1)
      gl.Uniform1iv(loc, count, iv.data());
    else if (c == 2)
      gl.Uniform2iv(loc, count, iv.data());
    else if (c == 3)
      gl.Uniform3iv(loc, count, iv.data());
    else
      gl.Uniform4iv(loc, count, iv.data());
  }
}

GLuint upload_texture(const Gl &gl, Api api, const std::string &dump, const json &t, const std::string &where) {
  const std::string kind = str(t, "kind", where);
  const long w = num(t, "w", where, 1, 16384), h = num(t, "h", where, 1, 16384), d = num(t, "d", where, 1, 4096);
  const GLenum target = kind == "cube" ? GL_TEXTURE_CUBE_MAP : kind == "3d" ? GL_TEXTURE_3D : GL_TEXTURE_2D;
  if (kind != "cube" && kind != "3d" && kind != "2d") throw Error(where + ".kind: unknown \"" + kind + "\"");
  if (kind == "cube" && w != h) throw Error(where + ": cube faces are not square");
  const size_t texels = kind == "cube" ? static_cast<size_t>(w) * w * 6
      : kind == "3d"                   ? static_cast<size_t>(w) * h * d
                                       : static_cast<size_t>(w) * h;
  const auto rgba = read_array<float>(file_in(dump, str(t, "file", where), where, false), texels * 4);
  GLuint id = 0;
  gl.GenTextures(1, &id);
  gl.BindTexture(target, id);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // The mip chain (levels 1..n, each max(1, size >> k) a side) and its filter, when the dump has one.
  const std::string mip = t.contains("mip_filter") ? str(t, "mip_filter", where) : "none";
  if (mip != "none" && mip != "nearest" && mip != "linear")
    throw Error(where + ".mip_filter: unknown \"" + mip + "\"");
  size_t nlevels = 0;
  if (t.contains("levels")) {
    if (!t.at("levels").is_array()) throw Error(where + ".levels: expected an array of file names");
    nlevels = t.at("levels").size();
  }
  if ((mip == "none") != (nlevels == 0) || (nlevels > 0 && kind != "2d"))
    throw Error(where + ": mip_filter \"" + mip + "\" with " + std::to_string(nlevels) + " levels");
  if (kind == "2d") {
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, rgba.data());
    for (size_t k = 0; k < nlevels; ++k) {
      const int l = static_cast<int>(k) + 1;
      const long lw = std::max(1L, w >> l), lh = std::max(1L, h >> l);
      if (l > 30 || (lw == 1 && lh == 1 && k + 1 < nlevels)) throw Error(where + ".levels: more levels than the size has");
      const std::string lwhere = where + ".levels[" + std::to_string(k) + "]";
      if (!t.at("levels")[k].is_string()) throw Error(lwhere + ": expected a file name");
      const auto lv = read_array<float>(file_in(dump, t.at("levels")[k].get<std::string>(), lwhere, false),
                                        static_cast<size_t>(lw) * lh * 4);
      gl.TexImage2D(GL_TEXTURE_2D, l, GL_RGBA32F, lw, lh, 0, GL_RGBA, GL_FLOAT, lv.data());
    }
  } else if (kind == "3d") {
    gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, w, h, d, 0, GL_RGBA, GL_FLOAT, rgba.data());
  } else {
    for (int f = 0; f < 6; ++f)
      gl.TexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA32F, w, w, 0, GL_RGBA, GL_FLOAT,
                    rgba.data() + static_cast<size_t>(f) * w * w * 4);
  }
  const GLint filter = boolean(t, "linear", where) ? GL_LINEAR : GL_NEAREST;
  const GLint wrap = boolean(t, "repeat", where) && kind != "cube" ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  GLint min_filter = filter;
  if (mip == "nearest") min_filter = filter == GL_LINEAR ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
  if (mip == "linear") min_filter = filter == GL_LINEAR ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
  gl.TexParameteri(target, GL_TEXTURE_MIN_FILTER, min_filter);
  gl.TexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
  if (kind != "2d") gl.TexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
  if (kind == "cube" && api == Api::GL33) gl.Disable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // GLES has no switch
  return id;
}

struct Options {
  std::string bundle, dump;
  Api api = Api::GLES3;
};

// Replays the dump; returns the number of differing channels.
long run(const Options &o, int *w_out, int *h_out, size_t *draws_out) {
  const std::string mpath = o.bundle + "/manifest.json", dpath = o.dump + "/draws.json";
  const json manifest = read_json(mpath), dump = read_json(dpath);
  if (num(manifest, "tiershade_bundle", mpath, 1, 1) != 1) throw Error(mpath + ": unknown bundle version");
  const std::string want_api = o.api == Api::GLES2 ? "gles2" : o.api == Api::GLES3 ? "gles3" : "gl33";
  if (str(manifest, "api", mpath) != want_api)
    throw Error(mpath + ": the bundle is for " + str(manifest, "api", mpath) + ", not --api " + want_api);
  std::map<std::string, json> variants;  // "shader|name" -> entry
  const json &mv = arr(manifest, "variants", mpath);
  for (size_t i = 0; i < mv.size(); ++i) {
    const std::string where = mpath + ": variants[" + std::to_string(i) + "]";
    variants[str(mv[i], "shader", where) + "|" + str(mv[i], "name", where)] = mv[i];
  }
  const int w = static_cast<int>(num(dump, "width", dpath, 1, 16384));
  const int h = static_cast<int>(num(dump, "height", dpath, 1, 16384));
  const json &clear_bits = arr(dump, "clear_bits", dpath);
  if (clear_bits.size() != 4) throw Error(dpath + ".clear_bits: want 4 values");
  float clear[4];
  for (int i = 0; i < 4; ++i) {
    const uint32_t b = clear_bits[i].get<uint32_t>();
    memcpy(&clear[i], &b, 4);
  }
  const std::string depth = str(dump, "depth_format", dpath);
  if (depth != "DEPTH_COMPONENT24" && depth != "DEPTH_COMPONENT32F")
    throw Error(dpath + ": unknown depth_format " + depth);
  const auto expected =
      read_array<float>(file_in(o.dump, str(dump, "frame_file", dpath), dpath, false), static_cast<size_t>(w) * h * 4);
  const json &draws = arr(dump, "draws", dpath);

  Gl gl;
  EglContext ctx(o.api, &gl);
  if (o.api == Api::GLES2) {
    const char *ext = reinterpret_cast<const char *>(gl.GetString(GL_EXTENSIONS));
    if (!ext || !strstr(ext, "GL_OES_element_index_uint")) throw Error("GLES2: no GL_OES_element_index_uint");
  }
  // The render state the shaders expect (docs/bundles.md): RGBA32F colour, depth LESS, no blending.
  GLuint color = 0, depth_rb = 0, fbo = 0;
  gl.GenTextures(1, &color);
  gl.BindTexture(GL_TEXTURE_2D, color);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.GenRenderbuffers(1, &depth_rb);
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth_rb);
  gl.RenderbufferStorage(GL_RENDERBUFFER, depth == "DEPTH_COMPONENT24" ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT32F,
                         w, h);
  gl.GenFramebuffers(1, &fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw Error("the RGBA32F + " + depth + " framebuffer is incomplete");
  if (o.api != Api::GLES2) {  // core GL needs a vertex array object; a GLES2 engine has none
    GLuint vao = 0;
    gl.GenVertexArrays(1, &vao);
    gl.BindVertexArray(vao);
  }
  gl.Viewport(0, 0, w, h);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.ClearColor(clear[0], clear[1], clear[2], clear[3]);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  std::map<std::string, Program> programs;
  for (size_t i = 0; i < draws.size(); ++i) {
    const json &d = draws[i];
    const std::string where = dpath + ": draws[" + std::to_string(i) + "]";
    const std::string key = str(d, "shader", where) + "|" + str(d, "variant", where);
    auto vit = variants.find(key);
    if (vit == variants.end()) throw Error(where + ": variant " + str(d, "variant", where) + " is not in " + mpath);
    auto pit = programs.find(key);
    if (pit == programs.end()) pit = programs.emplace(key, link(gl, o.bundle, vit->second, mpath + ": " + key)).first;
    const Program &p = pit->second;
    gl.UseProgram(p.id);
    // Uniforms: the dump sets the manifest's declared uniforms, except those the manifest says a
    // driver may trim (docs/bundles.md, "may_trim"), and nothing else.
    const json &mu = arr(p.entry, "uniforms", mpath);
    const json &du = arr(d, "uniforms", where);
    std::map<std::string, const json *> given;
    for (size_t k = 0; k < du.size(); ++k) given[str(du[k], "name", where)] = &du[k];
    std::map<std::string, bool> declared;
    for (size_t k = 0; k < mu.size(); ++k) declared[str(mu[k], "name", mpath)] = true;
    for (const auto &g : given)
      if (!declared.count(g.first)) throw Error(where + ": sets " + g.first + ", which the manifest does not list");
    for (size_t k = 0; k < mu.size(); ++k) {
      const std::string name = str(mu[k], "name", mpath);
      auto g = given.find(name);
      if (g == given.end()) {
        if (trimmed(p.entry, "uniforms", name, mpath)) continue;
        throw Error(where + ": no value for the manifest's uniform " + name);
      }
      set_uniform(gl, p.id, *g->second, where + ".uniforms." + name);
    }
    // Samplers: each at the manifest's unit, with the dump's texture of that name.
    std::vector<GLuint> textures;
    const json &ms = arr(p.entry, "samplers", mpath);
    const json &dt = arr(d, "textures", where);
    for (size_t k = 0; k < ms.size(); ++k) {
      const std::string name = str(ms[k], "name", mpath);
      const long unit = num(ms[k], "unit", mpath, 0, 31);
      const json *tex = nullptr;
      for (const auto &t : dt)
        if (t.is_object() && t.contains("sampler") && t["sampler"] == name) tex = &t;
      if (!tex && trimmed(p.entry, "samplers", name, mpath)) continue;
      if (!tex) throw Error(where + ": no texture for the sampler " + name);
      gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
      textures.push_back(upload_texture(gl, o.api, o.dump, *tex, where + ".textures." + name));
      const GLint loc = gl.GetUniformLocation(p.id, name.c_str());
      if (loc < 0 && trimmed(p.entry, "samplers", name, mpath)) continue;
      if (loc < 0) throw Error(mpath + ": " + key + ": no sampler " + name);
      gl.Uniform1i(loc, static_cast<GLint>(unit));
    }
    gl.ActiveTexture(GL_TEXTURE0);
    // Attributes from separate tightly packed float arrays.
    const size_t nv = static_cast<size_t>(num(d, "vertices", where, 0, 1L << 28));
    const size_t ni = static_cast<size_t>(num(d, "indices", where, 0, 1L << 30));
    std::vector<GLuint> buffers;
    for (size_t k = 0; k < p.attributes.size(); ++k) {
      const std::string &a = p.attributes[k];
      const char *key_file = a == "a_position" ? "position_file"
          : a == "a_normal"                    ? "normal_file"
          : a == "a_uv"                        ? "uv_file"
          : a == "a_tangent"                   ? "tangent_file"
          : a == "a_lightmap"                  ? "lightmap_file"
                                               : nullptr;
      const int comps = a == "a_uv" ? 2 : a == "a_tangent" || a == "a_lightmap" ? 4 : 3;
      const bool may_skip = trimmed(p.entry, "attributes", a, mpath);
      if (!key_file || !d.contains(key_file) || !d[key_file].is_string()) {
        if (may_skip) continue;  // the driver does not read it (the manifest's may_trim)
      }
      if (!key_file) throw Error(where + ": the dump has no data for attribute " + a);
      if (!field(d, key_file, where).is_string()) throw Error(where + ": no " + key_file + " for attribute " + a);
      const auto data = read_array<float>(file_in(o.dump, str(d, key_file, where), where, false), nv * comps);
      GLuint b = 0;
      gl.GenBuffers(1, &b);
      buffers.push_back(b);
      gl.BindBuffer(GL_ARRAY_BUFFER, b);
      gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * 4), data.data(), GL_STATIC_DRAW);
      gl.VertexAttribPointer(static_cast<GLuint>(k), comps, GL_FLOAT, GL_FALSE, 0, nullptr);
      gl.EnableVertexAttribArray(static_cast<GLuint>(k));
    }
    const auto idx = read_array<uint32_t>(file_in(o.dump, str(d, "index_file", where), where, false), ni);
    for (uint32_t k : idx)
      if (k >= nv) throw Error(where + ": index " + std::to_string(k) + " out of range");
    GLuint ib = 0;
    gl.GenBuffers(1, &ib);
    buffers.push_back(ib);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ib);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * 4), idx.data(), GL_STATIC_DRAW);
    gl.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(ni), GL_UNSIGNED_INT, nullptr);
    const GLenum e = gl.GetError();
    if (e != GL_NO_ERROR) throw Error(where + ": GL error " + std::to_string(e));
    for (size_t k = 0; k < p.attributes.size(); ++k) gl.DisableVertexAttribArray(static_cast<GLuint>(k));
    gl.DeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    (void)textures;  // kept until the context ends
  }
  std::vector<float> got(static_cast<size_t>(w) * h * 4);
  gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, got.data());
  gl.Finish();
  if (gl.GetError() != GL_NO_ERROR) throw Error("RGBA32F readback failed");
  long differ = 0;
  long first = -1;
  for (size_t i = 0; i < got.size(); ++i) {
    if (memcmp(&got[i], &expected[i], 4) != 0) {
      if (first < 0) first = static_cast<long>(i);
      ++differ;
    }
  }
  if (first >= 0) {
    const long px = first / 4;
    fprintf(stderr, "bare_gl_render: first difference at pixel (%ld, %ld) channel %ld: %.9g here, %.9g in the dump\n",
            px % w, px / w, first % 4, got[first], expected[first]);
  }
  *w_out = w;
  *h_out = h;
  *draws_out = draws.size();
  return differ;
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  std::string api;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--bundle" || a == "--dump" || a == "--api") && i + 1 < argc) {
      (a == "--bundle" ? o.bundle : a == "--dump" ? o.dump : api) = argv[++i];
    } else {
      fprintf(stderr,
              "bare_gl_render: unexpected argument '%s'\nusage: bare_gl_render --bundle DIR --dump DIR --api "
              "gles2|gles3|gl33\n",
              a.c_str());
      return 2;
    }
  }
  if (o.bundle.empty() || o.dump.empty() || api.empty()) {
    fprintf(stderr, "usage: bare_gl_render --bundle DIR --dump DIR --api gles2|gles3|gl33\n");
    return 2;
  }
  if (api == "gles2")
    o.api = Api::GLES2;
  else if (api == "gles3")
    o.api = Api::GLES3;
  else if (api == "gl33")
    o.api = Api::GL33;
  else {
    fprintf(stderr, "bare_gl_render: unknown --api '%s' (gles2, gles3, gl33)\n", api.c_str());
    return 2;
  }
  try {
    int w = 0, h = 0;
    size_t n = 0;
    const long differ = run(o, &w, &h, &n);
    printf("bare_gl_render: %d x %d, %zu draws, %ld channels differ\n", w, h, n, differ);
    return differ == 0 ? 0 : 1;
  } catch (const std::exception &e) {
    fprintf(stderr, "bare_gl_render: %s\n", e.what());
    return 2;
  }
}

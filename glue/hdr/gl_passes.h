// tiershade hdr: GL plumbing of the HDR passes: render targets (RGBA8, RGBA16F,
// RGBA32F) that later passes sample, full-screen passes drawn with a family's
// production program, readbacks, and the few GL 3.0 / GLES 3.0 entry points the
// histogram's pixel-pack-buffer route needs beyond GlFns (resolved here from the
// context's own loader, so that gl_fns.h stays as it is).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "exposure/auto_exposure.h"
#include "gl/float_target.h"
#include "shaderlib/variants.h"
#include "base/noncopyable.h"

enum class TargetFormat { RGBA8, RGBA16F, RGBA32F };
const char *target_format_name(TargetFormat f);
int target_bytes_per_pixel(TargetFormat f);

struct GlTarget {
  GLuint tex = 0, fbo = 0;
  int w = 0, h = 0;
  TargetFormat fmt = TargetFormat::RGBA8;
};

// A texture the size of the target, attached to its own framebuffer (CLAMP_TO_EDGE).
bool make_target(const GlFns &g, TargetFormat f, int w, int h, GlTarget *t, std::string *err);
void free_target(const GlFns &g, GlTarget *t);

// A texture a pass samples: uniform name, texture, and the filter to use for this pass.
struct PassTexture {
  std::string sampler;
  GLuint tex;
  bool linear;
};

// Full-screen passes: GlRenderer's full-screen triangle into GlTargets.
class PassRunner : NonCopyable {
 public:
  explicit PassRunner(GlRenderer &r);
  ~PassRunner();
  const GlFns &gl() const { return r_.gl(); }
  GlRenderer &renderer() { return r_; }
  // The production program of a family variant (vertex conform_fullscreen.vs for the
  // post-processing families), built once and kept.
  GLuint program(Api api, const std::string &shader, const std::string &variant, std::string *err);
  // Draws `program` into `t` (the whole target, or the scissor window when given).
  bool draw(GLuint program, const GlTarget &t, const std::vector<PassTexture> &textures, const ae_window *scissor,
            std::string *err);
  void set_vec4(GLuint program, const char *name, const float v[4]);

 private:
  GlRenderer &r_;
  std::vector<ShaderDecl> decls_;
  std::vector<std::pair<std::string, GLuint>> programs_;  // "shader|variant" -> program
};

// 2D textures (NEAREST, CLAMP_TO_EDGE) of HDR or display data: RGBA16F from half bits, RGBA8
// from codes; rows bottom-up. Delete them with glDeleteTextures.
GLuint upload_rgba16f(const GlFns &g, int w, int h, const std::vector<uint16_t> &halves);
GLuint upload_rgba8(const GlFns &g, int w, int h, const std::vector<uint8_t> &codes);

// Readbacks of a whole target (rows bottom-up): RGBA8 codes, or float values (RGBA16F and
// RGBA32F targets; half values convert to float exactly).
bool read_rgba8(const GlFns &g, const GlTarget &t, std::vector<uint8_t> *out, std::string *err);
bool read_float(const GlFns &g, const GlTarget &t, std::vector<float> *out, std::string *err);

// GL 3.0 / GLES 3.0 entry points not in GlFns (buffer mapping and fence syncs).
struct GlSyncFns {
  PFNGLMAPBUFFERRANGEPROC MapBufferRange = nullptr;
  PFNGLUNMAPBUFFERPROC UnmapBuffer = nullptr;
  PFNGLFENCESYNCPROC FenceSync = nullptr;
  PFNGLGETSYNCIVPROC GetSynciv = nullptr;
  PFNGLCLIENTWAITSYNCPROC ClientWaitSync = nullptr;
  PFNGLDELETESYNCPROC DeleteSync = nullptr;
};
bool load_sync_fns(Backend b, GlSyncFns *f, std::string *err);

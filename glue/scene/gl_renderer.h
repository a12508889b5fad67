// tiershade scene: a scene frame on GL, drawn as an engine draws it: each draw's production
// program (the family's vertex and fragment shaders, glue/conform/conform.h), its uniforms and
// textures, real geometry with a depth buffer, into an RGBA32F target. Also the G-buffer
// passes (shaders/scene_gbuffer.fs): the same vertex shader and depth, writing the records the
// production fragment shader received, so that the C twin can shade exactly what GL shaded.
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gl/float_target.h"
#include "base/image.h"
#include "scene/prepare.h"
#include "base/noncopyable.h"

class SceneGl : NonCopyable {
 public:
  SceneGl(GlRenderer &r, Api api);
  ~SceneGl();
  // Compiles the variants (one program per unique variant), uploads geometry and textures.
  // *compile_ms receives the time of compiling and linking the programs.
  // target_w/h > 0: a smaller colour/depth target than the frame's (shader warm-up contexts).
  bool init(const PreparedScene &p, std::string *err, double *compile_ms = nullptr, int target_w = 0, int target_h = 0);
  // Shader warm-up (another context on another thread, Mesa's shader cache on): draws the
  // draws from the last one down, each once into the small target, so that llvmpipe JIT-
  // compiles their shader variants and stores them in the cache; stops at the first draw the
  // main thread has already reached (*main_next: the index of the draw it is about to issue).
  void warm(const std::atomic<int> *main_next);
  // The main thread's progress, read by a warm-up thread (nullptr: none).
  void set_progress(std::atomic<int> *next) { progress_ = next; }
  // Draws the frame into the RGBA32F target (clear colour 0,0,0,0; depth 1) and reads it back.
  // before_draw (optional) is called after a draw's program, uniforms and textures are bound.
  bool frame(ImageF *out, std::string *err, double *draw_ms = nullptr,
             const std::function<void(int draw, GLuint program)> &before_draw = nullptr);
  // MSAA (the integer path; glue/scene/msaa.h), set before init: samples > 1 adds a
  // multisampled RGBA8 colour and depth renderbuffer pair that frame_msaa draws into and
  // resolves with glBlitFramebuffer into a one-sample RGBA8 texture, as an engine resolves.
  void set_msaa(int samples) { msaa_ = samples; }
  int msaa_samples() const { return msaa_got_; }  // the count GL allocated (GL_RENDERBUFFER_SAMPLES)
  // The production pass into the multisampled target (clear 0,0,0,0; depth 1), resolved and read
  // back as RGBA8 codes (rows bottom-up).
  bool frame_msaa(std::vector<uint8_t> *rgba8, std::string *err, double *draw_ms = nullptr,
                  const std::function<void(int draw, GLuint program)> &before_draw = nullptr);
  // Updates the shared slots (uniforms) of the draws from p (e.g. a new tone-map scale).
  void update(const PreparedScene &p) { p_ = &p; }
  // G-buffer: per pixel the draw index (-1 background) and the 6 pixel slots (24 floats); with
  // grads, also the uv's quad derivatives a mipmapped texture's level of detail comes from (4
  // floats a pixel: scene_shade_records' grads; shaders/scene_gbuffer.fs slot 6).
  bool gbuffer(std::vector<int> *draw, std::vector<float> *slots, std::string *err,
               std::vector<float> *grads = nullptr);
  // The same G-buffer drawn with the multisampled state (after set_msaa and init): an RGBA32F
  // target of the same sample count, only sample 0 written (glSampleCoverage 1/4 of 4), resolved
  // by glBlitFramebuffer ((v + 0 + 0 + 0) / 4, exact) and scaled back by 4: the records llvmpipe's
  // multisample shader variant interpolated at sample 0's pixels (for MSAA --check).
  bool gbuffer_msaa(std::vector<int> *draw, std::vector<float> *slots, std::string *err,
                    std::vector<float> *grads = nullptr);
  const GlFns &gl() const { return r_.gl(); }
  GLuint program_of(int draw) const { return programs_.at(prog_of_draw_.at(draw)); }
  // The host time of the last pass's per-draw set-up (program, uniforms, textures, attribute
  // bindings: bind_draw), summed over its draws (the large-scene bench's set-up share).
  double last_bind_ms() const { return bind_ms_; }

 private:
  void begin_pass();
  bool bind_draw(size_t i, GLuint program, bool production, std::string *err);
  bool draw_all(const std::vector<GLuint> &progs, bool production, int gb_slot, std::string *err,
                const std::function<void(int, GLuint)> &before_draw);
  bool read(std::vector<float> *rgba);
  bool init_msaa(std::string *err);
  bool gbuffer_passes(std::vector<int> *draw, std::vector<float> *slots, std::string *err,
                      const std::function<void()> &resolve, float scale, std::vector<float> *grads = nullptr);
  GlRenderer &r_;
  Api api_;
  const PreparedScene *p_ = nullptr;
  int tw_ = 0, th_ = 0;  // target size
  std::atomic<int> *progress_ = nullptr;
  double bind_ms_ = 0;
  std::vector<std::string> variant_names_;
  std::vector<GLuint> programs_;  // per unique variant
  std::vector<int> prog_of_draw_;
  std::vector<GLuint> textures_;  // per PreparedScene::textures entry
  struct Buffers {
    GLuint vbo[5] = {0, 0, 0, 0, 0};  // position, normal, uv, tangent, lightmap
    GLuint ibo = 0;
    GLsizei count = 0;
  };
  std::vector<Buffers> buffers_;  // per distinct DrawGeometry
  std::vector<int> buf_of_draw_;  // per draw: its index in buffers_
  GLuint vao_ = 0, fbo_ = 0, color_ = 0, depth_ = 0;
  int msaa_ = 0, msaa_got_ = 0;
  bool ms_pass_ = false;  // begin_pass binds the multisampled framebuffer
  bool gbm_pass_ = false;  // begin_pass binds the multisampled RGBA32F G-buffer framebuffer
  GLuint gbm_fbo_ = 0, gbm_color_ = 0, gbm_depth_ = 0;
  GLuint ms_fbo_ = 0, ms_color_ = 0, ms_depth_ = 0, rs_fbo_ = 0, rs_color_ = 0;
  std::vector<std::vector<GLuint>> gb_programs_;  // [slot + 1][unique variant]
  std::unique_ptr<SkyboxGl> sky_;  // the skybox pass of a scene with a sky (scene/skybox_pass.h)
};

// tiershade hdr: the two HDR paths of Source (talk: "Implemented Multiple HDR Paths";
// fact sheet section 7), on GL and as their exact C twins:
//   - integer: the lit shader ends with the tone-map scale and the sRGB output
//     (model_lighting OUTPUT_MODE 2) and writes an RGBA8 target;
//   - float: the lit shader writes linear HDR (tone-map scale 1) to an RGBA16F target;
//     bloom_downsample (4x4 box) -> bloom_blur X -> bloom_blur Y on quarter-size
//     RGBA16F targets, then hdr_tonemap (tone-map scale, bloom combine, sRGB) into RGBA8.
// The lit pass is a deferred frame of model_lighting (a G-buffer record + uniforms,
// glue/conform/family_frame.h). Every storage step is mirrored in C: fp16 targets round toward zero,
// RGBA8 targets round to nearest (c_ref/math/hdr_formats.h), so GL and C frames are equal
// code for code. A double-precision reference of the float path (no storage rounding)
// measures what each path loses (glue/bench/hdr.cpp).
#pragma once
#include <string>
#include <vector>

#include "families/family.h"
#include "conform/family_frame.h"
#include "hdr/gl_passes.h"
#include "base/noncopyable.h"

struct HdrSettings {
  float tone_map_scale = 1.f;
  float bloom_amount = 0.3f;  // floatcombine's bloom amount (mat_bloomscale smoothed)
  float bloom_exponent =
      2.2f;  // floatcombine's lum(bloom)^exp (the SDK's value is not in the fact sheet; 2.2 as r_bloomtintexponent)
};

// The model_lighting variant a path uses: sm3, albedo texture, half-Lambert, no Phong,
// and the given output encoding (0 linear for the float path, 2 exact sRGB for the integer path).
bool hdr_lit_variant(const std::vector<ShaderDecl> &decls, int output_mode, Variant *out, std::string *err);

// Quarter size of the bloom chain.
inline int hdr_bloom_size(int n) { return n / 4 > 0 ? n / 4 : 1; }

class HdrPipelineGl : NonCopyable {
 public:
  HdrPipelineGl(PassRunner &run, Api api);
  ~HdrPipelineGl();
  // Builds the programs and targets for w x h frames of `scene` (its G-buffer and textures are
  // uploaded once; the shared slots are bound per frame).
  bool init(const ShaderFamily &lit, const Variant &lit_linear, const Variant &lit_display, const FamilyInputs &scene,
            std::string *err);
  bool integer_frame(const std::vector<ts_vec4f> &shared, float tone_map_scale, std::string *err);
  // Post-processing only (scene frames, whose lit pass the caller draws): the float path's
  // targets and programs for w x h frames, then the chain from a linear frame whose values
  // are already fp16-representable (ts_quantize_half, as an RGBA16F render target stores them).
  // bloom false: a scene without bloom; the bloom programs are not built and post_* must be
  // called with bloom_amount 0 (the combine reads a black quarter-size bloom).
  bool init_post(int w, int h, std::string *err, bool bloom = true);
  bool post_float(const std::vector<float> &hdr_rgba, const HdrSettings &s, std::string *err);
  bool float_frame(const std::vector<ts_vec4f> &shared, const HdrSettings &s, std::string *err);
  const GlTarget &display() const { return display_; }  // RGBA8, the last frame of either path
  const GlTarget &hdr() const { return hdr_; }  // RGBA16F linear frame (float path)
  const GlTarget &bloom() const { return by_; }  // RGBA16F quarter-size blurred bloom

 private:
  bool post_chain(const HdrSettings &s, std::string *err);
  bool lit_pass(GLuint program, const std::vector<ts_vec4f> &shared, float scale, const GlTarget &t, std::string *err);
  PassRunner &run_;
  Api api_;
  const ShaderFamily *lit_ = nullptr;
  GlFrameProgram linear_, display_prog_;
  int w_ = 0, h_ = 0, rec_h_ = 0, rec_slots_ = 0;
  std::vector<bool> tex_linear_;  // per texture of the lit pass (record first)
  GlTarget display_, hdr_, ds_, bx_, by_;
  GLuint down_ = 0, blur_x_ = 0, blur_y_ = 0, tonemap_ = 0;
};

// The C twin of a frame of either path (float32, llvmpipe-exact), and the double reference.
struct HdrFrameC {
  int w = 0, h = 0, bw = 0, bh = 0;
  std::vector<uint8_t> display;  // RGBA8 codes, rows bottom-up
  std::vector<float> hdr;  // float path: the fp16 linear frame's values (rgba)
  std::vector<float> bloom;  // float path: the quarter-size blurred bloom (rgba)
  std::vector<float> bloom_down, bloom_x;  // float path: the downsampled and x-blurred bloom (scratch)
};
// `scene` holds the G-buffer and the shared slots; the tone-map scale is set by the functions.
void hdr_integer_frame_c(const ShaderFamily &lit, const Variant &v, const FamilyInputs &scene, float tone_map_scale,
                         HdrFrameC *out);
void hdr_float_frame_c(const ShaderFamily &lit, const Variant &v, const FamilyInputs &scene, const HdrSettings &s,
                       HdrFrameC *out);
// The float path's post chain (bloom, tone map, sRGB, RGBA8) from a linear frame already
// quantised to fp16 (rows bottom-up, rgba): the twin of HdrPipelineGl::post_float. keep_hdr
// false: out->hdr is left empty (a scene frame has the lit frame already: no copy of it).
void hdr_post_float_c(const std::vector<float> &hdr, int w, int h, const HdrSettings &s, HdrFrameC *out,
                      int threads = 1, bool keep_hdr = true);
// The float path in double with no storage rounding (intermediate images kept in float32):
// display values in [0, 1] (sRGB-encoded), 4 doubles per pixel.
void hdr_float_frame_reference(const ShaderFamily &lit, const Variant &v_linear, const FamilyInputs &scene,
                               const HdrSettings &s, std::vector<double> *display);

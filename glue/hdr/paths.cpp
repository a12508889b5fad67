// tiershade hdr: the integer and float HDR paths on GL (see hdr_pipeline.h).
#include "hdr/paths.h"

#include "twins/model_lighting.h"

bool hdr_lit_variant(const std::vector<ShaderDecl> &decls, int output_mode, Variant *out, std::string *err) {
  for (const ShaderDecl &d : decls) {
    if (d.name != "model_lighting") continue;
    for (const Variant &v : enumerate_variants(d, {Tier::SM3}, err)) {
      bool ok = true;
      for (const auto &kv : v.values) {
        const int want = kv.first == "ALBEDO_TEXTURE" || kv.first == "HALF_LAMBERT" ? 1
            : kv.first == "OUTPUT_MODE"                                             ? output_mode
                                                                                    : 0;
        if (kv.second != want) ok = false;
      }
      if (ok) {
        *out = v;
        return true;
      }
    }
  }
  *err = "no sm3 model_lighting variant with ALBEDO_TEXTURE=1, HALF_LAMBERT=1, OUTPUT_MODE=" +
      std::to_string(output_mode) + " and every other combo 0";
  return false;
}

HdrPipelineGl::HdrPipelineGl(PassRunner &run, Api api) : run_(run), api_(api) {}

HdrPipelineGl::~HdrPipelineGl() {
  const GlFns &g = run_.gl();
  gl_frame_release(run_.renderer(), &linear_);
  gl_frame_release(run_.renderer(), &display_prog_);
  for (GlTarget *t : {&display_, &hdr_, &ds_, &bx_, &by_}) free_target(g, t);
}

bool HdrPipelineGl::init(const ShaderFamily &lit, const Variant &lit_linear, const Variant &lit_display,
                         const FamilyInputs &scene, std::string *err) {
  lit_ = &lit;
  w_ = scene.w;
  h_ = scene.h;
  GlRenderer &r = run_.renderer();
  if (!gl_frame_setup(r, api_, lit, lit_linear, scene, &linear_, err) ||
      !gl_frame_setup(r, api_, lit, lit_display, scene, &display_prog_, err))
    return false;
  tex_linear_.assign(1, false);  // the record: NEAREST
  for (const TextureDesc &t : scene.textures) tex_linear_.push_back(t.linear);
  return init_post(w_, h_, err);
}

bool HdrPipelineGl::init_post(int w, int h, std::string *err, bool bloom) {
  w_ = w;
  h_ = h;
  const GlFns &g = run_.gl();
  const int bw = hdr_bloom_size(w_), bh = hdr_bloom_size(h_);
  if (!make_target(g, TargetFormat::RGBA8, w_, h_, &display_, err) ||
      !make_target(g, TargetFormat::RGBA16F, w_, h_, &hdr_, err) ||
      !make_target(g, TargetFormat::RGBA16F, bw, bh, &ds_, err) ||
      !make_target(g, TargetFormat::RGBA16F, bw, bh, &bx_, err) ||
      !make_target(g, TargetFormat::RGBA16F, bw, bh, &by_, err))
    return false;
  if (bloom) {
    down_ = run_.program(api_, "bloom_downsample", "sm3:SHAPE=0", err);
    if (down_) blur_x_ = run_.program(api_, "bloom_blur", "sm3:DIRECTION=0", err);
    if (blur_x_) blur_y_ = run_.program(api_, "bloom_blur", "sm3:DIRECTION=1", err);
    if (!blur_y_) return false;
  }
  tonemap_ = run_.program(api_, "hdr_tonemap", "sm3:OUTPUT_MODE=2", err);
  return tonemap_ != 0;
}

bool HdrPipelineGl::lit_pass(GLuint program, const std::vector<ts_vec4f> &shared, float scale, const GlTarget &t,
                             std::string *err) {
  const GlFns &g = run_.gl();
  std::vector<ts_vec4f> s = shared;
  s.at(ML_SLOT_PARAMS).x = scale;
  g.UseProgram(program);
  lit_->bind_uniforms(g, program, s);
  const GlFrameProgram &fp = program == linear_.program ? linear_ : display_prog_;
  std::vector<PassTexture> tex;
  for (size_t i = 0; i < fp.textures.size(); ++i) {
    // Cube and 3D textures belong to variants these paths do not use (Phong's envmap).
    if (g.GetUniformLocation(program, fp.textures[i].first.c_str()) < 0) continue;
    tex.push_back({fp.textures[i].first, fp.textures[i].second, tex_linear_.at(i)});
  }
  return run_.draw(program, t, tex, nullptr, err);
}

bool HdrPipelineGl::integer_frame(const std::vector<ts_vec4f> &shared, float tone_map_scale, std::string *err) {
  return lit_pass(display_prog_.program, shared, tone_map_scale, display_, err);
}

static void size4(int w, int h, float out[4]) {
  out[0] = static_cast<float>(w);
  out[1] = static_cast<float>(h);
  out[2] = 1.0f / static_cast<float>(w);
  out[3] = 1.0f / static_cast<float>(h);
}

bool HdrPipelineGl::post_float(const std::vector<float> &hdr_rgba, const HdrSettings &s, std::string *err) {
  const GlFns &g = run_.gl();
  if (hdr_rgba.size() != static_cast<size_t>(w_) * h_ * 4) {
    *err = "post_float: frame size mismatch";
    return false;
  }
  // Exact: every value is fp16-representable, so the upload's conversion does not round.
  g.BindTexture(GL_TEXTURE_2D, hdr_.tex);
  g.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  g.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w_, h_, GL_RGBA, GL_FLOAT, hdr_rgba.data());
  return post_chain(s, err);
}

bool HdrPipelineGl::float_frame(const std::vector<ts_vec4f> &shared, const HdrSettings &s, std::string *err) {
  if (!lit_pass(linear_.program, shared, 1.0f, hdr_, err)) return false;
  return post_chain(s, err);
}

bool HdrPipelineGl::post_chain(const HdrSettings &s, std::string *err) {
  float full[4], quarter[4];
  size4(w_, h_, full);
  size4(ds_.w, ds_.h, quarter);
  const float shape[4] = {0.3f, 0.59f, 0.11f, 2.2f};  // unused by SHAPE 0
  const float one[4] = {1.f, 0.f, 0.f, 0.f};
  if (s.bloom_amount != 0.f) {
    if (!down_) {
      *err = "post_chain: bloom asked for, but the bloom programs were not built (init_post bloom false)";
      return false;
    }
    run_.set_vec4(down_, "u_source_size", full);
    run_.set_vec4(down_, "u_shape", shape);
    if (!run_.draw(down_, ds_, {{"u_source", hdr_.tex, true}}, nullptr, err)) return false;
    run_.set_vec4(blur_x_, "u_source_size", quarter);
    run_.set_vec4(blur_x_, "u_params", one);
    if (!run_.draw(blur_x_, bx_, {{"u_source", ds_.tex, true}}, nullptr, err)) return false;
    run_.set_vec4(blur_y_, "u_source_size", quarter);
    run_.set_vec4(blur_y_, "u_params", one);
    if (!run_.draw(blur_y_, by_, {{"u_source", bx_.tex, true}}, nullptr, err)) return false;
  } else {
    // No bloom asked for: the three bloom passes are skipped and the combine reads a black
    // bloom (amount 0 x pow(0, exp) x 0 = 0), as hdr_post_float_c does.
    const GlFns &g = run_.gl();
    g.BindFramebuffer(GL_FRAMEBUFFER, by_.fbo);
    g.ClearColor(0.f, 0.f, 0.f, 0.f);
    g.Clear(GL_COLOR_BUFFER_BIT);
  }
  const float params[4] = {s.tone_map_scale, s.bloom_amount, s.bloom_exponent, 0.f};
  run_.set_vec4(tonemap_, "u_frame_size", full);
  run_.set_vec4(tonemap_, "u_params", params);
  return run_.draw(tonemap_, display_, {{"u_frame", hdr_.tex, false}, {"u_bloom", by_.tex, true}}, nullptr, err);
}

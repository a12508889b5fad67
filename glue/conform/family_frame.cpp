// tiershade conform: deferred GL frames and the multi-threaded C fallback (see frame.h).
#include "conform/family_frame.h"

#include <algorithm>
#include <cstring>

#include "base/parallel_rows.h"
#include "conform/conform.h"

bool gl_frame_setup(GlRenderer &r, Api api, const ShaderFamily &f, const Variant &v, const FamilyInputs &in,
                    GlFrameProgram *fp, std::string *err, const std::string &float_precision) {
  const Target t = target_for_api(api);
  Assembled vs, fs;
  if (!assemble("conform_fullscreen.vs", t, Stage::Vertex, {}, &vs, err)) return false;
  if (!assemble(v.shader->fragment, t, Stage::Fragment, variant_defines(v, InputMode::Deferred), &fs, err,
                float_precision))
    return false;
  fp->program = r.build_program(vs, fs, err);
  if (!fp->program) return false;
  const GlFns &g = r.gl();
  g.UseProgram(fp->program);
  const GLint size_loc = g.GetUniformLocation(fp->program, "ts_record_size");
  if (size_loc >= 0) g.Uniform2f(size_loc, static_cast<float>(in.w), static_cast<float>(in.h * in.slots));
  const GLint gh_loc = g.GetUniformLocation(fp->program, "ts_grid_height");
  if (gh_loc >= 0) g.Uniform1f(gh_loc, static_cast<float>(in.h));
  f.bind_uniforms(g, fp->program, in.shared);
  fp->textures.push_back({"ts_record", r.upload_texture(in.record_texture())});
  for (const auto &tex : in.textures) fp->textures.push_back({tex.sampler, r.upload_texture(tex)});
  return true;
}

bool gl_frame_draw(GlRenderer &r, const GlFrameProgram &fp, const FamilyInputs &in, ImageF *out, double *draw_ms,
                   std::string *err) {
  return r.draw(fp.program, fp.textures, in.w, in.h, out, err, draw_ms);
}

void gl_frame_release(GlRenderer &r, GlFrameProgram *fp) {
  for (auto &t : fp->textures) r.delete_texture(t.second);
  fp->textures.clear();
  r.delete_program(fp->program);
  fp->program = 0;
}

void cpu_render_frame(const ShaderFamily &f, const Variant &v, const FamilyInputs &in, ImageF *out, int threads) {
  out->w = in.w;
  out->h = in.h;
  out->rgba.assign(static_cast<size_t>(in.w) * in.h * 4, 0.f);
  if (f.eval_row_f) {  // the family's SIMD path: a row per call
    parallel_rows(in.h, threads, [&](int y) {
      thread_local std::vector<ts_vec4f> row;
      row.resize(static_cast<size_t>(in.w));
      f.eval_row_f(v, in, 0, y, in.w, row.data());
      std::memcpy(&out->rgba[static_cast<size_t>(y) * in.w * 4], row.data(), row.size() * sizeof(ts_vec4f));
    });
    return;
  }
  parallel_rows(in.h, threads, [&](int y) {
    for (int x = 0; x < in.w; ++x) {
      const ts_vec4f c = f.eval_f(v, in, x, y);
      float *p = &out->rgba[(static_cast<size_t>(y) * in.w + x) * 4];
      p[0] = c.x;
      p[1] = c.y;
      p[2] = c.z;
      p[3] = c.w;
    }
  });
}

void cpu_render_frame_double(const ShaderFamily &f, const Variant &v, const FamilyInputs &in, std::vector<double> *out,
                             int threads) {
  out->assign(static_cast<size_t>(in.w) * in.h * 4, 0.0);
  parallel_rows(in.h, threads, [&](int y) {
    for (int x = 0; x < in.w; ++x) {
      const ts_vec4d c = f.eval_d(v, in, x, y);
      double *p = &(*out)[(static_cast<size_t>(y) * in.w + x) * 4];
      p[0] = c.x;
      p[1] = c.y;
      p[2] = c.z;
      p[3] = c.w;
    }
  });
}

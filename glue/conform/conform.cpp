// tiershade conform: per-pixel GL-vs-C conformance (see conform.h).
#include "conform/conform.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/image_diff.h"

Target target_for_api(Api a) {
  switch (a) {
    case Api::GLES2:
      return Target::ESSL100;
    case Api::GLES3:
      return Target::ESSL300;
    case Api::GL33:
      return Target::GLSL330;
  }
  return Target::GLSL330;
}

bool adapt_textures_for_api(Api api, FamilyInputs *in) {
  if (api == Api::GL33) return false;
  bool changed = false;
  for (auto &t : in->textures) {
    if (t.kind == TexKind::Cube && t.linear) {
      t.linear = false;
      changed = true;
    }
  }
  return changed;
}

GLuint build_production_program(GlRenderer &r, Api api, const Variant &v, std::string *err) {
  const Target t = target_for_api(api);
  Assembled vs, fs;
  const auto defs = variant_defines(v, InputMode::Production);
  if (!assemble(v.shader->vertex, t, Stage::Vertex, defs, &vs, err)) return 0;
  if (!assemble(v.shader->fragment, t, Stage::Fragment, defs, &fs, err)) return 0;
  return r.build_program(vs, fs, err);
}

GLuint build_conform_program(GlRenderer &r, Api api, const Variant &v, std::string *err,
                             const std::string &float_precision) {
  const Target t = target_for_api(api);
  Assembled vs, fs;
  const auto defs = variant_defines(v, InputMode::Conform);
  if (!assemble("conform_fullscreen.vs", t, Stage::Vertex, {}, &vs, err, float_precision)) return 0;
  if (!assemble(v.shader->fragment, t, Stage::Fragment, defs, &fs, err, float_precision)) return 0;
  return r.build_program(vs, fs, err);
}

bool draw_conform_grid(GlRenderer &r, GLuint prog, const FamilyInputs &in, ImageF *img, std::string *err) {
  const GlFns &g = r.gl();
  g.UseProgram(prog);
  const GLint size_loc = g.GetUniformLocation(prog, "ts_record_size");
  if (size_loc >= 0) g.Uniform2f(size_loc, static_cast<float>(in.w), static_cast<float>(in.h * in.slots));
  const GLint gh_loc = g.GetUniformLocation(prog, "ts_grid_height");
  if (gh_loc >= 0) g.Uniform1f(gh_loc, static_cast<float>(in.h));
  std::vector<std::pair<std::string, GLuint>> texs;
  texs.push_back({"ts_record", r.upload_texture(in.record_texture())});
  for (const auto &t : in.textures) texs.push_back({t.sampler, r.upload_texture(t)});
  const bool ok = r.draw(prog, texs, in.w, in.h, img, err);
  for (auto &t : texs) r.delete_texture(t.second);
  r.delete_program(prog);
  return ok;
}

static std::string fmt_float(float f) {
  char b[64];
  uint32_t bits;
  memcpy(&bits, &f, 4);
  snprintf(b, sizeof b, "%.9g (0x%08x)", f, bits);
  return b;
}

std::string describe_pixel(const ShaderFamily &fam, const FamilyInputs &in, int x, int y) {
  std::ostringstream o;
  o << "  pixel (" << x << ", " << y << ")";
  if (!in.case_names.empty()) o << " hard case: " << in.case_names[static_cast<size_t>(y) * in.w + x];
  o << "\n  inputs:\n";
  for (int k = 0; k < fam.slots; ++k) {
    const ts_vec4f s = in.slot(x, y, k);
    char b[160];
    snprintf(b, sizeof b, "    %-14s %.9g %.9g %.9g %.9g\n", fam.slot_names[k].c_str(), s.x, s.y, s.z, s.w);
    o << b;
  }
  return o.str();
}

ConformResult conform_variant(const ConformRun &run, const ShaderFamily &fam, const Variant &v,
                              const FamilyInputs &in_given, InputSet set) {
  FamilyInputs adapted;
  const bool adapt = [&] {
    for (const auto &t : in_given.textures)
      if (t.kind == TexKind::Cube && t.linear && run.api != Api::GL33) return true;
    return false;
  }();
  if (adapt) {
    adapted = in_given;
    adapt_textures_for_api(run.api, &adapted);
  }
  const FamilyInputs &in = adapt ? adapted : in_given;
  ConformResult res;
  res.cube_maps_nearest = adapt;
  res.shader = fam.name;
  res.variant = v.name();
  res.tier = tier_name(v.tier);
  res.backend = backend_name(run.backend);
  res.api = api_name(run.api);
  res.set = input_set_name(set);
  const auto t0 = std::chrono::steady_clock::now();
  GlRenderer &r = *run.renderer;
  std::string err;
  // The production program (varyings and uniforms) must compile and link too.
  const GLuint prod = build_production_program(r, run.api, v, &err);
  if (!prod) {
    res.error = "production program: " + err;
    return res;
  }
  r.delete_program(prod);
  const GLuint prog = build_conform_program(r, run.api, v, &err);
  if (!prog) {
    res.error = err;
    return res;
  }
  ImageF img;
  if (!draw_conform_grid(r, prog, in, &img, &err)) {
    res.error = err;
    return res;
  }
  float lo, hi;
  fam.output_range(v, &lo, &hi);
  long worst_idx = -1;
  unsigned worst_ulp = 0;
  long first_bad_range = -1;
  for (int y = 0; y < in.h; ++y) {
    for (int x = 0; x < in.w; ++x) {
      const ts_vec4f c = fam.eval_f(v, in, x, y);
      const float *gp = &img.rgba[(static_cast<size_t>(y) * in.w + x) * 4];
      const float cv[4] = {c.x, c.y, c.z, c.w};
      bool bad = false;
      for (int ch = 0; ch < 4; ++ch) {
        const unsigned u = ulp_distance(gp[ch], cv[ch]);
        if (u > kConformMaxUlp) bad = true;
        if (u > res.max_ulp) res.max_ulp = u;
        const double a = std::fabs(static_cast<double>(gp[ch]) - cv[ch]);
        if (a > res.max_abs || std::isnan(a)) res.max_abs = std::isnan(a) ? INFINITY : std::fmax(res.max_abs, a);
        if (!std::isfinite(gp[ch]) || !std::isfinite(cv[ch]))
          ++res.nonfinite;
        else if (gp[ch] < lo || gp[ch] > hi || cv[ch] < lo || cv[ch] > hi) {
          ++res.out_of_range;
          if (first_bad_range < 0) first_bad_range = static_cast<long>(y) * in.w + x;
        }
        if (u > worst_ulp || (worst_idx < 0 && bad)) {
          worst_ulp = u;
          worst_idx = static_cast<long>(y) * in.w + x;
        }
      }
      if (bad) ++res.mismatches;
      ++res.pixels;
    }
  }
  if (worst_idx < 0 && first_bad_range >= 0) worst_idx = first_bad_range;
  if (worst_idx >= 0 && !res.passed()) {
    const int x = static_cast<int>(worst_idx % in.w), y = static_cast<int>(worst_idx / in.w);
    const ts_vec4f c = fam.eval_f(v, in, x, y);
    const float *gp = &img.rgba[static_cast<size_t>(worst_idx) * 4];
    const float cv[4] = {c.x, c.y, c.z, c.w};
    std::ostringstream o;
    o << describe_pixel(fam, in, x, y);
    for (int ch = 0; ch < 4; ++ch) {
      o << "  ch" << ch << ": GL " << fmt_float(gp[ch]) << "  C " << fmt_float(cv[ch]) << "  ULP "
        << ulp_distance(gp[ch], cv[ch]) << "\n";
    }
    res.worst = o.str();
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

std::string conform_result_json(const ConformResult &r) {
  nlohmann::ordered_json o;
  o["shader"] = r.shader;
  o["variant"] = r.variant;
  o["tier"] = r.tier;
  o["backend"] = r.backend;
  o["api"] = r.api;
  o["set"] = r.set;
  o["pixels"] = r.pixels;
  o["mismatches"] = r.mismatches;
  o["max_ulp"] = r.max_ulp;
  o["max_abs"] = r.max_abs;  // nlohmann writes a non-finite number as null
  o["nonfinite"] = r.nonfinite;
  o["out_of_range"] = r.out_of_range;
  o["cube_maps_nearest"] = r.cube_maps_nearest;
  o["passed"] = r.passed();
  if (!r.error.empty()) o["error"] = r.error;
  // A compiler message is not always UTF-8: replace what is not, rather than throw.
  return o.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

// tiershade conform: per-pixel error bounds (bounds.h): the interval instances of the twins,
// GL's output checked against them, and the per-variant summary (share inside, worst excess,
// interval widths in float32 ULP).
#include "conform/bounds.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/image_diff.h"
#include "families/color_correction_inputs.h"
#include "families/model_lighting.h"
#include "families/texture_grad.h"
#include "families/world_lighting.h"
#include "twins/bloom_blur.h"
#include "twins/bloom_downsample.h"
#include "twins/color_correction.h"
#include "twins/hdr_tonemap.h"
#include "twins/luminance_compare.h"
#include "twins/luminance_smooth.h"
#include "twins/model_lighting.h"
#include "twins/skybox.h"
#include "twins/world_lighting.h"

namespace {

// The family's interval twin on pixel (x, y): the same record and texture as its eval_f.
ts_vec4iv hdr_tonemap_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[HT_SLOTS];
  in.gather(x, y, HT_SLOTS, rec);
  const ht_variant hv = {v.value("OUTPUT_MODE")};  // as glue/families/hdr_tonemap.cpp's to_ht
  const ts_tex2d bloom = tex2d_of(in.textures.at(0));
  return hdr_tonemap_iv(&hv, rec, &bloom);
}

// The other families, each with the variant and texture views its glue/families/<family>.cpp
// gives its eval_f (the combo values and samplers are the same; the views are rebuilt per call).
ts_vec4iv model_lighting_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[ML_SLOTS];
  in.gather(x, y, ML_SLOTS, rec);
  const ml_variant mv = ml_variant_of(v);
  const MlTextureViews views(in);
  return model_lighting_iv(&mv, rec, &views.tex);
}

const TextureDesc &texture_named(const FamilyInputs &in, const char *sampler) {
  for (const TextureDesc &t : in.textures)
    if (t.sampler == sampler) return t;
  fprintf(stderr, "tiershade conform --bounds: the inputs have no texture for sampler '%s'\n", sampler);
  abort();
}

ts_vec4iv world_lighting_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[WL_SLOTS];
  in.gather(x, y, WL_SLOTS, rec);
  const wl_variant wv = wl_variant_of(v);
  const ts_tex2d base = tex2d_of(texture_named(in, "u_base")), nmap = tex2d_of(texture_named(in, "u_normalmap"));
  const ts_tex2d lm = tex2d_of(texture_named(in, "u_lightmap")), mask = tex2d_of(texture_named(in, "u_envmap_mask"));
  const ts_texcube env = texcube_of(texture_named(in, "u_envmap"));
  wl_textures t{};
  t.base = &base;
  t.normalmap = &nmap;
  t.lightmap = &lm;
  t.envmap_mask = &mask;
  t.envmap = &env;
  return world_lighting_iv(&wv, rec, &t);
}

ts_vec4iv skybox_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[SB_SLOTS];
  in.gather(x, y, SB_SLOTS, rec);
  const sb_variant sv = {tier_id(v.tier)};  // as glue/families/skybox.cpp's to_sb
  const ts_texcube sky = texcube_of(in.textures.at(0));
  return skybox_iv(&sv, rec, &sky);
}

ts_vec4iv bloom_blur_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[BB_SLOTS];
  in.gather(x, y, BB_SLOTS, rec);
  const bb_variant bv = {v.value("DIRECTION")};  // as bloom_blur.cpp's to_bb
  const ts_tex2d src = tex2d_of(in.textures.at(0));
  return bloom_blur_iv(&bv, rec, &src);
}

ts_vec4iv bloom_downsample_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[BD_SLOTS];
  in.gather(x, y, BD_SLOTS, rec);
  const bd_variant bv = {v.value("SHAPE")};  // as bloom_downsample.cpp's to_bd
  const ts_tex2d src = tex2d_of(in.textures.at(0));
  return bloom_downsample_iv(&bv, rec, &src);
}

ts_vec4iv color_correction_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[CC_SLOTS];
  in.gather(x, y, CC_SLOTS, rec);
  cc_variant cv;  // as color_correction.cpp's to_cc
  cv.atlas = v.value("LUT_ATLAS");
  cv.shader_trilinear = v.value("SHADER_TRILINEAR");
  cv.num_lookups = v.value("NUM_LOOKUPS");
  cc_luts luts;
  cc_luts_of(in, &luts);
  return color_correction_iv(&cv, rec, &luts);
}

ts_vec4iv luminance_compare_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[LC_SLOTS];
  in.gather(x, y, LC_SLOTS, rec);
  const lc_variant lv = {v.value("INPUT_ENCODING")};  // as luminance_compare.cpp's to_lc
  return luminance_compare_iv(&lv, rec);
}

ts_vec4iv luminance_smooth_bounds(const Variant &v, const FamilyInputs &in, int x, int y) {
  ts_vec4f rec[LS_SLOTS];
  in.gather(x, y, LS_SLOTS, rec);
  const ls_variant lv = {v.value("INPUT_ENCODING")};  // as luminance_smooth.cpp's to_ls
  return luminance_smooth_iv(&lv, rec);
}

struct BoundsEntry {
  const char *family;
  ts_vec4iv (*eval)(const Variant &, const FamilyInputs &, int, int);
};
const BoundsEntry kBounds[] = {{"hdr_tonemap", hdr_tonemap_bounds},
                               {"model_lighting", model_lighting_bounds},
                               {"world_lighting", world_lighting_bounds},
                               {"skybox", skybox_bounds},
                               {"bloom_blur", bloom_blur_bounds},
                               {"bloom_downsample", bloom_downsample_bounds},
                               {"color_correction", color_correction_bounds},
                               {"luminance_compare", luminance_compare_bounds},
                               {"luminance_smooth", luminance_smooth_bounds},
                               {"texture_grad", texture_grad_bounds}};

const BoundsEntry *find_bounds(const std::string &family) {
  for (const auto &e : kBounds)
    if (family == e.family) return &e;
  return nullptr;
}

std::string fmt_iv(ts_iv a) {
  char b[160];
  snprintf(b, sizeof b, "[%.9g, %.9g]%s", a.lo, a.hi, a.nan ? " or NaN" : "");
  return b;
}

}  // namespace

bool has_bounds(const std::string &family) { return find_bounds(family) != nullptr; }

ts_vec4iv eval_bounds(const ShaderFamily &fam, const Variant &v, const FamilyInputs &in, int x, int y) {
  return find_bounds(fam.name)->eval(v, in, x, y);
}

void check_bounds_image(const ShaderFamily &fam, const Variant &v, const FamilyInputs &in, const ImageF &img,
                        BoundsResult *out) {
  BoundsResult &res = *out;
  if (img.w != in.w || img.h != in.h || img.rgba.size() != static_cast<size_t>(in.w) * in.h * 4) {
    res.error = "the image is " + std::to_string(img.w) + "x" + std::to_string(img.h) + ", the grid " +
                std::to_string(in.w) + "x" + std::to_string(in.h);
    return;
  }
  std::vector<double> widths, to_double;
  long worst_idx = -1;
  int worst_ch = 0;
  for (int y = 0; y < in.h; ++y) {
    for (int x = 0; x < in.w; ++x) {
      const ts_vec4iv b = eval_bounds(fam, v, in, x, y);
      const ts_vec4f c = fam.eval_f(v, in, x, y);
      const ts_vec4d cd = fam.eval_d(v, in, x, y);
      const double dv[4] = {cd.x, cd.y, cd.z, cd.w};
      const ts_iv bi[4] = {b.x, b.y, b.z, b.w};
      const float cv[4] = {c.x, c.y, c.z, c.w};
      const float *gp = &img.rgba[(static_cast<size_t>(y) * in.w + x) * 4];
      for (int ch = 0; ch < 4; ++ch) {
        ++res.channels;
        const double wd = ts_ivwidth_ulp(bi[ch]);
        if (std::isinf(wd)) {
          ++res.unbounded;
          if (!in.case_names.empty()) {
            const std::string &cn = in.case_names[static_cast<size_t>(y) * in.w + x];
            if (std::find(res.unbounded_cases.begin(), res.unbounded_cases.end(), cn) == res.unbounded_cases.end())
              res.unbounded_cases.push_back(cn);
          }
        } else if (ch < 3) {
          widths.push_back(wd);  // the widths of the colour channels (alpha is often a constant)
          const float g = gp[ch], d = static_cast<float>(dv[ch]);
          if (std::isfinite(g) && std::isfinite(d)) {
            to_double.push_back(static_cast<double>(ulp_distance(g, d)));
            ++res.compared;
            if (std::memcmp(&g, &cv[ch], sizeof g) == 0) ++res.equal_to_c;
          }
        }
        if (!ts_ivcontains(bi[ch], cv[ch])) ++res.c_outside;
        if (!ts_ivcontains(bi[ch], gp[ch])) {
          ++res.outside;
          if (!in.case_names.empty()) {
            const std::string &cn = in.case_names[static_cast<size_t>(y) * in.w + x];
            if (std::find(res.outside_cases.begin(), res.outside_cases.end(), cn) == res.outside_cases.end())
              res.outside_cases.push_back(cn);
          }
          const double e = ts_ivexcess_ulp(bi[ch], gp[ch]);
          if (e > res.worst_excess_ulp || worst_idx < 0) {
            res.worst_excess_ulp = std::max(res.worst_excess_ulp, e);
            worst_idx = static_cast<long>(y) * in.w + x;
            worst_ch = ch;
          }
        } else if (worst_idx < 0 && !ts_ivcontains(bi[ch], cv[ch])) {
          worst_idx = static_cast<long>(y) * in.w + x;  // the C twin outside: show that pixel
          worst_ch = ch;
        }
      }
      ++res.pixels;
    }
  }
  if (!widths.empty()) {
    std::nth_element(widths.begin(), widths.begin() + static_cast<long>(widths.size() / 2), widths.end());
    res.median_width_ulp = widths[widths.size() / 2];
    res.max_width_ulp = *std::max_element(widths.begin(), widths.end());
  }
  if (!to_double.empty()) {
    std::nth_element(to_double.begin(), to_double.begin() + static_cast<long>(to_double.size() / 2), to_double.end());
    res.median_double_ulp = to_double[to_double.size() / 2];
    res.max_double_ulp = *std::max_element(to_double.begin(), to_double.end());
  }
  if (worst_idx >= 0) {
    const int x = static_cast<int>(worst_idx % in.w), y = static_cast<int>(worst_idx / in.w);
    const ts_vec4iv b = eval_bounds(fam, v, in, x, y);
    const ts_iv bi[4] = {b.x, b.y, b.z, b.w};
    const ts_vec4f c = fam.eval_f(v, in, x, y);
    const float cv[4] = {c.x, c.y, c.z, c.w};
    const float *gp = &img.rgba[static_cast<size_t>(worst_idx) * 4];
    std::ostringstream o;
    o << describe_pixel(fam, in, x, y);
    char line[256];
    snprintf(line, sizeof line, "  ch%d: GL %.9g  C %.9g  interval %s\n", worst_ch, gp[worst_ch], cv[worst_ch],
             fmt_iv(bi[worst_ch]).c_str());
    o << line;
    res.worst = o.str();
  }
}

BoundsResult bounds_variant(const ConformRun &run, const ShaderFamily &fam, const Variant &v,
                            const FamilyInputs &in_given, InputSet set) {
  FamilyInputs in = in_given;
  adapt_textures_for_api(run.api, &in);
  BoundsResult res;
  res.shader = fam.name;
  res.variant = v.name();
  res.tier = tier_name(v.tier);
  res.backend = backend_name(run.backend);
  res.api = api_name(run.api);
  res.set = input_set_name(set);
  if (!has_bounds(fam.name)) {
    res.error = "no interval instance of the " + std::string(fam.name) + " twin";
    return res;
  }
  GlRenderer &r = *run.renderer;
  std::string err;
  const GLuint prog = build_conform_program(r, run.api, v, &err, run.float_precision);
  if (!prog) {
    res.error = err;
    return res;
  }
  ImageF img;
  if (!draw_conform_grid(r, prog, in, &img, &err)) {
    res.error = err;
    return res;
  }
  check_bounds_image(fam, v, in, img, &res);
  return res;
}

std::string bounds_result_json(const BoundsResult &r) {
  nlohmann::ordered_json o;
  o["shader"] = r.shader;
  o["variant"] = r.variant;
  o["tier"] = r.tier;
  o["backend"] = r.backend;
  o["api"] = r.api;
  o["set"] = r.set;
  o["pixels"] = r.pixels;
  o["channels"] = r.channels;
  o["outside"] = r.outside;
  o["c_outside"] = r.c_outside;
  o["share_inside"] = r.share_inside();
  o["worst_excess_ulp"] = r.worst_excess_ulp;  // Inf (a NaN outside) is written as null
  o["unbounded"] = r.unbounded;
  o["unbounded_cases"] = r.unbounded_cases;
  o["outside_cases"] = r.outside_cases;
  o["median_width_ulp"] = r.median_width_ulp;
  o["max_width_ulp"] = r.max_width_ulp;
  o["median_double_ulp"] = r.median_double_ulp;
  o["max_double_ulp"] = r.max_double_ulp;
  o["compared"] = r.compared;
  o["equal_to_c"] = r.equal_to_c;
  o["passed"] = r.passed();
  if (!r.error.empty()) o["error"] = r.error;
  return o.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

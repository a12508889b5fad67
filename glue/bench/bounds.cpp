// tiershade bench: the bounds section of `tiershade bench` (docs/accuracy_cost.md, issue 14): per
// family and tier, the widths of the GLSL ES 3.00 intervals (conform/bounds.h) on llvmpipe, and the
// browser as a second implementation (glue/browser: headless Chromium, SwiftShader): its share inside,
// its distance from the C double against llvmpipe's, and how often the two agree bit for bit. The same
// grids as `tiershade conform --size 16` (seed 1). Not a test: nothing here passes or fails (make test
// runs the pass/fail form, conform --bounds and conform --backend chromium).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "base/stats.h"
#include "browser/webgl_conform.h"
#include "conform/bounds.h"
#include "families/family.h"
#include "gl/context.h"

namespace {

const int kGrid = 16;

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string num(double x) {
  char b[32];
  if (std::isinf(x)) return "inf";
  if (x < 1e4) snprintf(b, sizeof b, "%.0f", x);
  else snprintf(b, sizeof b, "%.2g", x);
  return b;
}

std::string pct(long a, long b) {
  char s[32];
  snprintf(s, sizeof s, "%.0f %%", b ? 100.0 * static_cast<double>(a) / static_cast<double>(b) : 0.0);
  return s;
}

bool run(const BenchOptions &, std::string *markdown, std::string *err) {
  static std::vector<ShaderDecl> decls;
  if (decls.empty() && !load_shader_decls(&decls, err)) return false;
  std::vector<Variant> variants;
  for (const auto &d : decls) {
    if (!find_family(d.name) || !has_bounds(d.name)) continue;
    auto v = enumerate_variants(d, all_tiers(), err);
    if (!err->empty()) return false;
    variants.insert(variants.end(), v.begin(), v.end());
  }
  const std::vector<InputSet> sets = {InputSet::Random, InputSet::Hard};
  std::map<std::string, std::vector<FamilyInputs>> inputs;
  for (const auto &v : variants) {
    const ShaderFamily *f = find_family(v.shader->name);
    if (inputs.count(f->name)) continue;
    for (InputSet s : sets) {
      FamilyInputs in;
      f->make_inputs(s, kGrid, kGrid, 7919u + static_cast<uint32_t>(s), &in);  // conform's seed 1
      inputs[f->name].push_back(in);
    }
  }
  // llvmpipe: EGL GLES 3.0
  auto ctx = GlContext::create(Backend::EGL, Api::GLES3, err);
  if (!ctx) return false;
  std::map<std::string, BoundsResult> lp;  // "shader variant set"
  {
    GlRenderer r(*ctx);
    ConformRun cr{&r, Backend::EGL, Api::GLES3};
    for (const auto &v : variants) {
      const ShaderFamily *f = find_family(v.shader->name);
      for (size_t si = 0; si < sets.size(); ++si) {
        BoundsResult res = bounds_variant(cr, *f, v, inputs[f->name][si], sets[si]);
        if (!res.error.empty()) {
          *err = v.shader->name + " " + v.name() + ": " + res.error;
          return false;
        }
        lp[res.shader + " " + res.variant + " " + res.set] = res;
      }
    }
  }
  // the browser: WebGL 2 (every variant; WebGL 1's are a subset of the same sources)
  WebglConformOptions wopt;
  wopt.webgl = 2;
  WebglConformOutcome wo;
  if (!webgl_conform(variants, inputs, sets, wopt, &wo, err)) return false;

  struct Agg {
    int variants = 0;
    long lp_inside = 0, lp_channels = 0, c_inside = 0, sw_inside_runs = 0, sw_runs = 0;
    long unb_r = 0, unb_h = 0, ch_r = 0, ch_h = 0, equal = 0, compared = 0;
    std::vector<double> width_r, width_h, sw_med, lp_med;
    double width_max = 0, sw_max = 0, lp_max = 0;
  };
  std::map<std::pair<std::string, int>, Agg> agg;  // (family, tier index)
  std::vector<std::string> order;
  for (const auto &v : variants) {
    if (std::find(order.begin(), order.end(), v.shader->name) == order.end()) order.push_back(v.shader->name);
    Agg &a = agg[{v.shader->name, static_cast<int>(v.tier)}];
    ++a.variants;
    for (InputSet s : sets) {
      const BoundsResult &l = lp[v.shader->name + " " + v.name() + " " + input_set_name(s)];
      a.lp_channels += l.channels;
      a.lp_inside += l.channels - l.outside;
      a.c_inside += l.channels - l.c_outside;
      a.width_max = std::max(a.width_max, l.max_width_ulp);
      if (s == InputSet::Random) {
        a.width_r.push_back(l.median_width_ulp);
        a.unb_r += l.unbounded;
        a.ch_r += l.channels;
        a.lp_med.push_back(l.median_double_ulp);
        a.lp_max = std::max(a.lp_max, l.max_double_ulp);
      } else {
        a.width_h.push_back(l.median_width_ulp);
        a.unb_h += l.unbounded;
        a.ch_h += l.channels;
      }
    }
  }
  for (const auto &res : wo.results) {
    auto it = std::find_if(variants.begin(), variants.end(),
                           [&](const Variant &v) { return v.shader->name == res.shader && v.name() == res.variant; });
    if (it == variants.end()) continue;
    Agg &a = agg[{res.shader, static_cast<int>(it->tier)}];
    ++a.sw_runs;
    if (res.error.empty() && res.outside == 0) ++a.sw_inside_runs;
    if (res.set == "random") {
      a.sw_med.push_back(res.median_double_ulp);
      a.sw_max = std::max(a.sw_max, res.max_double_ulp);
      a.equal += res.equal_to_c;
      a.compared += res.compared;
    }
  }
  std::ostringstream o;
  o << "## Error bounds per pixel, and the browser as a second implementation (issue 14)\n\n"
    << "Every variant on a " << kGrid << "x" << kGrid << " random and hard grid (`tiershade conform --size " << kGrid
    << "`, seed 1; rules and sources in docs/conformance.md \"Error bounds per pixel\"), on llvmpipe (EGL "
       "GLES 3.0, `--bounds`) and in headless Chromium (WebGL 2, ANGLE on SwiftShader: `"
    << wo.renderer
    << "`). Widths and distances in float32 ULP over the bounded colour channels; unbounded = the "
       "interval admits any value. \"From the C double\": the distance from the double twin rounded to "
       "float (median over the variants of each one's median / the largest). \"Equal\": the share of "
       "channels where SwiftShader gives exactly llvmpipe's bits (the C float twin).\n\n"
    << "| family | tier | variants | inside: llvmpipe / C twin | median width, random (median / worst variant) | "
       "median width, hard | max width | unbounded, random / hard | browser runs inside | browser from the C "
       "double | llvmpipe from the C double | equal to llvmpipe |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto &fam : order) {
    for (Tier t : all_tiers()) {
      auto it = agg.find({fam, static_cast<int>(t)});
      if (it == agg.end()) continue;
      const Agg &a = it->second;
      const double worst_r = a.width_r.empty() ? 0 : *std::max_element(a.width_r.begin(), a.width_r.end());
      o << "| " << fam << " | " << tier_name(t) << " | " << a.variants << " | " << pct(a.lp_inside, a.lp_channels)
        << " / " << pct(a.c_inside, a.lp_channels) << " | " << num(median_of(a.width_r)) << " / " << num(worst_r)
        << " | " << num(median_of(a.width_h)) << " | " << num(a.width_max) << " | " << pct(a.unb_r, a.ch_r) << " / "
        << pct(a.unb_h, a.ch_h) << " | " << a.sw_inside_runs << " / " << a.sw_runs << " | "
        << num(median_of(a.sw_med)) << " / " << num(a.sw_max) << " | " << num(median_of(a.lp_med)) << " / "
        << num(a.lp_max) << " | " << pct(a.equal, a.compared) << " |\n";
    }
  }
  o << "\nBrowser runs outside are on the hard grid's exact cube corner only "
       "(tests/conform/chromium_known_outside.txt, docs/conformance.md \"In a browser\"). What makes the "
       "bounds wide:\n"
       "- the CTS lookup precision (7 sub-texel weight bits) on every LINEAR lookup: 10^5-10^6 ULP on the "
       "random textures; variants without one are 17-120 ULP wide;\n"
       "- `pow` on a base that may be 0 is bounded since the shaders take the stable form "
       "`pow(max(x, 2^-60), k)` (Phong and rim, gamma 2.2 and sRGB output, LDR lightmap decode, bloom "
       "shaping; issue 14, docs/conformance.md \"After the pow guards\"): what stays unbounded is NaN "
       "input, inversesqrt of a length that may be 0 and lookups past 2^20;\n"
       "- RGBE lightmaps decoded after filtering (`exp2(255 a - 128)` of a filtered alpha): world_lighting's "
       "widest variants.\n";
  *markdown = o.str();
  return true;
}

const BenchSection kSection = {"bounds", run};
const BenchRegistrar kRegister(&kSection);

}  // namespace

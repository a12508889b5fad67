// tiershade browser: the conformance job for the WebGL page, its run in Chromium, and the check of
// what comes back (see webgl_conform.h).
#include "browser/webgl_conform.h"

#include <stdlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "base/base64.h"
#include "browser/chromium.h"
#include "bundle/webgl.h"
#include "io/atomic_dir.h"
#include "shaderlib/assembler.h"

namespace {

const char *kind_name(TexKind k) { return k == TexKind::Cube ? "cube" : k == TexKind::Tex3D ? "3d" : "2d"; }

std::string floats_b64(const std::vector<float> &v) { return base64_encode(v.data(), v.size() * sizeof(float)); }

struct PageProgram {
  size_t variant;  // index into the variants given
  const ShaderFamily *fam;
  std::string vs, fs;
  std::vector<int> grids;  // page grid index per input set
};

// Reads the page from the binary, adapts the grids (NEAREST cube maps), and assembles every variant
// the target offers; the others go to *not_offered.
bool prepare(const std::vector<Variant> &variants, const std::map<std::string, std::vector<FamilyInputs>> &inputs,
             int webgl, std::string *page_html, std::string *page_js,
             std::map<std::string, std::vector<FamilyInputs>> *adapted_out, std::vector<PageProgram> *programs_out,
             std::vector<std::string> *not_offered, std::string *err) {
  const Target target = webgl == 1 ? Target::ESSL100 : Target::ESSL300;
  if (!shader_library_read("glue/browser/webgl_conform.html", page_html) ||
      !shader_library_read("glue/browser/webgl_conform.js", page_js)) {
    *err = "the WebGL page (glue/browser/webgl_conform.html, .js) is not in this binary";
    return false;
  }
  // Browsers sample LINEAR cube maps seamlessly (WebGL 2 always; ANGLE in WebGL 1 too), which the
  // interval instance does not model: cube maps are sampled NEAREST, as conform does on GLES.
  std::map<std::string, std::vector<FamilyInputs>> &adapted = *adapted_out;
  adapted = inputs;
  for (auto &fi : adapted)
    for (auto &in : fi.second) adapt_textures_for_api(Api::GLES3, &in);
  std::vector<PageProgram> &programs = *programs_out;
  for (size_t i = 0; i < variants.size(); ++i) {
    const Variant &v = variants[i];
    const ShaderFamily *fam = find_family(v.shader->name);
    if (!fam || !has_bounds(fam->name) || !adapted.count(fam->name)) {
      *err = "shader '" + v.shader->name + "' has no C twin with an interval instance";
      return false;
    }
    bool offered = true;
    std::string why;
    if (!target_offers(v, target, &offered, &why, err)) return false;
    if (!offered) {
      not_offered->push_back(v.shader->name + " " + v.name() + ": " + why);
      continue;
    }
    Assembled vs, fs;
    if (!assemble("conform_fullscreen.vs", target, Stage::Vertex, {}, &vs, err) ||
        !assemble(v.shader->fragment, target, Stage::Fragment, variant_defines(v, InputMode::Conform), &fs, err))
      return false;
    programs.push_back({i, fam, vs.text, fs.text, {}});
  }
  return true;
}

// The intervals of every pixel of variant v over `in`: lo, hi (floats) and NaN admitted (bytes), base64.
nlohmann::json bounds_json(const ShaderFamily &fam, const Variant &v, const FamilyInputs &in) {
  const size_t n = static_cast<size_t>(in.w) * in.h * 4;
  std::vector<float> lo(n), hi(n);
  std::vector<uint8_t> nan(n);
  for (int y = 0; y < in.h; ++y)
    for (int x = 0; x < in.w; ++x) {
      const ts_vec4iv b = eval_bounds(fam, v, in, x, y);
      const ts_iv bi[4] = {b.x, b.y, b.z, b.w};
      for (int ch = 0; ch < 4; ++ch) {
        const size_t i = (static_cast<size_t>(y) * in.w + x) * 4 + ch;
        lo[i] = bi[ch].lo;
        hi[i] = bi[ch].hi;
        nan[i] = bi[ch].nan ? 1 : 0;
      }
    }
  return {{"lo", floats_b64(lo)}, {"hi", floats_b64(hi)}, {"nan", base64_encode(nan.data(), nan.size())}};
}

// The job of programs [p0, p1): their grids once each, their sources and draws; with_bounds (the
// user page): each draw's intervals, the variant's name, and the grids' case and slot names.
nlohmann::json job_json(std::vector<PageProgram> &programs, size_t p0, size_t p1, const std::vector<Variant> &variants,
                        const std::map<std::string, std::vector<FamilyInputs>> &adapted, const std::vector<InputSet> &sets,
                        int webgl, bool with_bounds) {
  nlohmann::json job;
  job["webgl"] = webgl;
  job["report"] = with_bounds;
  job["grids"] = nlohmann::json::array();
  job["programs"] = nlohmann::json::array();
  std::map<std::pair<std::string, size_t>, int> grid_index;
  for (size_t k = p0; k < p1; ++k) {
    PageProgram &pp = programs[k];
    pp.grids.clear();
    for (size_t si = 0; si < sets.size(); ++si) {
      const auto key = std::make_pair(std::string(pp.fam->name), si);
      if (!grid_index.count(key)) {
        const FamilyInputs &in = adapted.at(pp.fam->name).at(si);
        nlohmann::json g;
        g["w"] = in.w;
        g["h"] = in.h;
        g["slots"] = in.slots;
        g["records"] = floats_b64(in.records);
        g["textures"] = nlohmann::json::array();
        for (const auto &t : in.textures) {
          // WebGL 1 has no 3D textures; no variant it offers samples one (target_offers)
          if (t.kind == TexKind::Tex3D && webgl == 1) continue;
          nlohmann::json tj = {{"sampler", t.sampler}, {"kind", kind_name(t.kind)}, {"w", t.w}, {"h", t.h},
                               {"d", t.d}, {"linear", t.linear}, {"repeat", t.repeat},
                               {"data", floats_b64(t.rgba)}};
          // a 2D mip chain (glue/gl/mipmaps.h): levels 1.. and the mip filter (TS_MIP_NEAREST / _LINEAR)
          if (t.kind == TexKind::Tex2D && !t.mips.empty() && t.mip_filter != 0) {
            tj["mip_filter"] = t.mip_filter == 1 ? "nearest" : "linear";
            tj["levels"] = nlohmann::json::array();
            for (const auto &m : t.mips) tj["levels"].push_back(floats_b64(m));
          }
          g["textures"].push_back(tj);
        }
        if (with_bounds) {
          g["cases"] = in.case_names;
          g["slot_names"] = pp.fam->slot_names;
        }
        grid_index[key] = static_cast<int>(job["grids"].size());
        job["grids"].push_back(g);
      }
      pp.grids.push_back(grid_index[key]);
    }
    nlohmann::json pj = {{"vs", pp.vs}, {"fs", pp.fs}, {"draws", pp.grids}};
    if (with_bounds) {
      const Variant &v = variants[pp.variant];
      pj["shader"] = pp.fam->name;
      pj["variant"] = v.name();
      pj["sets"] = nlohmann::json::array();
      pj["bounds"] = nlohmann::json::array();
      for (size_t si = 0; si < sets.size(); ++si) {
        pj["sets"].push_back(input_set_name(sets[si]));
        pj["bounds"].push_back(bounds_json(*pp.fam, v, adapted.at(pp.fam->name).at(si)));
      }
    }
    job["programs"].push_back(pj);
  }
  return job;
}

}  // namespace

bool webgl_conform(const std::vector<Variant> &variants, const std::map<std::string, std::vector<FamilyInputs>> &inputs,
                   const std::vector<InputSet> &sets, const WebglConformOptions &opt, WebglConformOutcome *out,
                   std::string *err) {
  const char *api = opt.webgl == 1 ? "webgl1" : "webgl2";
  std::string page_html, page_js;
  std::map<std::string, std::vector<FamilyInputs>> adapted;
  std::vector<PageProgram> programs;
  if (!prepare(variants, inputs, opt.webgl, &page_html, &page_js, &adapted, &programs, &out->not_offered, err))
    return false;

  const int per_page = std::max(1, opt.programs_per_page);
  for (size_t p0 = 0; p0 < programs.size(); p0 += static_cast<size_t>(per_page)) {
    const size_t p1 = std::min(programs.size(), p0 + static_cast<size_t>(per_page));
    const nlohmann::json job = job_json(programs, p0, p1, variants, adapted, sets, opt.webgl, false);
    const std::string job_js = "var TS_JOB = " + job.dump() + ";\n";
    std::string text;
    if (!chromium_run_page({{"webgl_conform.html", page_html}, {"webgl_conform.js", page_js}, {"job.js", job_js}},
                           "webgl_conform.html", opt.timeout_s, &text, err))
      return false;
    // the page's lines: I (context), E (program error), R (a draw's floats), X (page error), DONE
    std::vector<std::vector<ImageF>> images(p1 - p0, std::vector<ImageF>(sets.size()));
    std::vector<std::string> perr(p1 - p0);
    bool done = false;
    size_t pos = 0;
    while (pos < text.size()) {
      size_t nl = text.find('\n', pos);
      if (nl == std::string::npos) nl = text.size();
      const std::string line = text.substr(pos, nl - pos);
      pos = nl + 1;
      if (line == "DONE") {
        done = true;
      } else if (line.compare(0, 2, "I ") == 0) {
        out->renderer = line.substr(2);
      } else if (line.compare(0, 2, "X ") == 0) {
        *err = "the WebGL page failed: " + line.substr(2);
        return false;
      } else if (line.compare(0, 2, "E ") == 0 || line.compare(0, 2, "R ") == 0) {
        char *end = nullptr;
        const long pi = strtol(line.c_str() + 2, &end, 10);
        if (!end || *end != ' ' || pi < 0 || static_cast<size_t>(pi) >= p1 - p0) {
          *err = "the WebGL page wrote a line for no program: " + line.substr(0, 80);
          return false;
        }
        if (line[0] == 'E') {
          try {
            perr[pi] = nlohmann::json::parse(end + 1).get<std::string>();
          } catch (const std::exception &) {
            perr[pi] = end + 1;
          }
          continue;
        }
        char *end2 = nullptr;
        const long di = strtol(end + 1, &end2, 10);
        std::vector<uint8_t> bytes;
        const PageProgram &pp = programs[p0 + static_cast<size_t>(pi)];
        if (!end2 || *end2 != ' ' || di < 0 || static_cast<size_t>(di) >= sets.size() ||
            !base64_decode(std::string(end2 + 1), &bytes)) {
          *err = "the WebGL page wrote a malformed result line: " + line.substr(0, 80);
          return false;
        }
        const FamilyInputs &in = adapted.at(pp.fam->name).at(static_cast<size_t>(di));
        ImageF &img = images[static_cast<size_t>(pi)][static_cast<size_t>(di)];
        if (bytes.size() != static_cast<size_t>(in.w) * in.h * 4 * sizeof(float)) {
          *err = "the WebGL page returned " + std::to_string(bytes.size()) + " bytes for a " + std::to_string(in.w) +
                 "x" + std::to_string(in.h) + " grid";
          return false;
        }
        img.w = in.w;
        img.h = in.h;
        img.rgba.resize(static_cast<size_t>(in.w) * in.h * 4);
        memcpy(img.rgba.data(), bytes.data(), bytes.size());
      }
    }
    if (!done) {
      *err = "the WebGL page did not run to its end (no DONE line): the browser may have stopped it";
      return false;
    }
    for (size_t k = p0; k < p1; ++k) {
      const PageProgram &pp = programs[k];
      const Variant &v = variants[pp.variant];
      for (size_t si = 0; si < sets.size(); ++si) {
        BoundsResult res;
        res.shader = pp.fam->name;
        res.variant = v.name();
        res.tier = tier_name(v.tier);
        res.backend = "chromium";
        res.api = api;
        res.set = input_set_name(sets[si]);
        const ImageF &img = images[k - p0][si];
        if (!perr[k - p0].empty())
          res.error = perr[k - p0];
        else if (img.rgba.empty())
          res.error = "the WebGL page returned no result for this draw";
        else
          check_bounds_image(*pp.fam, v, adapted.at(pp.fam->name).at(si), img, &res);
        out->results.push_back(res);
      }
    }
  }
  return true;
}

bool webgl_conform_write_page(const std::vector<Variant> &variants,
                              const std::map<std::string, std::vector<FamilyInputs>> &inputs,
                              const std::vector<InputSet> &sets, int webgl, const std::string &dir,
                              std::vector<std::string> *not_offered, size_t *programs_written, std::string *err) {
  std::string page_html, page_js;
  std::map<std::string, std::vector<FamilyInputs>> adapted;
  std::vector<PageProgram> programs;
  if (!prepare(variants, inputs, webgl, &page_html, &page_js, &adapted, &programs, not_offered, err)) return false;
  if (programs.empty()) {
    *err = "none of the selected variants is offered by WebGL " + std::to_string(webgl);
    return false;
  }
  const nlohmann::json job = job_json(programs, 0, programs.size(), variants, adapted, sets, webgl, true);
  DirWriter w;
  if (!w.begin(dir, "job.js", "conformance page", err) || !w.write("index.html", page_html, err) ||
      !w.write("webgl_conform.js", page_js, err) || !w.write("job.js", "var TS_JOB = " + job.dump() + ";\n", err) ||
      !w.commit(err))
    return false;
  *programs_written = programs.size();
  return true;
}

// tiershade cli: `conform` subcommand: per-pixel GL-vs-C conformance of every
// selected variant on every selected backend/API, on random and hard inputs.
#include <cstdio>
#include <map>
#include <set>

#include "io/text_lines.h"

#include "browser/webgl_conform.h"
#include "conform/bounds.h"
#include "conform/conform.h"
#include "families/family.h"
#include "families/hard_cases.h"
#include "cli/select_args.h"

// `tiershade conform --help`.
const char kHelp[] = R"(usage: tiershade conform [--shader S] [--tier T]... [--variant V] [--backend osmesa|egl|chromium|all]
                         [--api gl33|gles2|gles3|webgl1|webgl2|all] [--size N] [--set random|hard|all] [--seed K] [--json] [--verbose]
                         [--cases FILE]... [--list-cases] [--bounds [--precision highp|mediump]]
Renders an N x N grid of per-pixel input records through each variant on llvmpipe,
reads back RGBA32F and compares every pixel with the C reference (0 ULP allowed).
Hard inputs: the named cases of tests/conform/<shader>.cases (embedded; zero/denormal/huge/NaN
normals, light at the point, N.L = -1/0/1, colours up to 65504, Inf/NaN inputs...), each on a
random record; outputs must also be finite and in range. --cases FILE replaces the cases of the
shader FILE is named after (FILE = .../<shader>.cases; format: docs/conformance.md).
--list-cases prints the hard cases of the selected shaders and exits.
--bounds checks instead that every channel lies inside the interval GLSL ES 3.00 highp allows
(the twin's interval instance, c_ref/math/ts_interval.h; docs/conformance.md "Error bounds") and
reports per variant the share inside, the worst excess and the median and largest interval width
of the colour channels in float32 ULP (channels whose interval admits anything are counted as
unbounded; --verbose names the hard cases that have one). --precision mediump (with --bounds, on
GLES: --api gles2|gles3) compiles the shaders with mediump floats (llvmpipe computes them in fp16) and
checks them against the mediump rules instead (the CTS's mediump format, 9 fraction bits, range
2^14: docs/conformance.md "mediump"); widths stay in float32 ULP. Families without
an interval instance would be listed as skipped (every family has one).
--backend chromium runs the grids in headless Chromium (WebGL through ANGLE on SwiftShader, the page
glue/browser/webgl_conform.html; --api webgl1, webgl2 or all, default all) and checks them against
the bounds, as --bounds does (the 0-ULP check holds on llvmpipe only); variants the WebGL version
does not offer are listed, not run (docs/conformance.md "In a browser"). --page DIR writes,
instead, the conformance page a user opens on their own device (DIR/index.html: the programs, grids
and per-pixel intervals of the selected variants for --api webgl1 or webgl2; the page checks and
shows the result). --known-outside FILE
(chromium only): lines 'SHADER VARIANT HARD CASE NAME' where the browser is known to land outside;
a run outside on listed cases only passes with a note, a listed case found inside fails (stale).
Exit status 1 when any variant fails. --json prints one object per variant, backend, api and set.)";

// Prints one --bounds result (text form).
static void print_bounds_line(const BoundsResult &res, bool verbose) {
  printf("%s %s %s %s/%s %s: %.4f %% inside (%ld channels, C twin outside %ld), worst excess %.0f ULP, "
         "median width %.0f ULP, max %.0f ULP, %ld unbounded; from the C double median %.0f max %.0f ULP, %.2f %% "
         "equal to the C float twin\n",
         res.passed() ? "ok  " : "FAIL", res.shader.c_str(), res.variant.c_str(), res.backend.c_str(), res.api.c_str(),
         res.set.c_str(), 100.0 * res.share_inside(), res.channels, res.c_outside, res.worst_excess_ulp,
         res.median_width_ulp, res.max_width_ulp, res.unbounded, res.median_double_ulp, res.max_double_ulp,
         res.compared ? 100.0 * static_cast<double>(res.equal_to_c) / static_cast<double>(res.compared) : 100.0);
  if (!res.error.empty()) printf("  error: %s\n", res.error.c_str());
  if (verbose)
    for (const auto &cn : res.unbounded_cases) printf("  unbounded: %s\n", cn.c_str());
  if (!res.passed() && !res.worst.empty()) printf("  worst pixel:\n%s", res.worst.c_str());
}

// --backend chromium: the grids in headless Chromium, against the bounds (glue/browser).
// --known-outside FILE: lines 'SHADER VARIANT HARD CASE NAME' (the case name runs to the end of the
// line): hard cases where a browser is known to land outside the bounds. Key: "SHADER VARIANT|CASE".
static bool read_known_outside(const std::string &path, std::map<std::string, std::string> *known, std::string *err) {
  TextLines t;
  if (!t.open(path, "known-outside", err)) return false;
  std::string line;
  while (t.next(&line)) {
    const size_t a = line.find_first_not_of(" \t");
    if (a == std::string::npos) continue;
    const size_t b = line.find(' ', a);
    const size_t c = b == std::string::npos ? b : line.find_first_not_of(' ', b);
    const size_t d = c == std::string::npos ? c : line.find(' ', c);
    const size_t e = d == std::string::npos ? d : line.find_first_not_of(' ', d);
    if (e == std::string::npos) {
      *err = t.where() + ": expected 'SHADER VARIANT HARD CASE NAME'";
      return false;
    }
    std::string cname = line.substr(e);
    while (!cname.empty() && (cname.back() == ' ' || cname.back() == '\t' || cname.back() == '\r')) cname.pop_back();
    (*known)[line.substr(a, b - a) + " " + line.substr(c, d - c) + "|" + cname] = t.where();
  }
  return t.finish(err);
}

static int conform_in_browser(const std::vector<Variant> &variants,
                              const std::map<std::string, std::vector<FamilyInputs>> &inputs,
                              const std::vector<InputSet> &sets, const std::vector<int> &versions, bool json,
                              bool verbose, const std::map<std::string, std::string> &known) {
  long total = 0, failed = 0;
  std::set<std::string> known_seen_outside, known_run;  // keys of `known` outside somewhere / run at all
  bool first_json = true;
  if (json) printf("[\n");
  for (int ver : versions) {
    WebglConformOptions opt;
    opt.webgl = ver;
    WebglConformOutcome o;
    std::string err;
    if (!webgl_conform(variants, inputs, sets, opt, &o, &err)) {
      fprintf(stderr, "tiershade conform: chromium/webgl%d: %s\n", ver, err.c_str());
      ++failed;
      continue;
    }
    if (verbose && !json) {
      printf("# chromium/webgl%d: %s\n", ver, o.renderer.c_str());
      for (const auto &n : o.not_offered) printf("# not offered on webgl%d: %s\n", ver, n.c_str());
    }
    for (const auto &res0 : o.results) {
      BoundsResult res = res0;
      ++total;
      // a result outside only on listed hard cases passes, noted; any other case outside fails
      const std::string vkey = res.shader + " " + res.variant + "|";
      for (const auto &k : known)
        if (res.set == "hard" && k.first.compare(0, vkey.size(), vkey) == 0) known_run.insert(k.first);
      std::vector<std::string> listed;
      bool all_listed = res.error.empty() && res.c_outside == 0 && !res.outside_cases.empty();
      for (const auto &cn : res.outside_cases) {
        if (known.count(vkey + cn)) {
          listed.push_back(cn);
          known_seen_outside.insert(vkey + cn);
        } else {
          all_listed = false;
        }
      }
      const bool known_only = all_listed && !res.passed();
      if (!res.passed() && !known_only) ++failed;
      if (known_only && !json) {
        std::string names;
        for (const auto &cn : listed) names += (names.empty() ? "" : "; ") + cn;
        printf("ok   %s %s %s/%s %s: %ld channel(s) outside, all on hard cases known outside in a browser (%s)\n",
               res.shader.c_str(), res.variant.c_str(), res.backend.c_str(), res.api.c_str(), res.set.c_str(),
               res.outside, names.c_str());
        continue;
      }
      if (json) {
        printf("%s  %s", first_json ? "" : ",\n", bounds_result_json(res).c_str());
        first_json = false;
      } else {
        print_bounds_line(res, verbose);
      }
    }
    if (!json)
      printf("chromium/webgl%d: %zu variant(s) not offered by the target\n", ver, o.not_offered.size());
  }
  // a listed case that was run and never landed outside: the list is stale
  for (const auto &k : known) {
    if (!known_run.count(k.first) || known_seen_outside.count(k.first)) continue;
    ++failed;
    ++total;
    const size_t bar = k.first.find('|');
    printf("FAIL %s: hard case '%s' is listed as outside the bounds (%s) but every run of it is inside: delete the "
           "line\n",
           k.first.substr(0, bar).c_str(), k.first.substr(bar + 1).c_str(), k.second.c_str());
  }
  if (json)
    printf("\n]\n");
  else
    printf("conform --backend chromium: %ld runs, %ld passed, %ld failed\n", total, total - failed, failed);
  if (total == 0 && failed == 0) {
    fprintf(stderr, "tiershade conform --backend chromium: no selected variant is offered by the WebGL version(s)\n");
    return 1;
  }
  return failed ? 1 : 0;
}

int cmd_conform(int argc, char **argv) {
  Args a("conform", argc, argv, {"--help", "--json", "--verbose", "--list-cases", "--bounds"},
         {"--shader", "--tier", "--variant", "--backend", "--api", "--size", "--set", "--seed", "--cases",
          "--known-outside", "--page", "--precision"});
  if (a.help(kHelp)) return 0;
  a.no_positional();
  const int size = a.get_int("--size", 64, 1, 1024);
  const int seed = a.get_int("--seed", 1, 0, 1 << 30);
  const std::string set_name = a.get("--set", "all");
  std::vector<InputSet> sets;
  if (set_name == "random" || set_name == "all") sets.push_back(InputSet::Random);
  if (set_name == "hard" || set_name == "all") sets.push_back(InputSet::Hard);
  if (sets.empty()) a.fail("unknown input set '" + set_name + "' (random, hard, all)");
  for (const auto &file : a.all("--cases")) {
    std::string err;
    if (!use_hard_case_file(file, &err)) a.fail(err);
  }
  Selection sel;
  select_variants(a, &sel);
  // The hard cases of every selected family, checked before anything runs.
  std::map<std::string, const HardCases *> cases;
  for (const auto &v : sel.variants) {
    const ShaderFamily *f = find_family(v.shader->name);
    if (!f) a.fail("shader '" + v.shader->name + "' has no C twin registered");
    std::string err;
    if (!cases.count(f->name) && !family_hard_cases(*f, &cases[f->name], &err)) {
      fprintf(stderr, "tiershade conform: %s\n", err.c_str());
      return 1;
    }
  }
  if (a.flag("--list-cases")) {
    for (const auto &fc : cases) {
      const HardCases &hc = *fc.second;
      printf("%s: %zu hard cases (%s)", fc.first.c_str(), hc.cases.size(), hc.file.c_str());
      if (!hc.repeat.empty()) printf(", each once per %s value (%zu)", hc.repeat_combo.c_str(), hc.repeat.size());
      printf("\n");
      for (const auto &c : hc.cases) printf("  %s\n", c.name.c_str());
    }
    return 0;
  }
  const bool json = a.flag("--json");
  const bool page = a.has("--page");
  if (page && a.has("--backend")) a.fail("--page writes a page for any browser: it takes no --backend");
  const bool browser = page || a.get("--backend", "all") == "chromium";
  std::vector<int> webgl_versions;
  if (browser) {
    const std::string api = a.get("--api", page ? "webgl2" : "all");
    if (api == "webgl1" || api == "all") webgl_versions.push_back(1);
    if (api == "webgl2" || api == "all") webgl_versions.push_back(2);
    if (webgl_versions.empty()) a.fail("--backend chromium runs WebGL: --api webgl1, webgl2 or all, not '" + api + "'");
  } else if (a.has("--known-outside")) {
    a.fail("--known-outside lists what a browser is known to get outside the bounds: it needs --backend chromium");
  } else if (a.get("--api", "") == "webgl1" || a.get("--api", "") == "webgl2") {
    a.fail("--api " + a.get("--api") + " is WebGL: it needs --backend chromium");
  }
  const auto configs = browser ? std::vector<BackendApi>{} : select_configs(a);

  // Inputs are generated once per family and set, and shared by every variant and backend.
  std::map<std::string, std::vector<FamilyInputs>> inputs;
  for (const auto &v : sel.variants) {
    const ShaderFamily *f = find_family(v.shader->name);
    if (!f) a.fail("shader '" + v.shader->name + "' has no C twin registered");
    if (inputs.count(f->name)) continue;
    for (InputSet s : sets) {
      FamilyInputs in;
      f->make_inputs(s, size, size, static_cast<uint32_t>(seed) * 7919u + static_cast<uint32_t>(s), &in);
      inputs[f->name].push_back(in);
    }
  }

  if (page) {
    if (webgl_versions.size() != 1) a.fail("--page is for one WebGL version: --api webgl1 or webgl2");
    std::vector<std::string> not_offered;
    size_t written = 0;
    std::string perr;
    if (!webgl_conform_write_page(sel.variants, inputs, sets, webgl_versions[0], a.get("--page"), &not_offered, &written,
                                  &perr)) {
      fprintf(stderr, "tiershade conform --page %s: %s\n", a.get("--page").c_str(), perr.c_str());
      return 1;
    }
    printf("wrote %s: %zu variant(s) for WebGL %d (%zu not offered by it), %zu input set(s) of %dx%d; open %s/index.html "
           "in the browser to check\n",
           a.get("--page").c_str(), written, webgl_versions[0], not_offered.size(), sets.size(), size, size,
           a.get("--page").c_str());
    return 0;
  }
  if (browser) {
    std::map<std::string, std::string> known;
    std::string kerr;
    if (a.has("--known-outside") && !read_known_outside(a.get("--known-outside"), &known, &kerr)) a.fail(kerr);
    return conform_in_browser(sel.variants, inputs, sets, webgl_versions, json, a.flag("--verbose"), known);
  }

  long total = 0, failed = 0;
  const bool bounds = a.flag("--bounds");
  const std::string precision = a.get("--precision", "highp");
  if (precision != "highp" && precision != "mediump") a.fail("--precision '" + precision + "': expected highp or mediump");
  if (precision == "mediump") {
    if (!bounds) a.fail("--precision mediump is checked against the mediump bounds: it needs --bounds");
    for (const auto &cfg : configs)
      if (cfg.api != Api::GLES2 && cfg.api != Api::GLES3)
        a.fail(std::string("--precision mediump: desktop GL ignores precision qualifiers; use --api gles2 or gles3, not ") +
               api_name(cfg.api));
    ts_iv_set_mediump(1);  // the interval instance's mediump rules (c_ref/math/ts_interval.h)
  }
  std::map<std::string, int> skipped;  // --bounds: variants of families without an interval instance
  std::map<std::string, int> no_target;  // variants of shaders without a program for the API's target
  bool first_json = true;
  if (json) printf("[\n");
  for (const auto &cfg : configs) {
    std::string err;
    auto ctx = GlContext::create(cfg.backend, cfg.api, &err);
    if (!ctx) {
      fprintf(stderr, "tiershade conform: %s/%s: %s\n", backend_name(cfg.backend), api_name(cfg.api), err.c_str());
      ++failed;
      continue;
    }
    GlRenderer r(*ctx);
    ConformRun run{&r, cfg.backend, cfg.api, precision};
    if (a.flag("--verbose") && !json)
      printf("# %s/%s: %s\n", backend_name(cfg.backend), api_name(cfg.api), ctx->renderer().c_str());
    for (const auto &v : sel.variants) {
      const ShaderFamily *f = find_family(v.shader->name);
      const auto &ins = inputs[f->name];
      if (!v.shader->has_target(target_name(target_for_api(cfg.api)))) {
        ++no_target[v.shader->name + " on " + api_name(cfg.api)];
        continue;
      }
      if (bounds && !has_bounds(f->name)) {
        ++skipped[f->name];
        continue;
      }
      for (size_t si = 0; si < sets.size() && bounds; ++si) {
        const BoundsResult res = bounds_variant(run, *f, v, ins[si], sets[si]);
        ++total;
        if (!res.passed()) ++failed;
        if (json) {
          printf("%s  %s", first_json ? "" : ",\n", bounds_result_json(res).c_str());
          first_json = false;
          continue;
        }
        print_bounds_line(res, a.flag("--verbose"));
      }
      for (size_t si = 0; si < sets.size() && !bounds; ++si) {
        const ConformResult res = conform_variant(run, *f, v, ins[si], sets[si]);
        ++total;
        if (!res.passed()) ++failed;
        if (json) {
          printf("%s  %s", first_json ? "" : ",\n", conform_result_json(res).c_str());
          first_json = false;
        } else if (!res.passed() || a.flag("--verbose")) {
          printf("%s %s %s %s/%s %s: %ld px, %ld mismatched, max %u ULP, %ld non-finite, %ld out of range%s (%.2f s)\n",
                 res.passed() ? "ok  " : "FAIL", res.shader.c_str(), res.variant.c_str(), res.backend.c_str(),
                 res.api.c_str(), res.set.c_str(), res.pixels, res.mismatches, res.max_ulp, res.nonfinite,
                 res.out_of_range, res.cube_maps_nearest ? ", cube maps NEAREST" : "", res.seconds);
        }
        if (!res.passed() && !json) {
          if (!res.error.empty()) printf("  error: %s\n", res.error.c_str());
          if (!res.worst.empty()) printf("  worst pixel:\n%s", res.worst.c_str());
        }
      }
    }
  }
  if (json)
    printf("\n]\n");
  else
    printf("conform%s: %ld runs, %ld passed, %ld failed\n", bounds ? " --bounds" : "", total, total - failed, failed);
  for (const auto &nt : no_target)
    fprintf(stderr, "tiershade conform: skipped %d variant(s) of %s: the shader has no program for that target (its "
            ".variants 'targets')\n", nt.second, nt.first.c_str());
  for (const auto &sk : skipped)
    fprintf(stderr, "tiershade conform --bounds: skipped %d variant(s) of %s: no interval instance of its twin yet\n",
            sk.second, sk.first.c_str());
  if (bounds && total == 0 && failed == 0) {
    fprintf(stderr, "tiershade conform --bounds: none of the selected variants has an interval instance\n");
    return 1;
  }
  return failed ? 1 : 0;
}

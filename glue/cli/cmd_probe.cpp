// tiershade cli: `probe` subcommand: one pixel of one variant, evaluated in GL and in
// C (float32 bit-exact twin and the double reference), printed side by side.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "conform/conform.h"
#include "families/family.h"
#include "families/hard_cases.h"
#include "cli/select_args.h"
#include "base/image_diff.h"
#include "io/text_lines.h"

namespace {

// SLOT=x,y,z,w (--set) or a line 'SLOT x y z w' of --input: the case-file syntax
// (families/hard_cases.h), where a bare slot may take 1 to 4 values (the first components).
void set_slot_value(const Args &a, const ShaderFamily &f, FamilyInputs *in, Rng *rng, const std::string &where,
                    const std::string &line) {
  CaseAssignment asg;
  std::string err;
  if (!parse_case_assignment(f, line, where, true, &asg, &err)) a.fail(err);
  std::vector<ts_vec4f> rec(static_cast<size_t>(f.slots));
  for (int k = 0; k < f.slots; ++k) rec[k] = in->slot(0, 0, k);
  CaseEval env;
  env.rng = rng;
  apply_case_assignment(asg, env, rec.data());
  for (int k = 0; k < f.slots; ++k) in->set_slot(0, 0, k, rec[k]);
}

std::string fmt(float f) {
  char b[64];
  uint32_t bits;
  memcpy(&bits, &f, 4);
  snprintf(b, sizeof b, "%-16.9g 0x%08x", f, bits);
  return b;
}

}  // namespace

// `tiershade probe --help`.
const char kHelp[] = R"(usage: tiershade probe --shader S --variant V [--backend osmesa|egl] [--api gl33|gles2|gles3]
                       [--grid random|hard:X,Y | --case NAME] [--size N --seed K] [--cases FILE]
                       [--input FILE] [--set SLOT=x,y,z,w]...
Evaluates one pixel of a variant in GL and in C and prints both, with the ULP distance
and the double-precision reference. The pixel's input record starts from a conformance
grid pixel (--grid, same --size/--seed as `conform`), from the first pixel of the hard grid
that has hard case NAME (--case; the cases: tests/conform/<shader>.cases, or --cases FILE),
or from the first random record; then FILE (lines 'SLOT x y z w', # comments) and --set
override single slots (SLOT.xz for some components; the case-file syntax, docs/conformance.md).
Values accept nan, inf and hex floats. Slot names: see the worst-pixel report of conform.)";

int cmd_probe(int argc, char **argv) {
  Args a("probe", argc, argv, {"--help"},
         {"--shader", "--variant", "--backend", "--api", "--set", "--input", "--grid", "--case", "--cases", "--size",
          "--seed"});
  if (a.help(kHelp)) return 0;
  a.no_positional();
  if (!a.has("--shader") || !a.has("--variant")) a.fail("--shader and --variant are required");
  Selection sel;
  select_variants(a, &sel);
  const Variant v = sel.variants.at(0);
  const ShaderFamily *f = find_family(v.shader->name);
  if (!f) a.fail("shader '" + v.shader->name + "' has no C twin registered");
  const int size = a.get_int("--size", 64, 1, 1024);
  const int seed = a.get_int("--seed", 1, 0, 1 << 30);

  // The grid the pixel comes from, generated exactly as `conform` does.
  InputSet set = InputSet::Random;
  int gx = 0, gy = 0;
  if (a.has("--grid")) {
    const std::string g = a.get("--grid");
    const size_t colon = g.find(':');
    const std::string sname = g.substr(0, colon);
    if (sname == "hard")
      set = InputSet::Hard;
    else if (sname != "random")
      a.fail("--grid wants random|hard[:X,Y], got '" + g + "'");
    if (colon != std::string::npos && sscanf(g.c_str() + colon + 1, "%d,%d", &gx, &gy) != 2)
      a.fail("--grid wants SET:X,Y, got '" + g + "'");
    if (gx < 0 || gy < 0 || gx >= size || gy >= size)
      a.fail("--grid pixel lies outside the " + std::to_string(size) + "^2 grid");
  }
  for (const auto &file : a.all("--cases")) {
    std::string err;
    if (!use_hard_case_file(file, &err)) a.fail(err);
  }
  const HardCases *cases = nullptr;
  if (a.has("--case")) {
    if (a.has("--grid")) a.fail("--case and --grid both choose the pixel: give one");
    std::string err;
    if (!family_hard_cases(*f, &cases, &err)) a.fail(err);
    set = InputSet::Hard;
  }
  FamilyInputs grid;
  f->make_inputs(set, size, size, static_cast<uint32_t>(seed) * 7919u + static_cast<uint32_t>(set), &grid);
  if (cases) {  // the first pixel of the case (any repeat value), or the exact pixel name
    const std::string want = a.get("--case");
    size_t i = 0;
    while (i < grid.case_names.size() && grid.case_names[i] != want &&
           cases->cases[i % cases->cases.size()].name != want)
      ++i;
    if (i == grid.case_names.size()) {
      bool known = false;
      for (const auto &c : cases->cases) known = known || c.name == want;
      if (known)
        a.fail("hard case '" + want + "' has no pixel in the " + std::to_string(size) + "^2 grid (raise --size)");
      a.fail("unknown hard case '" + want + "' (" + cases->file + " has " + std::to_string(cases->cases.size()) +
             " cases; `tiershade conform --list-cases --shader " + f->name + "` lists them)");
    }
    gx = static_cast<int>(i % static_cast<size_t>(size));
    gy = static_cast<int>(i / static_cast<size_t>(size));
  }
  FamilyInputs in;
  in.resize(1, 1, f->slots);
  in.textures = grid.textures;
  for (int k = 0; k < f->slots; ++k) in.set_slot(0, 0, k, grid.slot(gx, gy, k));
  if (!grid.case_names.empty()) in.case_names = {grid.case_names[static_cast<size_t>(gy) * size + gx]};

  Rng rng(static_cast<uint32_t>(seed));  // for uniform() and pick() in --input and --set values
  if (a.has("--input")) {
    const std::string path = a.get("--input");
    TextLines file;
    std::string line, err;
    if (!file.open(path, "input", &err)) a.fail(err);
    while (file.next(&line)) {
      std::istringstream ls(line);
      std::string name, rest, tok;
      if (!(ls >> name)) continue;
      while (ls >> tok) rest += (rest.empty() ? "" : " ") + tok;
      set_slot_value(a, *f, &in, &rng, file.where(), name + " " + rest);
    }
    if (!file.finish(&err)) a.fail(err);
  }
  for (const auto &s : a.all("--set")) {
    const size_t eq = s.find('=');
    if (eq == std::string::npos) a.fail("--set: '" + s + "' is not SLOT=x,y,z,w");
    set_slot_value(a, *f, &in, &rng, "--set", s.substr(0, eq) + " " + s.substr(eq + 1));
  }

  Backend b = Backend::OSMesa;
  Api api = Api::GL33;
  if (a.has("--backend") && (!parse_backend(a.get("--backend"), &b) || b == Backend::CPU))
    a.fail("unknown backend '" + a.get("--backend") + "' (osmesa, egl)");
  if (a.has("--api") && !parse_api(a.get("--api"), &api)) a.fail("unknown api '" + a.get("--api") + "'");
  if (!a.has("--api") && b == Backend::EGL) api = Api::GLES3;
  std::string err;
  if (!config_supported(b, api, &err)) a.fail(err);
  if (adapt_textures_for_api(api, &in))
    printf("note: cube maps sampled with NEAREST on GLES (seamless filtering; see glue/conform/conform.h)\n");
  auto ctx = GlContext::create(b, api, &err);
  if (!ctx) {
    fprintf(stderr, "tiershade probe: %s\n", err.c_str());
    return 1;
  }
  GlRenderer r(*ctx);
  const GLuint prog = build_conform_program(r, api, v, &err);
  if (!prog) {
    fprintf(stderr, "tiershade probe: %s\n", err.c_str());
    return 1;
  }
  const GlFns &g = r.gl();
  g.UseProgram(prog);
  const GLint size_loc = g.GetUniformLocation(prog, "ts_record_size");
  if (size_loc >= 0) g.Uniform2f(size_loc, 1.f, static_cast<float>(f->slots));
  const GLint gh_loc = g.GetUniformLocation(prog, "ts_grid_height");
  if (gh_loc >= 0) g.Uniform1f(gh_loc, 1.f);
  std::vector<std::pair<std::string, GLuint>> texs = {{"ts_record", r.upload_texture(in.record_texture())}};
  for (const auto &t : in.textures) texs.push_back({t.sampler, r.upload_texture(t)});
  ImageF img;
  const bool ok = r.draw(prog, texs, 1, 1, &img, &err);
  for (auto &t : texs) r.delete_texture(t.second);
  r.delete_program(prog);
  if (!ok) {
    fprintf(stderr, "tiershade probe: %s\n", err.c_str());
    return 1;
  }
  const ts_vec4f c = f->eval_f(v, in, 0, 0);
  const ts_vec4d d = f->eval_d(v, in, 0, 0);
  printf("%s %s on %s/%s\n%s", f->name, v.name().c_str(), backend_name(b), api_name(api),
         describe_pixel(*f, in, 0, 0).c_str());
  const float cv[4] = {c.x, c.y, c.z, c.w};
  const double dv[4] = {d.x, d.y, d.z, d.w};
  printf("  %-3s %-27s %-27s %-8s %s\n", "ch", "GL (llvmpipe)", "C float32", "ULP", "C double");
  int worst = 0;
  for (int ch = 0; ch < 4; ++ch) {
    const unsigned u = ulp_distance(img.rgba[ch], cv[ch]);
    if (u) worst = 1;
    printf("  %-3d %s %s %-8u %.17g\n", ch, fmt(img.rgba[ch]).c_str(), fmt(cv[ch]).c_str(), u, dv[ch]);
  }
  printf("%s\n", worst ? "GL and C differ" : "GL and C agree bit for bit");
  return worst;
}

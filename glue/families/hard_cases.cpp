// tiershade families: parsing, checking and applying the hard-case files (see hard_cases.h;
// the format is in docs/conformance.md).
#include "families/hard_cases.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

#include "shaderlib/shader_sources.h"
#include "shaderlib/variants.h"

namespace {

std::map<std::string, std::vector<CaseFunction>> &function_registry() {
  static std::map<std::string, std::vector<CaseFunction>> r;
  return r;
}

const char *const kCaseDir = "tests/conform/";

std::string trim(const std::string &s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

// A swizzle of 1 to 4 distinct letters of xyzw.
bool parse_swizzle(const std::string &s, int comps[4], int *n) {
  if (s.empty() || s.size() > 4) return false;
  for (size_t i = 0; i < s.size(); ++i) {
    const char *p = std::strchr("xyzw", s[i]);
    if (!p || !s[i]) return false;
    comps[i] = static_cast<int>(p - "xyzw");
    for (size_t j = 0; j < i; ++j)
      if (comps[j] == comps[i]) return false;
  }
  *n = static_cast<int>(s.size());
  return true;
}

// SLOT or SLOT.SWIZZLE (slot names may contain dots: the longest name that fits wins).
bool parse_slot_ref(const ShaderFamily &fam, const std::string &tok, int *slot, int comps[4], int *n) {
  int best = -1;
  for (int k = 0; k < fam.slots; ++k) {
    const std::string &s = fam.slot_names[k];
    if (tok == s) {
      *slot = k;
      *n = 4;
      for (int i = 0; i < 4; ++i) comps[i] = i;
      return true;
    }
    if (tok.size() > s.size() + 1 && tok.compare(0, s.size(), s) == 0 && tok[s.size()] == '.' &&
        (best < 0 || s.size() > fam.slot_names[best].size()))
      best = k;
  }
  if (best < 0) return false;
  *slot = best;
  return parse_swizzle(tok.substr(fam.slot_names[best].size() + 1), comps, n);
}

std::string slot_list(const ShaderFamily &fam) {
  std::string names;
  for (const auto &s : fam.slot_names) names += " " + s;
  return names;
}

// The built-in functions (docs/conformance.md); add, sub, mul and nextafter work per component.
bool componentwise(const std::string &fn) { return fn == "add" || fn == "sub" || fn == "mul" || fn == "nextafter"; }
const char *const kBuiltins[] = {"vec", "add", "sub", "mul", "nextafter", "normalize", "uniform", "pick"};

class ExprParser {
 public:
  ExprParser(const ShaderFamily &fam, const std::string &text) : fam_(fam), s_(text) {}

  // Terms separated by blanks or commas, up to the end of the text.
  bool parse_list(std::vector<CaseExpr> *out, std::string *err) {
    for (;;) {
      skip_separators();
      if (pos_ >= s_.size()) return true;
      CaseExpr e;
      if (!parse_term(&e, err)) return false;
      out->push_back(e);
    }
  }

 private:
  void skip_blanks() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r')) ++pos_;
  }
  void skip_separators() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r' || s_[pos_] == ',')) ++pos_;
  }
  std::string word() {
    const size_t a = pos_;
    while (pos_ < s_.size() && !std::strchr(" \t\r,()", s_[pos_])) ++pos_;
    return s_.substr(a, pos_ - a);
  }

  bool parse_term(CaseExpr *e, std::string *err) {
    const std::string w = word();
    if (w.empty()) {
      *err = std::string("expected a value, found '") + s_[pos_] + "'";
      return false;
    }
    skip_blanks();
    if (pos_ < s_.size() && s_[pos_] == '(') {
      ++pos_;
      e->kind = CaseExpr::Call;
      e->fn = w;
      for (;;) {
        skip_blanks();
        if (pos_ >= s_.size()) {
          *err = "missing ')' after the arguments of " + w + "()";
          return false;
        }
        if (s_[pos_] == ')') {
          ++pos_;
          break;
        }
        if (!e->args.empty()) {
          if (s_[pos_] != ',') {
            *err = "expected ',' or ')' in the arguments of " + w + "()";
            return false;
          }
          ++pos_;
        }
        CaseExpr a;
        skip_blanks();
        if (!parse_term(&a, err)) return false;
        e->args.push_back(a);
      }
      return check_call(e, err);
    }
    // A number: decimal (the nearest float, as a C literal), hex float, nan, inf, with a sign.
    errno = 0;
    char *end = nullptr;
    const float f = std::strtof(w.c_str(), &end);
    if (end != w.c_str() && *end == 0) {
      uint32_t bits;
      std::memcpy(&bits, &f, 4);  // not f == 0: under DAZ a denormal compares equal to 0
      if (errno == ERANGE && (bits & 0x7fffffffu) % 0x7f800000u == 0) {
        *err = "number '" + w + "' is outside the float range (write inf or 0 for those)";
        return false;
      }
      e->kind = CaseExpr::Number;
      e->number = f;
      e->width = 1;
      return true;
    }
    int n = 0;
    if (!parse_slot_ref(fam_, w, &e->slot, e->comps, &n)) {
      if (std::strchr("+-.0123456789", w[0]))
        *err = "bad number '" + w + "'";
      else
        *err = "unknown slot or value '" + w + "'; " + fam_.name + " has:" + slot_list(fam_);
      return false;
    }
    e->kind = CaseExpr::Ref;
    e->width = n;
    return true;
  }

  bool check_call(CaseExpr *e, std::string *err) {
    const std::string &f = e->fn;
    std::vector<int> w;
    for (const auto &a : e->args) w.push_back(a.width);
    auto bad = [&](const std::string &why) {
      *err = f + "(): " + why;
      return false;
    };
    if (f == "vec") {
      if (w.empty()) return bad("needs at least one argument");
      e->width = 0;
      for (int x : w) e->width += x;
      if (e->width > 4) return bad("more than 4 components");
      return true;
    }
    if (componentwise(f)) {
      if (w.size() != 2) return bad("takes 2 arguments");
      if (w[0] != w[1] && w[0] != 1 && w[1] != 1)
        return bad("argument widths " + std::to_string(w[0]) + " and " + std::to_string(w[1]) + " differ");
      e->width = std::max(w[0], w[1]);
      return true;
    }
    if (f == "normalize") {
      if (w.size() != 1 || w[0] != 3) return bad("takes one 3-component argument");
      e->width = 3;
      return true;
    }
    if (f == "uniform") {
      if (w.size() != 2 || w[0] != 1 || w[1] != 1) return bad("takes 2 numbers (lo, hi)");
      e->width = 1;
      return true;
    }
    if (f == "pick") {
      if (w.size() < 2) return bad("needs at least 2 choices");
      for (int x : w)
        if (x != w[0]) return bad("every choice must have the same width");
      e->width = w[0];
      return true;
    }
    auto reg = function_registry().find(fam_.name);
    if (reg != function_registry().end())
      for (const CaseFunction &cf : reg->second) {
        if (cf.name != f) continue;
        if (w != cf.arg_widths) {
          std::string want;
          for (int x : cf.arg_widths) want += (want.empty() ? "" : ", ") + std::to_string(x);
          return bad("wants arguments of widths (" + want + ")");
        }
        e->width = cf.result_width;
        e->family_fn = &cf;
        return true;
      }
    std::string names;
    for (const char *b : kBuiltins) names += std::string(" ") + b;
    if (reg != function_registry().end())
      for (const CaseFunction &cf : reg->second) names += " " + cf.name;
    *err = "unknown function '" + f + "'; " + fam_.name + " cases may call:" + names;
    return false;
  }

  const ShaderFamily &fam_;
  std::string s_;
  size_t pos_ = 0;
};

void eval_expr(const CaseExpr &e, const CaseEval &env, const ts_vec4f *rec, float *out) {
  switch (e.kind) {
    case CaseExpr::Number:
      out[0] = e.number;
      return;
    case CaseExpr::Ref: {
      const float *s = &rec[e.slot].x;
      for (int i = 0; i < e.width; ++i) out[i] = s[e.comps[i]];
      return;
    }
    case CaseExpr::Call:
      break;
  }
  const std::string &f = e.fn;
  if (f == "pick") {  // draws first, then evaluates the chosen argument only
    const uint32_t k = env.rng->next() % static_cast<uint32_t>(e.args.size());
    eval_expr(e.args[k], env, rec, out);
    return;
  }
  float a[16];
  int n = 0;
  for (const auto &arg : e.args) {  // left to right: the order of the draws
    eval_expr(arg, env, rec, a + n);
    n += arg.width;
  }
  if (f == "vec") {
    for (int i = 0; i < n; ++i) out[i] = a[i];
  } else if (componentwise(f)) {
    const int wa = e.args[0].width, wb = e.args[1].width;
    for (int i = 0; i < e.width; ++i) {
      const float x = a[wa == 1 ? 0 : i], y = a[wa + (wb == 1 ? 0 : i)];
      out[i] = f == "add" ? x + y : f == "sub" ? x - y : f == "mul" ? x * y : std::nextafter(x, y);
    }
  } else if (f == "normalize") {
    const ts_vec3f v = ts_normalize3f(ts_v3f(a[0], a[1], a[2]));
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
  } else if (f == "uniform") {
    out[0] = env.rng->uniform(a[0], a[1]);
  } else {
    e.family_fn->eval(a, env, out);
  }
}

// Whether a value expression holds a NaN or Inf number literal (anywhere in its calls).
bool has_nonfinite_number(const std::vector<CaseExpr> &values) {
  for (const auto &v : values) {
    if (v.kind == CaseExpr::Number && !std::isfinite(v.number)) return true;
    if (v.kind == CaseExpr::Call && has_nonfinite_number(v.args)) return true;
  }
  return false;
}

// The combo of the [repeat] an expression reads (through a family function), if any.
bool uses_repeat(const CaseExpr &e, std::string *combo) {
  if (e.family_fn && !e.family_fn->repeat_combo.empty()) {
    *combo = e.family_fn->repeat_combo;
    return true;
  }
  for (const auto &a : e.args)
    if (uses_repeat(a, combo)) return true;
  return false;
}

const ShaderDecl *find_decl(const std::vector<ShaderDecl> &decls, const std::string &name) {
  for (const auto &d : decls)
    if (d.name == name) return &d;
  return nullptr;
}

}  // namespace

CaseFunctionRegistrar::CaseFunctionRegistrar(const char *family, std::vector<CaseFunction> fns) {
  auto &v = function_registry()[family];
  for (auto &f : fns) v.push_back(std::move(f));
}

bool parse_case_assignment(const ShaderFamily &fam, const std::string &line, const std::string &where, bool prefix_ok,
                           CaseAssignment *out, std::string *err) {
  const std::string t = trim(line);
  const size_t sp = t.find_first_of(" \t");
  const std::string target = t.substr(0, sp);
  const std::string rest = sp == std::string::npos ? "" : t.substr(sp);
  *out = CaseAssignment();
  out->where = where;
  int n = 0;
  if (!parse_slot_ref(fam, target, &out->slot, out->comps, &n)) {
    *err = where + ": unknown slot '" + target + "'; " + fam.name + " has:" + slot_list(fam);
    return false;
  }
  const bool bare = target == fam.slot_names[out->slot];
  ExprParser p(fam, rest);
  std::string e;
  if (!p.parse_list(&out->values, &e)) {
    *err = where + ": " + t + ": " + e;
    return false;
  }
  int width = 0;
  for (const auto &v : out->values) width += v.width;
  if (width == 0 || width > n || (width < n && !(bare && prefix_ok))) {
    *err = where + ": '" + target + "' wants " + (bare && prefix_ok ? "1 to 4" : std::to_string(n)) + " values, got " +
        std::to_string(width);
    return false;
  }
  out->width = width;
  return true;
}

void apply_case_assignment(const CaseAssignment &a, const CaseEval &env, ts_vec4f *rec) {
  float v[4];
  int n = 0;
  for (const auto &e : a.values) {
    eval_expr(e, env, rec, v + n);
    n += e.width;
  }
  float *s = &rec[a.slot].x;
  for (int i = 0; i < a.width; ++i) s[a.comps[i]] = v[i];
}

bool parse_hard_cases(const ShaderFamily &fam, const std::string &file, const std::string &text, HardCases *out,
                      std::string *err) {
  *out = HardCases();
  out->family = fam.name;
  out->file = file;
  std::istringstream in(text);
  std::string raw;
  int lineno = 0, repeat_line = 0;
  enum { None, InCase, InRepeat } section = None;
  auto fail = [&](int line, const std::string &why) {
    *err = file + ":" + std::to_string(line) + ": " + why;
    return false;
  };
  while (std::getline(in, raw)) {
    ++lineno;
    const size_t hash = raw.find('#');
    const std::string line = trim(hash == std::string::npos ? raw : raw.substr(0, hash));
    if (line.empty()) continue;
    if (line[0] == '[') {
      if (line.back() != ']') return fail(lineno, "a section header is '[case NAME]' or '[repeat COMBO]'");
      const std::string head = trim(line.substr(1, line.size() - 2));
      if (head.compare(0, 5, "case ") == 0 && !trim(head.substr(5)).empty()) {
        HardCase c;
        c.name = trim(head.substr(5));
        c.line = lineno;
        for (const auto &o : out->cases)
          if (o.name == c.name)
            return fail(lineno, "duplicate case '" + c.name + "' (first at line " + std::to_string(o.line) + ")");
        out->cases.push_back(c);
        section = InCase;
      } else if (head.compare(0, 7, "repeat ") == 0 && !trim(head.substr(7)).empty()) {
        if (repeat_line)
          return fail(lineno, "a second [repeat] section (the first is at line " + std::to_string(repeat_line) + ")");
        repeat_line = lineno;
        out->repeat_combo = trim(head.substr(7));
        std::vector<ShaderDecl> decls;
        std::string e;
        if (!load_shader_decls(&decls, &e)) return fail(lineno, e);
        const ShaderDecl *d = find_decl(decls, fam.name);
        const Combo *combo = nullptr;
        if (d)
          for (const auto &c : d->combos)
            if (c.name == out->repeat_combo) combo = &c;
        if (!combo)
          return fail(lineno, "shader " + std::string(fam.name) + " has no combo '" + out->repeat_combo + "'");
        section = InRepeat;
      } else {
        return fail(lineno, "unknown section '" + line + "' (sections: [case NAME], [repeat COMBO])");
      }
      continue;
    }
    if (section == None) return fail(lineno, "'" + line + "' is outside a section (start a case with [case NAME])");
    if (section == InRepeat) {
      std::istringstream ls(line);
      std::string v;
      ls >> v;
      char *end = nullptr;
      const long value = std::strtol(v.c_str(), &end, 10);
      std::string label;
      std::getline(ls, label);
      label = trim(label);
      if (end == v.c_str() || *end || label.empty())
        return fail(lineno, "a [repeat] line is 'VALUE LABEL' (an integer and a label), got '" + line + "'");
      std::vector<ShaderDecl> decls;
      std::string e;
      load_shader_decls(&decls, &e);
      for (const auto &c : find_decl(decls, fam.name)->combos)
        if (c.name == out->repeat_combo && (value < c.min || value > c.max))
          return fail(
              lineno,
              out->repeat_combo + " has values " + std::to_string(c.min) + ".." + std::to_string(c.max) + ", not " + v);
      for (const auto &r : out->repeat)
        if (r.first == value) return fail(lineno, "value " + v + " is repeated twice");
      out->repeat.push_back({static_cast<int>(value), label});
      continue;
    }
    HardCase &c = out->cases.back();
    if (line == "random") {
      if (c.random) return fail(lineno, "'random' twice in case '" + c.name + "'");
      c.random = true;
      continue;
    }
    if (line == "llvmpipe_only") {
      if (c.llvmpipe_only) return fail(lineno, "'llvmpipe_only' twice in case '" + c.name + "'");
      c.llvmpipe_only = true;
      continue;
    }
    CaseAssignment a;
    if (!parse_case_assignment(fam, line, file + ":" + std::to_string(lineno), false, &a, err)) return false;
    if (!c.llvmpipe_only && has_nonfinite_number(a.values))
      return fail(lineno, "case '" + c.name +
                              "' writes NaN or Inf: such inputs are outside the portable contract, so the case "
                              "must say 'llvmpipe_only' (before this line)");
    std::string combo;
    for (const auto &v : a.values)
      if (uses_repeat(v, &combo) && combo != out->repeat_combo)
        return fail(lineno,
                    "the value reads the pixel's " + combo + ": the file needs a [repeat " + combo + "] section");
    c.body.push_back(a);
  }
  if (repeat_line && out->repeat.empty()) return fail(repeat_line, "[repeat " + out->repeat_combo + "] lists no value");
  if (out->cases.empty()) return fail(lineno, "no [case NAME] in the file");
  for (const auto &c : out->cases) {
    if (c.body.empty()) return fail(c.line, "case '" + c.name + "' sets no slot");
    if (c.random) continue;
    std::vector<bool> set(static_cast<size_t>(fam.slots) * 4, false);
    for (const auto &a : c.body)
      for (int i = 0; i < a.width; ++i) set[static_cast<size_t>(a.slot) * 4 + a.comps[i]] = true;
    for (size_t i = 0; i < set.size(); ++i)
      if (!set[i])
        return fail(c.line,
                    "case '" + c.name + "' leaves " + fam.slot_names[i / 4] + "." + "xyzw"[i % 4] +
                        " unset (set every slot, or write 'random' to keep the random record's values)");
  }
  return true;
}

std::string HardCases::pixel_name(size_t i) const {
  const std::string &n = cases[i % cases.size()].name;
  if (repeat.empty()) return n;
  return n + " (" + repeat[(i / cases.size()) % repeat.size()].second + ")";
}

void HardCases::apply(size_t i, Rng *rng, ts_vec4f *rec) const {
  CaseEval env;
  env.rng = rng;
  if (!repeat.empty()) env.repeat_value = repeat[(i / cases.size()) % repeat.size()].first;
  for (const auto &a : cases[i % cases.size()].body) apply_case_assignment(a, env, rec);
}

namespace {

std::mutex g_cases_mutex;
std::map<std::string, std::unique_ptr<HardCases>> &case_cache() {
  static std::map<std::string, std::unique_ptr<HardCases>> c;
  return c;
}

const char *embedded_text(const std::string &path) {
  for (const EmbeddedFile *e = kShaderFiles; e->name; ++e)
    if (path == e->name) return e->text;
  return nullptr;
}

}  // namespace

std::vector<std::string> embedded_case_files() {
  std::vector<std::string> v;
  for (const EmbeddedFile *e = kShaderFiles; e->name; ++e)
    if (std::strncmp(e->name, kCaseDir, std::strlen(kCaseDir)) == 0) v.push_back(e->name);
  return v;
}

bool family_hard_cases(const ShaderFamily &fam, const HardCases **out, std::string *err) {
  std::lock_guard<std::mutex> lock(g_cases_mutex);
  auto &cache = case_cache();
  auto it = cache.find(fam.name);
  if (it == cache.end()) {
    const std::string path = std::string(kCaseDir) + fam.name + ".cases";
    const char *text = embedded_text(path);
    if (!text) {
      *err = path + ": no such case file: the hard cases of " + fam.name + " are missing (every family needs one)";
      return false;
    }
    std::unique_ptr<HardCases> hc(new HardCases);
    if (!parse_hard_cases(fam, path, text, hc.get(), err)) return false;
    it = cache.emplace(fam.name, std::move(hc)).first;
  }
  *out = it->second.get();
  return true;
}

bool use_hard_case_file(const std::string &path, std::string *err) {
  const size_t slash = path.find_last_of('/');
  std::string stem = path.substr(slash == std::string::npos ? 0 : slash + 1);
  if (stem.size() <= 6 || stem.compare(stem.size() - 6, 6, ".cases") != 0) {
    *err = path + ": a case file is named FAMILY.cases (e.g. model_lighting.cases)";
    return false;
  }
  stem.resize(stem.size() - 6);
  const ShaderFamily *fam = find_family(stem);
  if (!fam) {
    std::string names;
    for (const ShaderFamily *f : all_families()) names += std::string(" ") + f->name;
    *err = path + ": '" + stem + "' is not a shader family (the file's name says whose cases it holds):" + names;
    return false;
  }
  std::ifstream f(path, std::ios::binary);
  const std::string text = f ? std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()) : "";
  if (!f || f.bad()) {
    *err = path + ": cannot read: " + std::strerror(errno);
    return false;
  }
  std::unique_ptr<HardCases> hc(new HardCases);
  if (!parse_hard_cases(*fam, path, text, hc.get(), err)) return false;
  std::lock_guard<std::mutex> lock(g_cases_mutex);
  case_cache()[fam->name] = std::move(hc);
  return true;
}

void fill_record_grid(const char *family, InputSet set, int w, int h, int slots, Rng &r,
                      const std::function<void(ts_vec4f *rec)> &random_pixel, FamilyInputs *out) {
  const HardCases *cases = nullptr;
  if (set == InputSet::Hard) {
    std::string err;
    const ShaderFamily *fam = find_family(family);
    if (!fam) err = std::string("no shader family '") + family + "'";
    if (!fam || !family_hard_cases(*fam, &cases, &err)) {
      fprintf(stderr, "tiershade: %s\n", err.c_str());
      exit(1);
    }
  }
  out->resize(w, h, slots);
  out->case_names.clear();
  std::vector<ts_vec4f> rec(static_cast<size_t>(slots));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      // Every pixel draws a random record first, so that the generator's sequence (and with it
      // the textures drawn after the grid) does not depend on which slots a case sets.
      random_pixel(rec.data());
      if (cases) {
        const size_t i = static_cast<size_t>(y) * w + x;
        cases->apply(i, &r, rec.data());
        out->case_names.push_back(cases->pixel_name(i));
      }
      for (int k = 0; k < slots; ++k) out->set_slot(x, y, k, rec[k]);
    }
  }
}

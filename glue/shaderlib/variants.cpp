// tiershade shaderlib: variant declarations, skip rules and enumeration (see variants.h).
#include "shaderlib/variants.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "base/enum_names.h"
#include "shaderlib/assembler.h"

static const EnumName<Tier> kTierNames[] = {{Tier::PS20, "ps20"}, {Tier::PS2B, "ps2b"}, {Tier::SM3, "sm3"}};

const char *tier_name(Tier t) { return enum_name(kTierNames, t); }
bool parse_tier(const std::string &s, Tier *out) { return enum_parse(kTierNames, s, out); }
std::vector<Tier> all_tiers() { return {Tier::PS20, Tier::PS2B, Tier::SM3}; }

int Variant::value(const std::string &combo, int fallback) const {
  for (const auto &kv : values)
    if (kv.first == combo) return kv.second;
  return fallback;
}
std::string Variant::name() const {
  std::string s = tier_name(tier);
  s += ":";
  for (size_t i = 0; i < values.size(); ++i) {
    if (i) s += ",";
    s += values[i].first + "=" + std::to_string(values[i].second);
  }
  return s;
}

// ---- expression evaluator: precedence climbing over ints ----
namespace {
// The binary operators by precedence level, loosest first; within a level a two-character
// token comes before its one-character prefix ("<=" before "<"). Operands and results are
// long long, so that checked() sees an overflow before it is narrowed back to int.
using Wide = long long;
struct BinOp {
  const char *token;
  Wide (*apply)(Wide a, Wide b);
};
const BinOp kLevels[][6] = {
    {{"||", [](Wide a, Wide b) -> Wide { return a || b; }}},
    {{"&&", [](Wide a, Wide b) -> Wide { return a && b; }}},
    {{"==", [](Wide a, Wide b) -> Wide { return a == b; }}, {"!=", [](Wide a, Wide b) -> Wide { return a != b; }},
     {"<=", [](Wide a, Wide b) -> Wide { return a <= b; }}, {">=", [](Wide a, Wide b) -> Wide { return a >= b; }},
     {"<", [](Wide a, Wide b) -> Wide { return a < b; }}, {">", [](Wide a, Wide b) -> Wide { return a > b; }}},
    {{"+", [](Wide a, Wide b) -> Wide { return a + b; }}, {"-", [](Wide a, Wide b) -> Wide { return a - b; }}},
    {{"*", [](Wide a, Wide b) -> Wide { return a * b; }}},
};
constexpr size_t kLevelCount = sizeof kLevels / sizeof kLevels[0];

struct Parser {
  const std::string &s;
  const std::map<std::string, int> &vars;
  size_t p = 0;
  std::string err;
  void ws() {
    while (p < s.size() && std::isspace(static_cast<unsigned char>(s[p]))) ++p;
  }
  bool eat(const char *tok) {
    ws();
    const size_t n = std::char_traits<char>::length(tok);
    if (s.compare(p, n, tok) == 0) {
      p += n;
      return true;
    }
    return false;
  }
  bool primary(int *v) {
    ws();
    if (eat("(")) {
      if (!expression(v)) return false;
      if (!eat(")")) return fail("')' expected");
      return true;
    }
    if (eat("!")) {
      int x;
      if (!primary(&x)) return false;
      *v = !x;
      return true;
    }
    if (eat("-")) {
      int x;
      if (!primary(&x)) return false;
      return checked(-static_cast<long long>(x), v);
    }
    if (p < s.size() && std::isdigit(static_cast<unsigned char>(s[p]))) {
      long x = 0;
      while (p < s.size() && std::isdigit(static_cast<unsigned char>(s[p]))) {
        x = x * 10 + (s[p++] - '0');
        if (x > 1000000) return fail("number too large");
      }
      *v = static_cast<int>(x);
      return true;
    }
    if (p < s.size() && (std::isalpha(static_cast<unsigned char>(s[p])) || s[p] == '_')) {
      size_t b = p;
      while (p < s.size() && (std::isalnum(static_cast<unsigned char>(s[p])) || s[p] == '_')) ++p;
      const std::string id = s.substr(b, p - b);
      auto it = vars.find(id);
      if (it == vars.end()) return fail("unknown combo '" + id + "'");
      *v = it->second;
      return true;
    }
    return fail("operand expected");
  }
  // Results are kept within +-1e9 so that no int operation can overflow.
  bool checked(long long x, int *v) {
    if (x > 1000000000LL || x < -1000000000LL) return fail("value out of range (|x| > 1e9)");
    *v = static_cast<int>(x);
    return true;
  }
  // One binary level after another, from `level` down to the primaries (kLevels), each
  // left-associative.
  bool binary(size_t level, int *v) {
    if (level == kLevelCount) return primary(v);
    if (!binary(level + 1, v)) return false;
    for (;;) {
      const BinOp *op = nullptr;
      for (const BinOp &o : kLevels[level])
        if (o.token && eat(o.token)) {
          op = &o;
          break;
        }
      if (!op) return true;
      int r;
      if (!binary(level + 1, &r)) return false;
      if (!checked(op->apply(*v, r), v)) return false;
    }
  }
  bool expression(int *v) { return binary(0, v); }
  bool fail(const std::string &m) {
    if (err.empty()) err = m + " at column " + std::to_string(p + 1);
    return false;
  }
};

bool tier_in(Tier t, const std::vector<Tier> &v) { return v.empty() || std::find(v.begin(), v.end(), t) != v.end(); }
}  // namespace

bool eval_expr(const std::string &expr, const std::map<std::string, int> &vars, int *out, std::string *err) {
  Parser ps{expr, vars, 0, std::string()};
  int v = 0;
  if (!ps.expression(&v)) {
    *err = ps.err;
    return false;
  }
  ps.ws();
  if (ps.p != expr.size()) {
    *err = "unexpected '" + expr.substr(ps.p) + "' at column " + std::to_string(ps.p + 1);
    return false;
  }
  *out = v;
  return true;
}

bool parse_shader_decl(const std::string &file, const std::string &text, ShaderDecl *out, std::string *err) {
  *out = ShaderDecl();
  out->file = file;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  auto fail = [&](const std::string &m) {
    *err = file + ":" + std::to_string(lineno) + ": " + m;
    return false;
  };
  auto parse_tiers = [&](std::istringstream &ls, std::vector<Tier> *tiers) {
    std::string t;
    while (ls >> t) {
      Tier tier;
      if (!parse_tier(t, &tier)) return fail("unknown tier '" + t + "' (ps20, ps2b, sm3)");
      tiers->push_back(tier);
    }
    return true;
  };
  while (std::getline(in, line)) {
    ++lineno;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    const size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 5, "skip:") == 0) line.insert(first + 4, " ");
    std::istringstream ls(line);
    std::string key;
    if (!(ls >> key)) continue;
    if (key == "shader") {
      if (!(ls >> out->name)) return fail("shader name expected");
    } else if (key == "fragment") {
      if (!(ls >> out->fragment)) return fail("fragment entry file expected");
    } else if (key == "vertex") {
      if (!(ls >> out->vertex)) return fail("vertex entry file expected");
    } else if (key == "tiers") {
      if (!parse_tiers(ls, &out->tiers)) return false;
    } else if (key == "targets") {
      std::string t;
      while (ls >> t) {
        Target target;
        if (!parse_target(t, &target)) return fail("unknown target '" + t + "' (essl100, essl300, glsl330)");
        out->targets.push_back(t);
      }
      if (out->targets.empty()) return fail("'targets TARGET...' expected");
    } else if (key == "static" || key == "dynamic") {
      Combo c;
      c.dynamic = key == "dynamic";
      std::string range;
      if (!(ls >> c.name >> range)) return fail("'" + key + " NAME MIN..MAX [tiers]' expected");
      const size_t dots = range.find("..");
      if (dots == std::string::npos) return fail("range '" + range + "' is not MIN..MAX");
      try {
        size_t used = 0;
        c.min = std::stoi(range.substr(0, dots), &used);
        if (used != dots) return fail("range '" + range + "' is not MIN..MAX");
        c.max = std::stoi(range.substr(dots + 2), &used);
        if (used != range.size() - dots - 2) return fail("range '" + range + "' is not MIN..MAX");
      } catch (...) {
        return fail("range '" + range + "' is not MIN..MAX");
      }
      if (c.min > c.max || c.max - c.min > 64) return fail("range '" + range + "' is empty or too large");
      if (!parse_tiers(ls, &c.tiers)) return false;
      for (const auto &o : out->combos)
        if (o.name == c.name) return fail("combo '" + c.name + "' declared twice");
      out->combos.push_back(c);
    } else if (key == "skip") {
      SkipRule r;
      r.line = lineno;
      std::string rest;
      std::getline(ls, rest);
      const size_t colon = rest.find(':');
      if (colon == std::string::npos) return fail("'skip [tiers]: EXPR' expected");
      std::istringstream ts(rest.substr(0, colon));
      if (!parse_tiers(ts, &r.tiers)) return false;
      r.expr = rest.substr(colon + 1);
      std::map<std::string, int> vars;
      for (const auto &c : out->combos) vars[c.name] = c.min;
      int v;
      std::string e;
      if (!eval_expr(r.expr, vars, &v, &e)) return fail("skip rule: " + e);
      out->skips.push_back(r);
    } else {
      return fail("unknown key '" + key + "'");
    }
  }
  lineno = 0;
  if (out->name.empty()) return fail("no 'shader' line");
  if (out->fragment.empty()) return fail("no 'fragment' line");
  if (out->vertex.empty()) return fail("no 'vertex' line");
  if (out->tiers.empty()) out->tiers = all_tiers();
  return true;
}

bool load_shader_decls(std::vector<ShaderDecl> *out, std::string *err) {
  out->clear();
  for (const auto &f : shader_library_files()) {
    if (f.size() < 9 || f.compare(f.size() - 9, 9, ".variants") != 0) continue;
    std::string text;
    if (!shader_library_read(f, &text)) {
      *err = "shaders/" + f + ": cannot read";
      return false;
    }
    ShaderDecl d;
    if (!parse_shader_decl("shaders/" + f, text, &d, err)) return false;
    out->push_back(d);
  }
  std::sort(out->begin(), out->end(), [](const ShaderDecl &a, const ShaderDecl &b) { return a.name < b.name; });
  return true;
}

std::vector<Variant> enumerate_variants(const ShaderDecl &s, const std::vector<Tier> &tiers, std::string *err) {
  std::vector<Variant> result;
  for (Tier t : tiers) {
    if (!tier_in(t, s.tiers)) continue;
    // Static combos outside, dynamic combos inside (they vary fastest), each in declaration order.
    std::vector<const Combo *> active;
    for (int dyn = 0; dyn < 2; ++dyn)
      for (const auto &c : s.combos)
        if (tier_in(t, c.tiers) && c.dynamic == (dyn == 1)) active.push_back(&c);
    std::vector<int> v;
    for (const auto *c : active) v.push_back(c->min);
    for (;;) {
      Variant var;
      var.shader = &s;
      var.tier = t;
      std::map<std::string, int> vars;
      for (const auto &c : s.combos) vars[c.name] = 0;  // absent combos read as 0 in skip rules
      for (size_t i = 0; i < active.size(); ++i) {
        var.values.push_back({active[i]->name, v[i]});
        vars[active[i]->name] = v[i];
      }
      bool skip = false;
      for (const auto &r : s.skips) {
        if (!tier_in(t, r.tiers)) continue;
        int x = 0;
        if (!eval_expr(r.expr, vars, &x, err)) {
          *err = s.file + ":" + std::to_string(r.line) + ": " + *err;
          return {};
        }
        if (x) skip = true;
      }
      if (!skip) result.push_back(var);
      // odometer: dynamic combos innermost (last declared varies fastest)
      int i = static_cast<int>(active.size()) - 1;
      while (i >= 0 && v[i] == active[i]->max) {
        v[i] = active[i]->min;
        --i;
      }
      if (i < 0) break;
      ++v[i];
    }
  }
  return result;
}

bool find_variant(const std::vector<ShaderDecl> &decls, const std::string &shader, const std::string &variant,
                  Variant *out, std::string *err) {
  for (const auto &d : decls) {
    if (d.name != shader) continue;
    auto vars = enumerate_variants(d, all_tiers(), err);
    for (size_t i = 0; i < vars.size(); ++i) {
      if (vars[i].name() == variant || std::to_string(i) == variant) {
        *out = vars[i];
        return true;
      }
    }
    // A short name: "TIER:NAME=V,..." listing some combos; the others take their minimum.
    const size_t colon = variant.find(':');
    Tier tier;
    if (colon != std::string::npos && parse_tier(variant.substr(0, colon), &tier)) {
      std::map<std::string, int> given;
      std::istringstream in(variant.substr(colon + 1));
      std::string kv;
      bool ok = true;
      while (std::getline(in, kv, ',')) {
        const size_t eq = kv.find('=');
        if (eq == std::string::npos) {
          ok = false;
          break;
        }
        try {
          given[kv.substr(0, eq)] = std::stoi(kv.substr(eq + 1));
        } catch (...) {
          ok = false;
          break;
        }
      }
      for (size_t i = 0; ok && i < vars.size(); ++i) {
        if (vars[i].tier != tier) continue;
        bool match = true;
        for (const auto &c : d.combos) {
          auto it = given.find(c.name);
          const int want = it != given.end() ? it->second : c.min;
          if (vars[i].value(c.name, c.min) != want) match = false;
        }
        for (const auto &g : given) {
          bool known = false;
          for (const auto &c : d.combos) known = known || c.name == g.first;
          if (!known) match = false;
        }
        if (match) {
          *out = vars[i];
          return true;
        }
      }
    }
    *err = "shader '" + shader + "' has no variant '" + variant + "' (see: tiershade variants --list --shader " +
        shader + ")";
    return false;
  }
  *err = "no shader named '" + shader + "'";
  return false;
}

bool ShaderDecl::has_target(const char *target) const {
  return targets.empty() || std::find(targets.begin(), targets.end(), target) != targets.end();
}

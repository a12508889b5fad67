// tiershade budget: the Mesa NIR cross-check counter (budget_count_nir_text in budget.h):
// scalar ALU and texture instructions of the fragment NIR that Mesa prints under ST_DEBUG=nir
// (captured by nir_capture.cpp; docs/budget_model.md, "Cross-check against Mesa's NIR").
#include "budget/budget.h"
#include "budget/trim.h"

#include <cctype>
#include <cstdlib>
#include <set>
#include <sstream>
#include <vector>

// Mesa 22.x prints SSA definitions as
//     vec1 32 ssa_9 = fmul ssa_8.x, ssa_0
//     vec4 32 ssa_8 = (float32)tex ssa_7 (coord), 1 (texture), 1 (sampler)
// and newer Mesa as "con 32x4 %8 = ..." or "32 %9 = ...".  We accept both.
namespace {

using budget::trim;

// Splits a NIR line into blank-separated tokens; a "quoted string" is one token and ';'
// starts a comment.
std::vector<std::string> tokenize(const std::string &line) {
  std::vector<std::string> toks;
  size_t i = 0, n = line.size();
  while (i < n) {
    while (i < n && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i >= n) break;
    if (line[i] == ';') break;  // comment
    std::string tok;
    if (line[i] == '"') {
      tok += line[i++];
      while (i < n && line[i] != '"') {
        if (line[i] == '\\' && i + 1 < n) tok += line[i++];
        tok += line[i++];
      }
      if (i < n) tok += line[i++];
    } else {
      while (i < n && !std::isspace(static_cast<unsigned char>(line[i]))) tok += line[i++];
    }
    toks.push_back(tok);
  }
  return toks;
}

struct NirSection {
  std::string sha1;
  std::vector<std::string> lines;
};

// Width of a NIR destination from the tokens before "=" (vecN, or BITSxN).
int nir_dest_width(const std::vector<std::string> &lhs) {
  for (const std::string &t : lhs) {
    if (t.rfind("vec", 0) == 0 && t.size() > 3) return std::atoi(t.c_str() + 3);
    size_t x = t.find('x');
    if (x != std::string::npos && x > 0 && std::isdigit(static_cast<unsigned char>(t[0])))
      return std::atoi(t.c_str() + x + 1);
  }
  return 1;
}

}  // namespace

bool budget_count_nir_text(const std::string &nir_dump, int *scalar_alu, int *tex, std::string *err) {
  std::string dummy;
  std::string &e = err ? *err : dummy;
  e.clear();
  if (!scalar_alu || !tex) {
    e = "budget_count_nir_text: null output";
    return false;
  }
  *scalar_alu = 0;
  *tex = 0;

  // Split the dump into shader sections and keep the fragment ones.
  std::vector<NirSection> frags;
  NirSection *cur = nullptr;
  std::istringstream in(nir_dump);
  std::string line;
  while (std::getline(in, line)) {
    std::string t = trim(line);
    if (t.rfind("shader: MESA_SHADER_", 0) == 0) {
      if (t == "shader: MESA_SHADER_FRAGMENT") {
        frags.push_back(NirSection());
        cur = &frags.back();
      } else
        cur = nullptr;
      continue;
    }
    if (t.rfind("NIR before handing off", 0) == 0) {
      cur = nullptr;
      continue;
    }
    if (!cur) continue;
    if (t.rfind("source_sha1:", 0) == 0) cur->sha1 = t;
    cur->lines.push_back(t);
  }
  if (frags.empty()) {
    e = "no \"shader: MESA_SHADER_FRAGMENT\" section in the NIR dump (was ST_DEBUG=nir set?)";
    return false;
  }
  for (const NirSection &s : frags) {
    if (s.sha1 != frags.front().sha1) {
      e = "the NIR dump holds " + std::to_string(frags.size()) +
          " different fragment shaders; pass the dump of one shader";
      return false;
    }
  }

  static const std::set<std::string> kFree = {
      "mov",       "vec2",        "vec3",         "vec4",       "vec5",      "vec8", "vec16",     "load_const",
      "deref_var", "deref_array", "deref_struct", "deref_cast", "intrinsic", "phi",  "undefined", "ssa_undef"};
  static const std::set<std::string> kTex = {"tex", "txb", "txl", "txd", "txf", "txf_ms", "tg4"};
  int alu = 0, tx = 0;
  bool saw_impl = false;
  for (const std::string &t : frags.front().lines) {
    if (t.rfind("impl ", 0) == 0) saw_impl = true;
    size_t eq = t.find(" = ");
    if (eq == std::string::npos) continue;
    std::vector<std::string> lhs = tokenize(t.substr(0, eq));
    if (lhs.empty()) continue;
    const std::string &dst = lhs.back();
    bool is_dest = dst.rfind("ssa_", 0) == 0 ||
        (dst.size() > 1 && dst[0] == '%' && std::isdigit(static_cast<unsigned char>(dst[1])));
    if (!is_dest || lhs.size() < 2) continue;  // e.g. "intrinsic store_deref (...) (wrmask=...)"
    std::vector<std::string> rhs = tokenize(t.substr(eq + 3));
    if (rhs.empty()) continue;
    std::string op = rhs[0];
    if (!op.empty() && op[0] == '(') {  // "(float32)tex"
      size_t close = op.find(')');
      op = close == std::string::npos ? op : op.substr(close + 1);
    }
    size_t dot = op.find('.');  // saturate/exact suffixes in some Mesa versions
    if (dot != std::string::npos) op = op.substr(0, dot);
    if (op.empty()) continue;
    if (kTex.count(op)) {
      ++tx;
      continue;
    }
    if (op.rfind("tx", 0) == 0 || op == "lod" || op == "query_levels" || op == "texture_samples" ||
        op == "samples_identical" || op == "fragment_fetch" || op == "fragment_mask_fetch")
      continue;  // texture queries: not counted
    if (kFree.count(op) || op[0] == '@') continue;  // '@name': intrinsic in newer Mesa
    alu += nir_dest_width(lhs);
  }
  if (!saw_impl) {
    e = "the fragment section of the NIR dump has no \"impl\" body";
    return false;
  }
  *scalar_alu = alu;
  *tex = tx;
  return true;
}

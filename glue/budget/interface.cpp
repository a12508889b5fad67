// tiershade budget: the declared interface of a program from its source (see interface.h).
// The SPIR-V words are read directly (the binary layout: SPIR-V spec section 2.3, a 5-word header,
// then instructions whose first word is word count << 16 | opcode).
#include "budget/interface.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "budget/glsl_to_spirv.h"

namespace {

using spv::Op;

struct Type {
  Op op = Op::OpNop;
  std::vector<uint32_t> w;  // the operands after the result id
};

struct Var {
  uint32_t id = 0, pointee = 0;  // the variable and the type it points to
  spv::StorageClass storage = spv::StorageClass::Input;
  bool used = false;
  bool whole = false;  // used as a whole (loaded or passed without an index)
  long max_index = -1;  // largest constant first index
  bool dynamic = false;  // indexed with a non-constant
};

struct Reader {
  std::map<uint32_t, Type> types;
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, long> int_consts;  // OpConstant of an integer type
  std::map<uint32_t, Var> vars;  // global variables
  std::set<uint32_t> builtins;  // ids decorated BuiltIn (or members of such blocks)
  std::map<uint32_t, uint32_t> chain_root;  // access chain result -> variable
  std::map<uint32_t, std::vector<uint32_t>> calls;  // function -> functions it calls
  std::map<uint32_t, std::vector<std::vector<uint32_t>>> bodies;  // function -> its instructions
  uint32_t entry = 0;

  static std::string str(const uint32_t *w, size_t n) {
    std::string s;
    for (size_t i = 0; i < n; ++i)
      for (int b = 0; b < 4; ++b) {
        const char c = static_cast<char>((w[i] >> (8 * b)) & 0xff);
        if (!c) return s;
        s += c;
      }
    return s;
  }

  bool read(const std::vector<uint32_t> &words, std::string *err) {
    if (words.size() < 5 || words[0] != spv::MagicNumber) {
      *err = "not a SPIR-V module";
      return false;
    }
    uint32_t func = 0;
    for (size_t i = 5; i < words.size();) {
      const uint32_t n = words[i] >> 16;
      const Op op = static_cast<Op>(words[i] & 0xffff);
      if (n == 0 || i + n > words.size()) {
        *err = "truncated SPIR-V instruction at word " + std::to_string(i);
        return false;
      }
      const uint32_t *w = &words[i + 1];
      const size_t m = n - 1;
      switch (op) {
        case Op::OpName:
          names[w[0]] = str(w + 1, m - 1);
          break;
        case Op::OpEntryPoint:
          entry = w[1];
          break;
        case Op::OpDecorate:
          if (m >= 2 && w[1] == static_cast<uint32_t>(spv::Decoration::BuiltIn)) builtins.insert(w[0]);
          break;
        case Op::OpMemberDecorate:
          if (m >= 3 && w[2] == static_cast<uint32_t>(spv::Decoration::BuiltIn)) builtins.insert(w[0]);
          break;
        case Op::OpTypeBool: case Op::OpTypeInt: case Op::OpTypeFloat: case Op::OpTypeVector:
        case Op::OpTypeMatrix: case Op::OpTypeImage: case Op::OpTypeSampledImage: case Op::OpTypeArray:
        case Op::OpTypeStruct: case Op::OpTypePointer: case Op::OpTypeSampler:
          types[w[0]] = {op, std::vector<uint32_t>(w + 1, w + m)};
          break;
        case Op::OpConstant:
          if (m >= 3 && types.count(w[0]) && types[w[0]].op == Op::OpTypeInt)
            int_consts[w[1]] = types[w[0]].w[1] ? static_cast<long>(static_cast<int32_t>(w[2])) : static_cast<long>(w[2]);
          break;
        case Op::OpVariable:
          if (!func) {
            Var v;
            v.id = w[1];
            v.storage = static_cast<spv::StorageClass>(w[2]);
            auto t = types.find(w[0]);
            if (t != types.end() && t->second.op == Op::OpTypePointer) v.pointee = t->second.w[1];
            vars[v.id] = v;
          }
          break;
        case Op::OpFunction:
          func = w[1];
          bodies[func];
          break;
        case Op::OpFunctionEnd:
          func = 0;
          break;
        default:
          break;
      }
      if (func && op != Op::OpFunction) {
        std::vector<uint32_t> inst(words.begin() + static_cast<long>(i), words.begin() + static_cast<long>(i + n));
        if (op == Op::OpFunctionCall) calls[func].push_back(w[2]);
        bodies[func].push_back(std::move(inst));
      }
      i += n;
    }
    if (!entry) {
      *err = "SPIR-V module without an entry point";
      return false;
    }
    return true;
  }

  // A pointer operand: the global variable it reaches (through access chains), or 0.
  uint32_t root(uint32_t id) const {
    if (vars.count(id)) return id;
    auto c = chain_root.find(id);
    return c == chain_root.end() ? 0 : c->second;
  }

  // Marks the uses in every function reachable from the entry point.
  void mark_uses() {
    std::set<uint32_t> seen;
    std::vector<uint32_t> todo = {entry};
    while (!todo.empty()) {
      const uint32_t f = todo.back();
      todo.pop_back();
      if (!seen.insert(f).second) continue;
      for (uint32_t c : calls[f]) todo.push_back(c);
    }
    // Access chains first (in order: a chain may build on an earlier one), then the uses.
    for (uint32_t f : seen)
      for (const auto &inst : bodies[f]) {
        const Op op = static_cast<Op>(inst[0] & 0xffff);
        if ((op != Op::OpAccessChain && op != Op::OpInBoundsAccessChain) || inst.size() < 4) continue;
        const uint32_t base = inst[3], r = root(base);
        if (!r) continue;
        chain_root[inst[2]] = r;
        Var &v = vars[r];
        v.used = true;
        if (base != r) continue;  // a chain on a chain: its first index was seen on the inner one
        if (inst.size() < 5) {
          v.whole = true;
          continue;
        }
        auto k = int_consts.find(inst[4]);
        if (k == int_consts.end())
          v.dynamic = true;
        else
          v.max_index = std::max(v.max_index, k->second);
      }
    for (uint32_t f : seen)
      for (const auto &inst : bodies[f]) {
        const Op op = static_cast<Op>(inst[0] & 0xffff);
        std::vector<uint32_t> ptrs;
        if (op == Op::OpLoad && inst.size() >= 4) ptrs = {inst[3]};
        if (op == Op::OpStore && inst.size() >= 3) ptrs = {inst[1], inst[2]};
        if (op == Op::OpCopyMemory && inst.size() >= 3) ptrs = {inst[1], inst[2]};
        if (op == Op::OpFunctionCall) ptrs.assign(inst.begin() + 4, inst.end());
        for (uint32_t p : ptrs) {
          if (!vars.count(p)) continue;  // chains were marked above
          vars[p].used = true;
          vars[p].whole = true;
        }
      }
  }

  // GLSL name of a (non-array) type id; registers per element in *regs.
  std::string glsl_type(uint32_t id, int *regs) const {
    *regs = 1;
    auto t = types.find(id);
    if (t == types.end()) return "?";
    const Type &ty = t->second;
    switch (ty.op) {
      case Op::OpTypeBool:
        return "bool";
      case Op::OpTypeInt:
        return ty.w[1] ? "int" : "uint";
      case Op::OpTypeFloat:
        return "float";
      case Op::OpTypeVector: {
        int r;
        const std::string c = glsl_type(ty.w[0], &r);
        const std::string n = std::to_string(ty.w[1]);
        return (c == "float" ? "vec" : c == "int" ? "ivec" : c == "uint" ? "uvec" : "bvec") + n;
      }
      case Op::OpTypeMatrix: {
        auto col = types.find(ty.w[0]);
        const uint32_t rows = col != types.end() ? col->second.w[1] : 0;
        *regs = static_cast<int>(ty.w[1]);
        return rows == ty.w[1] ? "mat" + std::to_string(rows) : "mat" + std::to_string(ty.w[1]) + "x" + std::to_string(rows);
      }
      case Op::OpTypeSampledImage:
        return glsl_type(ty.w[0], regs);
      case Op::OpTypeImage: {
        const auto dim = static_cast<spv::Dim>(ty.w[1]);
        const std::string base = dim == spv::Dim::Dim2D ? "sampler2D" : dim == spv::Dim::Dim3D ? "sampler3D"
            : dim == spv::Dim::Cube ? "samplerCube" : "sampler?";
        return base + (ty.w[3] ? "Array" : "") + (ty.w[2] == 1 ? "Shadow" : "");
      }
      default:
        return "?";
    }
  }

  bool collect(bool vertex, ProgramInterface *out, std::string *err) const {
    for (const auto &kv : vars) {
      const Var &v = kv.second;
      if (!v.used || builtins.count(v.id)) continue;
      const bool input = v.storage == spv::StorageClass::Input;
      const bool uniform = v.storage == spv::StorageClass::UniformConstant || v.storage == spv::StorageClass::Uniform;
      if (!(input && vertex) && !uniform) continue;
      if (builtins.count(v.pointee)) continue;
      auto nm = names.find(v.id);
      if (nm == names.end() || nm->second.empty() || nm->second.compare(0, 3, "gl_") == 0) continue;
      InterfaceVar iv;
      iv.name = nm->second;
      uint32_t elem = v.pointee;
      auto t = types.find(elem);
      if (t != types.end() && t->second.op == Op::OpTypeArray) {
        auto len = int_consts.find(t->second.w[1]);
        if (len == int_consts.end()) {
          *err = "array '" + iv.name + "' has no constant length";
          return false;
        }
        iv.array_size = static_cast<int>(len->second);
        iv.used_size = v.whole || v.dynamic ? iv.array_size : static_cast<int>(v.max_index + 1);
        elem = t->second.w[0];
      }
      if (types.count(elem) && types.at(elem).op == Op::OpTypeStruct) {
        *err = "uniform '" + iv.name + "' is a struct or block (tiershade's shaders declare none)";
        return false;
      }
      iv.type = glsl_type(elem, &iv.registers_per_element);
      (vertex ? iv.vertex : iv.fragment) = true;
      const bool sampler = iv.type.compare(0, 7, "sampler") == 0;
      (input ? out->attributes : sampler ? out->samplers : out->uniforms).push_back(iv);
    }
    return true;
  }
};

void sort_by_name(std::vector<InterfaceVar> *v) {
  std::sort(v->begin(), v->end(), [](const InterfaceVar &a, const InterfaceVar &b) { return a.name < b.name; });
}

bool merge(std::vector<InterfaceVar> *into, const std::vector<InterfaceVar> &from, std::string *err) {
  for (const InterfaceVar &f : from) {
    auto it = std::find_if(into->begin(), into->end(), [&](const InterfaceVar &x) { return x.name == f.name; });
    if (it == into->end()) {
      into->push_back(f);
      continue;
    }
    if (it->type != f.type || it->array_size != f.array_size) {
      *err = "uniform '" + f.name + "' is declared differently in the two stages";
      return false;
    }
    it->used_size = std::max(it->used_size, f.used_size);
    it->vertex = it->vertex || f.vertex;
    it->fragment = it->fragment || f.fragment;
  }
  sort_by_name(into);
  return true;
}

}  // namespace

bool reflect_stage(const std::string &glsl330_source, bool vertex, ProgramInterface *out, std::string *err) {
  *out = ProgramInterface();
  std::string prepared;
  std::vector<uint32_t> words;
  if (!budget::prepare_source(glsl330_source, &prepared, err) ||
      !budget::compile_glsl_stage(prepared, vertex, true, &words, err))
    return false;
  Reader r;
  if (!r.read(words, err)) return false;
  r.mark_uses();
  if (!r.collect(vertex, out, err)) return false;
  sort_by_name(&out->attributes);
  sort_by_name(&out->uniforms);
  sort_by_name(&out->samplers);
  return true;
}

bool reflect_fragment_unrolled(const std::string &glsl330_source, ProgramInterface *out, std::string *err) {
  *out = ProgramInterface();
  std::string prepared;
  std::vector<uint32_t> words, optimized;
  if (!budget::prepare_source(glsl330_source, &prepared, err) ||
      !budget::compile_glsl_stage(prepared, false, true, &words, err))
    return false;
  // Every loop asks to be unrolled (OpLoopMerge's loop control: Unroll set, DontUnroll cleared;
  // SPIR-V spec 3.23), so that spirv-opt's loop unroller unrolls each loop whose trip count is a
  // constant, as fxc did for ps_2_0 / ps_2_b, which cannot index constants with a register.
  for (size_t i = 5; i < words.size();) {
    const uint32_t n = words[i] >> 16;
    if (n == 0) break;
    if (static_cast<Op>(words[i] & 0xffff) == Op::OpLoopMerge && n >= 4 && i + 3 < words.size()) {
      words[i + 3] |= static_cast<uint32_t>(spv::LoopControlMask::Unroll);
      words[i + 3] &= ~static_cast<uint32_t>(spv::LoopControlMask::DontUnroll);
    }
    i += n;
  }
  if (!budget::optimize_spirv(words, &optimized, err)) return false;
  Reader r;
  if (!r.read(optimized, err)) return false;
  r.mark_uses();
  return r.collect(false, out, err);
}

bool reflect_program(const std::string &vertex330, const std::string &fragment330, ProgramInterface *out,
                     std::string *err) {
  ProgramInterface vs, fs;
  if (!reflect_stage(vertex330, true, &vs, err)) {
    *err = "vertex stage: " + *err;
    return false;
  }
  if (!reflect_stage(fragment330, false, &fs, err)) {
    *err = "fragment stage: " + *err;
    return false;
  }
  *out = vs;
  return merge(&out->uniforms, fs.uniforms, err) && merge(&out->samplers, fs.samplers, err);
}

int fragment_constant_registers(const ProgramInterface &p) {
  int n = 0;
  for (const auto &u : p.uniforms)
    if (u.fragment) n += u.registers(true);
  return n;
}

int fragment_uniform_vectors(const ProgramInterface &p) {
  int n = 0;
  for (const auto &u : p.uniforms)
    if (u.fragment) n += u.registers(false);
  return n;
}

bool preprocessed_identifiers(const std::string &source, bool vertex, std::set<std::string> *out, std::string *err) {
  std::string text;
  if (!budget::preprocess_glsl(source, vertex, &text, err)) return false;
  out->clear();
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (std::isalpha(c) || c == '_') {
      size_t j = i;
      while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
      out->insert(text.substr(i, j - i));
      i = j;
    } else if (std::isdigit(c)) {  // a number with its suffix (1.0e5, 2u): not an identifier
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
    } else {
      ++i;
    }
  }
  return true;
}

// tiershade budget: the optimised SPIR-V module as the slot counter sees it (functions, blocks,
// instructions with typed operands, types, constants), read from the binary words with
// SPIRV-Tools' spvBinaryParse. Internal to glue/budget/.
#pragma once

#include <spirv/unified1/spirv.hpp11>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace budget {

using Id = uint32_t;  // a SPIR-V result id; 0 means "none"
using Op = spv::Op;

// One operand after the result id and the result type (the order of the binary).
struct Operand {
  Id id = 0;  // the id operand (IdRef, IdScope, IdMemorySemantics), 0 for a literal
  std::vector<uint32_t> words;  // the literal's words (numbers, enums, masks, strings); empty for an id
  bool is_id() const { return id != 0; }
  uint32_t literal() const { return words.empty() ? 0u : words[0]; }
  bool literal_nonzero() const {
    for (uint32_t w : words)
      if (w != 0) return true;
    return false;
  }
};

struct Inst {
  Op op = Op::OpNop;
  Id result = 0;
  Id type = 0;  // result type, 0 if none
  std::vector<Operand> args;  // operands after the result type
};

struct Block {
  Id label = 0;
  std::vector<Inst> insts;
  std::vector<Id> succ;
  Id merge = 0;  // from OpSelectionMerge / OpLoopMerge
  Id cont = 0;  // continue target (loop headers only)
  bool loop_header = false;
};

struct Function {
  Id id = 0;
  std::vector<Block> blocks;
};

struct TypeInfo {
  enum Kind { Scalar, Vector, Matrix, Other } kind = Other;
  int comps = 1;  // vector width, or rows for a matrix
  int cols = 1;  // matrix columns
};

struct ConstInfo {
  Id type = 0;  // type id
  bool known = false;  // numeric values available
  std::vector<double> values;  // flattened components
};

struct Module {
  std::map<Id, TypeInfo> types;
  std::map<Id, ConstInfo> consts;  // OpConstant*, OpSpecConstant*, OpUndef
  std::map<Id, uint32_t> var_storage;  // OpVariable id -> spv::StorageClass
  std::map<Id, std::string> ext_sets;  // OpExtInstImport id -> set name
  std::vector<Function> functions;
  Id fragment_entry = 0;
};

// Fills *m from a SPIR-V binary.  False with a message when the binary does not parse or has
// no Fragment entry point.
bool read_spirv_module(const std::vector<uint32_t> &words, Module *m, std::string *err);

// "OpFAdd" for spv::OpFAdd (SPIRV-Tools' grammar names, as spirv-dis prints them).
std::string op_name(Op op);
// "Fma" for GLSLstd450Fma; empty for a number outside GLSL.std.450.
const char *glsl450_name(uint32_t inst);
// "%12" for id 12: how messages name ids.
std::string id_name(Id id);

}  // namespace budget

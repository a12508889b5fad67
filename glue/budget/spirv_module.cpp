// tiershade budget: reads the optimised SPIR-V binary into budget::Module with SPIRV-Tools'
// binary parser (spvBinaryParse), one callback per instruction: no disassembly text.
// Instruction and operand layouts: SPIR-V 1.6 specification, sections 2.3 and 3.
#include "budget/spirv_module.h"

#include <spirv-tools/libspirv.h>
#include <spirv/unified1/GLSL.std.450.h>

#include <cmath>
#include <cstring>

namespace budget {

namespace {

bool starts_with(const std::string &s, const char *prefix) { return s.rfind(prefix, 0) == 0; }

// A literal string operand: UTF-8 bytes packed little-endian into words, NUL-terminated (2.2.1).
std::string literal_string(const std::vector<uint32_t> &words) {
  std::string s;
  for (uint32_t w : words) {
    for (int b = 0; b < 4; ++b) {
      char c = static_cast<char>((w >> (8 * b)) & 0xffu);
      if (c == '\0') return s;
      s += c;
    }
  }
  return s;
}

// IEEE 754 binary16 to double, exactly (every half is a double).
double half_to_double(uint32_t h) {
  const int sign = (h >> 15) & 1, exp = (h >> 10) & 0x1f, mant = h & 0x3ff;
  double v;
  if (exp == 0)
    v = std::ldexp(static_cast<double>(mant), -24);
  else if (exp == 31)
    v = mant ? std::nan("") : HUGE_VAL;
  else
    v = std::ldexp(static_cast<double>(mant | 0x400), exp - 25);
  return sign ? -v : v;
}

// The value of an OpConstant / OpSpecConstant literal: its operand's number kind and width come
// from the result type (SPIRV-Tools fills them in from the OpTypeInt / OpTypeFloat seen before).
bool literal_value(const spv_parsed_operand_t &o, const uint32_t *w, double *out) {
  const uint64_t lo = w[0], bits = o.num_words >= 2 ? (lo | static_cast<uint64_t>(w[1]) << 32) : lo;
  const uint32_t width = o.number_bit_width;
  switch (o.number_kind) {
    case SPV_NUMBER_FLOATING:
      if (width == 32) {
        float f;
        uint32_t u = w[0];
        std::memcpy(&f, &u, 4);
        *out = f;
        return true;
      }
      if (width == 64) {
        double d;
        std::memcpy(&d, &bits, 8);
        *out = d;
        return true;
      }
      if (width == 16) {
        *out = half_to_double(w[0] & 0xffffu);
        return true;
      }
      return false;
    case SPV_NUMBER_SIGNED_INT: {
      if (width == 0 || width > 64) return false;
      const unsigned shift = 64 - width;  // sign-extend from `width` bits
      *out = static_cast<double>(static_cast<int64_t>(bits << shift) >> shift);
      return true;
    }
    case SPV_NUMBER_UNSIGNED_INT:
      if (width == 0 || width > 64) return false;
      *out = static_cast<double>(width == 64 ? bits : bits & ((uint64_t{1} << width) - 1));
      return true;
    default:
      return false;
  }
}

struct Reader {
  Module *m;
  Function *fn = nullptr;
  Block *blk = nullptr;
  std::string err;
  size_t index = 0;  // instruction number, for messages

  spv_result_t add(const spv_parsed_instruction_t &p);
};

int type_size(const Module &m, Id type) {
  auto it = m.types.find(type);
  if (it == m.types.end()) return 1;
  return it->second.comps * it->second.cols;
}

spv_result_t Reader::add(const spv_parsed_instruction_t &p) {
  ++index;
  Inst inst;
  inst.op = static_cast<Op>(p.opcode);
  inst.result = p.result_id;
  inst.type = p.type_id;
  std::vector<const spv_parsed_operand_t *> lit_ops;  // the parsed operand of each literal in args
  for (uint16_t i = 0; i < p.num_operands; ++i) {
    const spv_parsed_operand_t &o = p.operands[i];
    if (o.type == SPV_OPERAND_TYPE_RESULT_ID) continue;
    if (i == 0 && o.type == SPV_OPERAND_TYPE_TYPE_ID && p.type_id != 0) continue;  // the result type
    Operand a;
    if (o.type == SPV_OPERAND_TYPE_ID || o.type == SPV_OPERAND_TYPE_TYPE_ID || o.type == SPV_OPERAND_TYPE_SCOPE_ID ||
        o.type == SPV_OPERAND_TYPE_MEMORY_SEMANTICS_ID) {
      a.id = p.words[o.offset];
    } else {
      a.words.assign(p.words + o.offset, p.words + o.offset + o.num_words);
    }
    inst.args.push_back(a);
    lit_ops.push_back(&o);
  }
  const Op op = inst.op;
  const std::vector<Operand> &a = inst.args;

  if (op == Op::OpFunction) {
    m->functions.push_back(Function());
    fn = &m->functions.back();
    fn->id = inst.result;
    blk = nullptr;
    return SPV_SUCCESS;
  }
  if (op == Op::OpFunctionEnd) {
    fn = nullptr;
    blk = nullptr;
    return SPV_SUCCESS;
  }
  if (fn) {
    if (op == Op::OpLabel) {
      fn->blocks.push_back(Block());
      blk = &fn->blocks.back();
      blk->label = inst.result;
      return SPV_SUCCESS;
    }
    if (!blk) {
      if (op == Op::OpFunctionParameter) return SPV_SUCCESS;
      err = "SPIR-V instruction " + std::to_string(index) + " (" + op_name(inst.op) + ") is outside a block";
      return SPV_ERROR_INVALID_BINARY;
    }
    if (op == Op::OpBranch && a.size() >= 1) blk->succ.push_back(a[0].id);
    if (op == Op::OpBranchConditional && a.size() >= 3) {
      blk->succ.push_back(a[1].id);
      blk->succ.push_back(a[2].id);
    }
    if (op == Op::OpSwitch && a.size() >= 2) {
      blk->succ.push_back(a[1].id);
      for (size_t i = 3; i < a.size(); i += 2) blk->succ.push_back(a[i].id);
    }
    if (op == Op::OpSelectionMerge && !a.empty()) blk->merge = a[0].id;
    if (op == Op::OpLoopMerge && a.size() >= 2) {
      blk->merge = a[0].id;
      blk->cont = a[1].id;
      blk->loop_header = true;
    }
    if (op == Op::OpUndef) {
      ConstInfo c;
      c.type = inst.type;
      m->consts[inst.result] = c;
    }
    blk->insts.push_back(std::move(inst));
    return SPV_SUCCESS;
  }

  // Module-level declarations.
  const std::string name = op_name(inst.op);
  if (op == Op::OpEntryPoint && a.size() >= 2 &&
      a[0].literal() == static_cast<uint32_t>(spv::ExecutionModel::Fragment) && m->fragment_entry == 0) {
    m->fragment_entry = a[1].id;
  } else if (op == Op::OpExtInstImport && !a.empty()) {
    m->ext_sets[inst.result] = literal_string(a[0].words);
  } else if (op == Op::OpTypeFloat || op == Op::OpTypeInt || op == Op::OpTypeBool) {
    TypeInfo ti;
    ti.kind = TypeInfo::Scalar;
    m->types[inst.result] = ti;
  } else if (op == Op::OpTypeVector && a.size() >= 2) {
    TypeInfo ti;
    ti.kind = TypeInfo::Vector;
    ti.comps = static_cast<int>(a[1].literal());
    m->types[inst.result] = ti;
  } else if (op == Op::OpTypeMatrix && a.size() >= 2) {
    TypeInfo ti;
    ti.kind = TypeInfo::Matrix;
    ti.cols = static_cast<int>(a[1].literal());
    auto col = m->types.find(a[0].id);
    ti.comps = col != m->types.end() ? col->second.comps : 4;
    m->types[inst.result] = ti;
  } else if (starts_with(name, "OpType")) {
    m->types[inst.result] = TypeInfo();
  } else if (op == Op::OpConstant || op == Op::OpSpecConstant) {
    ConstInfo c;
    double v = 0;
    if (!a.empty() && !a[0].is_id() && literal_value(*lit_ops[0], a[0].words.data(), &v)) {
      c.known = true;
      c.values.push_back(v);
    }
    m->consts[inst.result] = c;
  } else if (op == Op::OpConstantTrue || op == Op::OpSpecConstantTrue || op == Op::OpConstantFalse ||
             op == Op::OpSpecConstantFalse) {
    ConstInfo c;
    c.known = true;
    c.values.push_back(op == Op::OpConstantTrue || op == Op::OpSpecConstantTrue ? 1.0 : 0.0);
    m->consts[inst.result] = c;
  } else if (op == Op::OpConstantComposite || op == Op::OpSpecConstantComposite) {
    ConstInfo c;
    c.known = true;
    for (const Operand &o : a) {
      auto it = m->consts.find(o.id);
      if (!o.is_id() || it == m->consts.end() || !it->second.known) {
        c.known = false;
        c.values.clear();
        break;
      }
      c.values.insert(c.values.end(), it->second.values.begin(), it->second.values.end());
    }
    m->consts[inst.result] = c;
  } else if (op == Op::OpConstantNull) {
    ConstInfo c;
    c.known = true;
    c.values.assign(static_cast<size_t>(type_size(*m, inst.type)), 0.0);
    m->consts[inst.result] = c;
  } else if (starts_with(name, "OpConstant") || starts_with(name, "OpSpecConstant") || op == Op::OpUndef) {
    m->consts[inst.result] = ConstInfo();  // a constant without usable numeric value
  } else if (op == Op::OpVariable && !a.empty()) {
    m->var_storage[inst.result] = a[0].literal();
  }
  auto c = m->consts.find(inst.result);
  if (inst.result != 0 && c != m->consts.end()) c->second.type = inst.type;
  return SPV_SUCCESS;
}

spv_result_t on_instruction(void *user, const spv_parsed_instruction_t *p) {
  return static_cast<Reader *>(user)->add(*p);
}

// One parsing context for the process: read-only after creation, so shared by all threads.
struct ParseContext {
  spv_context ctx = spvContextCreate(SPV_ENV_UNIVERSAL_1_6);
  ~ParseContext() { spvContextDestroy(ctx); }
};

}  // namespace

bool read_spirv_module(const std::vector<uint32_t> &words, Module *m, std::string *err) {
  static const ParseContext context;
  *m = Module();
  Reader r;
  r.m = m;
  spv_diagnostic diag = nullptr;
  spv_result_t rc = spvBinaryParse(context.ctx, &r, words.data(), words.size(), nullptr, on_instruction, &diag);
  if (rc != SPV_SUCCESS) {
    *err = !r.err.empty() ? r.err
                          : std::string("SPIR-V binary does not parse: ") +
            (diag && diag->error ? diag->error : "error " + std::to_string(rc));
    spvDiagnosticDestroy(diag);
    return false;
  }
  spvDiagnosticDestroy(diag);
  if (m->fragment_entry == 0) {
    *err = "no Fragment entry point in the SPIR-V";
    return false;
  }
  return true;
}

std::string op_name(Op op) { return std::string("Op") + spvOpcodeString(static_cast<uint32_t>(op)); }

const char *glsl450_name(uint32_t inst) {
#define TS_GLSL450(n) \
  { GLSLstd450##n, #n }
  static const std::map<uint32_t, const char *> kNames = {
      TS_GLSL450(Round),
      TS_GLSL450(RoundEven),
      TS_GLSL450(Trunc),
      TS_GLSL450(FAbs),
      TS_GLSL450(SAbs),
      TS_GLSL450(FSign),
      TS_GLSL450(SSign),
      TS_GLSL450(Floor),
      TS_GLSL450(Ceil),
      TS_GLSL450(Fract),
      TS_GLSL450(Radians),
      TS_GLSL450(Degrees),
      TS_GLSL450(Sin),
      TS_GLSL450(Cos),
      TS_GLSL450(Tan),
      TS_GLSL450(Asin),
      TS_GLSL450(Acos),
      TS_GLSL450(Atan),
      TS_GLSL450(Sinh),
      TS_GLSL450(Cosh),
      TS_GLSL450(Tanh),
      TS_GLSL450(Asinh),
      TS_GLSL450(Acosh),
      TS_GLSL450(Atanh),
      TS_GLSL450(Atan2),
      TS_GLSL450(Pow),
      TS_GLSL450(Exp),
      TS_GLSL450(Log),
      TS_GLSL450(Exp2),
      TS_GLSL450(Log2),
      TS_GLSL450(Sqrt),
      TS_GLSL450(InverseSqrt),
      TS_GLSL450(Determinant),
      TS_GLSL450(MatrixInverse),
      TS_GLSL450(Modf),
      TS_GLSL450(ModfStruct),
      TS_GLSL450(FMin),
      TS_GLSL450(UMin),
      TS_GLSL450(SMin),
      TS_GLSL450(FMax),
      TS_GLSL450(UMax),
      TS_GLSL450(SMax),
      TS_GLSL450(FClamp),
      TS_GLSL450(UClamp),
      TS_GLSL450(SClamp),
      TS_GLSL450(FMix),
      TS_GLSL450(IMix),
      TS_GLSL450(Step),
      TS_GLSL450(SmoothStep),
      TS_GLSL450(Fma),
      TS_GLSL450(Frexp),
      TS_GLSL450(FrexpStruct),
      TS_GLSL450(Ldexp),
      TS_GLSL450(PackSnorm4x8),
      TS_GLSL450(PackUnorm4x8),
      TS_GLSL450(PackSnorm2x16),
      TS_GLSL450(PackUnorm2x16),
      TS_GLSL450(PackHalf2x16),
      TS_GLSL450(PackDouble2x32),
      TS_GLSL450(UnpackSnorm2x16),
      TS_GLSL450(UnpackUnorm2x16),
      TS_GLSL450(UnpackHalf2x16),
      TS_GLSL450(UnpackSnorm4x8),
      TS_GLSL450(UnpackUnorm4x8),
      TS_GLSL450(UnpackDouble2x32),
      TS_GLSL450(Length),
      TS_GLSL450(Distance),
      TS_GLSL450(Cross),
      TS_GLSL450(Normalize),
      TS_GLSL450(FaceForward),
      TS_GLSL450(Reflect),
      TS_GLSL450(Refract),
      TS_GLSL450(FindILsb),
      TS_GLSL450(FindSMsb),
      TS_GLSL450(FindUMsb),
      TS_GLSL450(InterpolateAtCentroid),
      TS_GLSL450(InterpolateAtSample),
      TS_GLSL450(InterpolateAtOffset),
      TS_GLSL450(NMin),
      TS_GLSL450(NMax),
      TS_GLSL450(NClamp),
  };
#undef TS_GLSL450
  auto it = kNames.find(inst);
  return it == kNames.end() ? "" : it->second;
}

std::string id_name(Id id) { return "%" + std::to_string(id); }

}  // namespace budget

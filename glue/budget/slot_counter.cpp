// tiershade budget: the DX9 slot counter: per-instruction costs (the weight table plus its
// special rules), mad / dp2add / _sat fusion, constant folding of unrolled loops and the walk
// over the flattened entry point (docs/budget_model.md, "Counting model").
#include "budget/slot_counter.h"

#include <spirv/unified1/GLSL.std.450.h>

#include <sstream>

namespace budget {

namespace {

bool starts_with(const std::string &s, const char *prefix) { return s.rfind(prefix, 0) == 0; }

// OpFOrdEqual .. OpFUnordGreaterThanEqual: the twelve float comparisons.
bool is_float_compare(Op op) {
  const auto v = static_cast<uint32_t>(op);
  return v >= static_cast<uint32_t>(Op::OpFOrdEqual) && v <= static_cast<uint32_t>(Op::OpFUnordGreaterThanEqual);
}

bool is_ext(const Inst &in, GLSLstd450 a, GLSLstd450 b) {
  if (in.args.size() < 2) return false;
  const uint32_t n = in.args[1].literal();
  return n == static_cast<uint32_t>(a) || n == static_cast<uint32_t>(b);
}

}  // namespace

Counter::Counter(const Module &m) : m_(m) {
  for (const Rule &r : weight_rules()) {
    std::istringstream ss(r.ops);
    std::string name;
    while (ss >> name) (r.ext ? ext_rules_ : core_rules_)[name] = &r;
  }
}

Id Counter::output_variable(Id ptr) const {
  Id id = ptr;
  for (int guard = 0; guard < 16; ++guard) {
    auto v = m_.var_storage.find(id);
    if (v != m_.var_storage.end()) return v->second == static_cast<uint32_t>(spv::StorageClass::Output) ? id : 0;
    const Inst *d = def(id);
    if (!d || (d->op != Op::OpAccessChain && d->op != Op::OpInBoundsAccessChain) || d->args.empty()) return 0;
    id = d->args[0].id;
  }
  return 0;
}

// Values computed only from constants and induction variables fold away once
// a loop is unrolled (and spirv-opt already folded the rest).
void Counter::propagate_derived(const Function &f) {
  static const std::set<Op> kOpaque = {Op::OpLoad,         Op::OpAccessChain,  Op::OpInBoundsAccessChain,
                                       Op::OpPhi,          Op::OpFunctionCall, Op::OpVariable,
                                       Op::OpSampledImage, Op::OpImage,        Op::OpFunctionParameter};
  derived_.clear();
  for (Id id : induction_) {
    const Inst *d = def(id);
    if (d && d->op == Op::OpPhi) derived_.insert(id);
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (const Block &b : f.blocks) {
      if (!reachable_.count(b.label)) continue;
      for (const Inst &in : b.insts) {
        if (in.result == 0 || derived_.count(in.result)) continue;
        if (kOpaque.count(in.op) || starts_with(op_name(in.op), "OpImage")) continue;
        if (in.op == Op::OpExtInst && ext_set(in) != "GLSL.std.450") continue;
        std::vector<Id> ids = id_operands(in);
        bool all = !ids.empty();
        for (Id id : ids)
          if (!is_const(id)) {
            all = false;
            break;
          }
        if (all) {
          derived_.insert(in.result);
          changed = true;
        }
      }
    }
  }
}

// mad fusion, dp2add fusion and _sat clamps.
void Counter::analyse_fusion(const Function &f) {
  auto same_block = [&](Id a, Id b) {
    auto ia = def_block_.find(a), ib = def_block_.find(b);
    return ia != def_block_.end() && ib != def_block_.end() && ia->second == ib->second;
  };
  for (const Block &b : f.blocks) {
    for (const Inst &in : b.insts) {
      if ((in.op != Op::OpFAdd && in.op != Op::OpFSub) || in.args.size() != 2) continue;
      if (derived_.count(in.result)) continue;
      bool fused = false;
      for (const Operand &o : in.args) {
        const Id a = o.id;
        const Inst *d = def(a);
        if (d && (d->op == Op::OpFMul || d->op == Op::OpVectorTimesScalar) && uses(a) == 1 &&
            same_block(a, in.result) && !fused_mul_.count(a) && !derived_.count(a)) {
          fused_mul_.insert(a);
          fused = true;
          break;
        }
      }
      if (fused) continue;
      for (const Operand &o : in.args) {
        const Inst *d = def(o.id);
        if (d && d->op == Op::OpDot && !d->args.empty() && comps(value_type(d->args[0].id)) == 2 && uses(o.id) == 1 &&
            same_block(o.id, in.result) && !derived_.count(o.id)) {
          free_add_.insert(in.result);
          break;
        }
      }
    }
  }
  // _sat: needs the fusion sets above to know whether x is a real ALU instruction.
  for (const Block &b : f.blocks) {
    for (const Inst &in : b.insts) {
      if (ext_set(in) != "GLSL.std.450" || !is_ext(in, GLSLstd450FClamp, GLSLstd450NClamp)) continue;
      if (!const_all(ext_arg(in, 1), 0.0) || !const_all(ext_arg(in, 2), 1.0)) continue;
      // x must be a single-use ALU result, or a vector built only from
      // single-use ALU results (each lane's instruction takes the _sat).
      auto alu_result = [&](Id id) {
        const Inst *d = def(id);
        if (!d || uses(id) != 1 || !same_block(id, in.result)) return false;
        Cost c = cost(*d, *blocks_.at(def_block_.at(id)));
        return c.alu >= 1 && c.tex == 0;
      };
      const Id x = ext_arg(in, 0);
      const Inst *d = def(x);
      bool sat = alu_result(x);
      if (!sat && d && d->op == Op::OpCompositeConstruct && uses(x) == 1 && same_block(x, in.result)) {
        sat = true;
        for (const Operand &lane : d->args)
          if (!alu_result(lane.id)) sat = false;
      }
      if (sat) sat_clamp_.insert(in.result);
    }
  }
}

int Counter::div_cost(const Inst &in) const {
  if (in.args.size() != 2) return 2;
  const Id num = in.args[0].id, den = in.args[1].id;
  int rcp;
  if (is_const(den)) {
    rcp = 0;  // reciprocal folded into a constant
  } else {
    const Inst *d = def(den);
    rcp = comps(in.type);
    if (d && d->op == Op::OpCompositeConstruct && !d->args.empty()) {
      bool splat = true;
      for (const Operand &a : d->args)
        if (a.id != d->args[0].id || !a.is_id()) splat = false;
      if (splat) rcp = 1;
    }
  }
  int mul = (const_all(num, 1.0) && rcp > 0) ? 0 : 1;
  return rcp + mul;
}

Cost Counter::ext_cost(const Inst &in) const {
  Cost c;
  const std::string set = ext_set(in);
  if (set != "GLSL.std.450") {
    c.name = starts_with(set, "NonSemantic.") ? std::string() : "other:" + set;
    c.alu = c.name.empty() ? 0 : 1;
    return c;
  }
  const std::string name = ext_name(in);
  c.name = name;
  const int n = comps(in.type);
  const Id x = ext_arg(in, 0);
  if (is_ext(in, GLSLstd450FClamp, GLSLstd450NClamp)) {
    if (const_all(ext_arg(in, 1), 0.0) && const_all(ext_arg(in, 2), 1.0))
      c.alu = sat_clamp_.count(in.result) ? 0 : 1;
    else
      c.alu = 2;
    return c;
  }
  if (is_ext(in, GLSLstd450Step, GLSLstd450Step)) {
    c.alu = const_all(x, 0.0) ? 1 : 2;
    return c;
  }
  if (is_ext(in, GLSLstd450SmoothStep, GLSLstd450SmoothStep)) {
    c.alu = (is_const(x) && is_const(ext_arg(in, 1))) ? 4 : 7;
    return c;
  }
  if (is_ext(in, GLSLstd450Length, GLSLstd450Length)) {
    c.alu = comps(value_type(x)) > 1 ? 3 : 1;
    return c;
  }
  if (is_ext(in, GLSLstd450Distance, GLSLstd450Distance)) {
    int w = comps(value_type(x));
    if (w <= 1) w = comps(value_type(ext_arg(in, 1)));
    c.alu = w > 1 ? 4 : 2;
    return c;
  }
  if (is_ext(in, GLSLstd450Determinant, GLSLstd450MatrixInverse)) {
    const TypeInfo &t = type_of(value_type(x));
    int size = t.kind == TypeInfo::Matrix ? t.cols : 4;
    static const int det[] = {2, 2, 2, 3, 12}, inv[] = {4, 4, 4, 12, 36};
    size = size < 2 ? 2 : (size > 4 ? 4 : size);
    c.alu = is_ext(in, GLSLstd450Determinant, GLSLstd450Determinant) ? det[size] : inv[size];
    return c;
  }
  auto r = ext_rules_.find(name);
  if (r == ext_rules_.end()) {
    c.name = "other:" + name;
    c.alu = 1;
    return c;
  }
  int slots = r->second->fixed + r->second->per_comp * n;
  if (r->second->unit == Unit::Tex)
    c.tex = slots;
  else if (r->second->unit == Unit::Alu)
    c.alu = slots;
  return c;
}

Cost Counter::cost(const Inst &in, const Block &b) const {
  Cost c;
  c.name = op_name(in.op);
  const Op op = in.op;
  if (in.result != 0 && derived_.count(in.result)) return Cost();  // folds to a constant
  if (op == Op::OpExtInst) return ext_cost(in);
  if (op == Op::OpFMul || op == Op::OpVectorTimesScalar) {
    c.alu = fused_mul_.count(in.result) ? 0 : 1;
    return c;
  }
  if (op == Op::OpFAdd || op == Op::OpFSub) {
    c.alu = free_add_.count(in.result) ? 0 : 1;
    return c;
  }
  if (op == Op::OpDot) {
    c.alu = (!in.args.empty() && comps(value_type(in.args[0].id)) == 2) ? 2 : 1;
    return c;
  }
  if (op == Op::OpFDiv) {
    c.alu = div_cost(in);
    return c;
  }
  if (op == Op::OpFMod || op == Op::OpFRem) {
    c.alu = div_cost(in) + 2;
    return c;
  }
  if (op == Op::OpPhi) {
    int incoming = static_cast<int>(in.args.size() / 2);
    c.alu = b.loop_header || incoming < 2 ? 0 : incoming - 1;
    return c;
  }
  if (op == Op::OpSwitch) {  // selector, default, then (literal, label) pairs
    if (in.args.empty() || is_const(in.args[0].id)) return c;
    for (size_t i = 2; i < in.args.size(); i += 2)
      if (in.args[i].literal_nonzero()) ++c.alu;
    return c;
  }
  if (is_float_compare(op)) {
    bool vs_zero = false;
    for (const Operand &a : in.args)
      if (const_all(a.id, 0.0)) vs_zero = true;
    c.alu = vs_zero ? 0 : 1;
    return c;
  }
  if (op == Op::OpVectorShuffle || op == Op::OpCompositeConstruct || op == Op::OpCompositeInsert) {
    // Which operands feed lanes of the result?
    std::vector<Id> srcs;
    if (op == Op::OpVectorShuffle && in.args.size() >= 2) {
      const int w0 = comps(value_type(in.args[0].id));
      for (size_t i = 2; i < in.args.size(); ++i) {
        const uint32_t lane = in.args[i].literal();
        if (lane == 0xffffffffu) continue;  // undefined lane
        srcs.push_back(static_cast<int>(lane) < w0 ? in.args[0].id : in.args[1].id);
      }
    } else if (op == Op::OpCompositeInsert && in.args.size() >= 2) {
      srcs = {in.args[0].id, in.args[1].id};
    } else {
      for (const Operand &a : in.args) srcs.push_back(a.id);
    }
    bool any_const = false, any_var = false;
    for (Id s : srcs) {
      if (s == 0) continue;
      if (is_const(s))
        any_const = true;
      else
        any_var = true;
    }
    c.alu = (any_const && any_var) ? 1 : 0;
    if (c.alu) c.name += " (constant lanes)";
    return c;
  }
  if (op == Op::OpMatrixTimesVector || op == Op::OpVectorTimesMatrix) {
    c.alu = comps(in.type);
    return c;
  }
  if (op == Op::OpMatrixTimesMatrix) {
    const TypeInfo &t = type_of(in.type);
    c.alu = t.cols * t.comps;
    return c;
  }
  if (op == Op::OpMatrixTimesScalar || op == Op::OpOuterProduct) {
    c.alu = type_of(in.type).cols;
    return c;
  }

  auto r = core_rules_.find(c.name);
  if (r == core_rules_.end()) {
    c.name = "other:" + c.name;
    c.alu = 1;
    return c;
  }
  int slots = r->second->fixed + r->second->per_comp * comps(in.type);
  if (r->second->unit == Unit::Tex)
    c.tex = slots;
  else if (r->second->unit == Unit::Alu)
    c.alu = slots;
  return c;
}

bool Counter::analyse_function(const Function &f, std::string *err) {
  defs_.clear();
  def_block_.clear();
  use_count_.clear();
  blocks_.clear();
  reachable_.clear();
  loops_.clear();
  induction_.clear();
  derived_.clear();
  fused_mul_.clear();
  free_add_.clear();
  sat_clamp_.clear();
  if (f.blocks.empty()) {
    *err = "fragment entry point has no body";
    return false;
  }

  for (const Block &b : f.blocks) {
    blocks_[b.label] = &b;
    if (b.insts.empty()) {
      *err = "empty block " + id_name(b.label);
      return false;
    }
    for (const Inst &in : b.insts) {
      if (in.result != 0) {
        defs_[in.result] = &in;
        def_block_[in.result] = b.label;
      }
      for (Id id : id_operands(in)) ++use_count_[id];
    }
  }
  std::vector<Id> work{f.blocks.front().label};
  reachable_.insert(work.back());
  while (!work.empty()) {
    Id l = work.back();
    work.pop_back();
    auto it = blocks_.find(l);
    if (it == blocks_.end()) {
      *err = "branch to unknown block " + id_name(l);
      return false;
    }
    for (Id s : it->second->succ)
      if (reachable_.insert(s).second) work.push_back(s);
  }
  for (const Block &b : f.blocks) {
    if (!reachable_.count(b.label) || !b.loop_header) continue;
    LoopInfo loop;
    if (!analyse_loop(b, &loop, err)) return false;
    loops_.push_back(loop);
  }
  propagate_derived(f);
  analyse_fusion(f);
  return true;
}

bool Counter::count(BudgetCounts *out, std::string *err) {
  const Function *entry = nullptr;
  for (const Function &f : m_.functions)
    if (f.id == m_.fragment_entry) entry = &f;
  if (!entry) {
    *err = "fragment entry point " + id_name(m_.fragment_entry) + " not found";
    return false;
  }
  if (!analyse_function(*entry, err)) return false;

  BudgetCounts r;
  std::map<Id, std::set<Id>> outputs;  // output variable -> blocks storing it
  for (const Block &b : entry->blocks) {
    if (!reachable_.count(b.label)) continue;
    long mult = 1;
    for (const LoopInfo &l : loops_) {
      if (!l.body.count(b.label)) continue;
      mult *= l.prefix.count(b.label) ? l.trips_prefix : l.trips_body;
      if (mult > kMaxMultiplier) {
        *err = "nested loops run more than 2^20 iterations";
        return false;
      }
    }
    for (const Inst &in : b.insts) {
      if (in.op == Op::OpFunctionCall) {
        *err = "a function call survived the -O passes (" + id_name(in.args.empty() ? 0 : in.args.front().id) +
            "); cannot count it";
        return false;
      }
      if (in.op == Op::OpStore && !in.args.empty()) {
        Id var = output_variable(in.args[0].id);
        if (var != 0) outputs[var].insert(b.label);
        continue;
      }
      Cost c = cost(in, b);
      if (c.alu == 0 && c.tex == 0) continue;
      int alu = static_cast<int>(c.alu * mult), tex = static_cast<int>(c.tex * mult);
      r.alu += alu;
      r.tex += tex;
      r.by_op[c.name] += alu + tex;
    }
  }
  for (const auto &o : outputs) {
    r.alu += 1;
    r.by_op["output mov (oC#/oDepth)"] += 1;
    if (o.second.size() > 1) {  // written on several flattened paths: cmp selects the value
      int extra = static_cast<int>(o.second.size()) - 1;
      r.alu += extra;
      r.by_op["output merge cmp"] += extra;
    }
  }
  *out = r;
  return true;
}

}  // namespace budget

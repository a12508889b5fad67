// tiershade budget: the DX9 slot counter over one budget::Module: fusion (mad, dp2add, _sat),
// loop trip counts, flattened control flow and per-instruction costs from the weight table.
// Internal to glue/budget/; the model is docs/budget_model.md, "Counting model".
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "budget/budget.h"
#include "budget/spirv_module.h"
#include "budget/weight_table.h"

namespace budget {

constexpr int kMaxTrips = 1024;  // per loop
constexpr long kMaxMultiplier = 1 << 20;  // product over nested loops

struct Cost {
  int alu = 0;
  int tex = 0;
  std::string name;
};

class Counter {
 public:
  explicit Counter(const Module &m);

  // Counts the reachable instructions of the Fragment entry point.
  bool count(BudgetCounts *out, std::string *err);

 private:
  struct LoopInfo {
    Id header = 0, merge = 0;
    std::set<Id> body;  // includes the header
    std::set<Id> prefix;  // blocks executed before the exit test (top-tested loops)
    long trips_prefix = 0;  // executions of prefix blocks
    long trips_body = 0;  // executions of the other body blocks
  };

  // --- lookups ---
  const Inst *def(Id id) const {
    auto it = defs_.find(id);
    return it == defs_.end() ? nullptr : it->second;
  }
  int uses(Id id) const {
    auto it = use_count_.find(id);
    return it == use_count_.end() ? 0 : it->second;
  }
  const ConstInfo *constant(Id id) const {
    auto it = m_.consts.find(id);
    return it == m_.consts.end() ? nullptr : &it->second;
  }
  bool is_const(Id id) const { return constant(id) != nullptr || derived_.count(id) > 0; }
  bool const_all(Id id, double v) const {
    const ConstInfo *c = constant(id);
    if (!c || !c->known || c->values.empty()) return false;
    for (double x : c->values)
      if (x != v) return false;
    return true;
  }
  const TypeInfo &type_of(Id type_id) const {
    auto it = m_.types.find(type_id);
    return it == m_.types.end() ? unknown_type_ : it->second;
  }
  int comps(Id type_id) const { return type_of(type_id).comps; }
  // type id of any value: instruction result or constant
  Id value_type(Id id) const {
    if (const Inst *d = def(id)) return d->type;
    if (const ConstInfo *c = constant(id)) return c->type;
    return 0;
  }
  // id operands of an instruction (for OpExtInst without the set and the instruction number)
  std::vector<Id> id_operands(const Inst &in) const {
    std::vector<Id> ids;
    size_t start = in.op == Op::OpExtInst ? 2 : 0;
    for (size_t i = start; i < in.args.size(); ++i)
      if (in.args[i].is_id()) ids.push_back(in.args[i].id);
    return ids;
  }
  // the extended instruction set of an OpExtInst ("GLSL.std.450"), empty otherwise
  std::string ext_set(const Inst &in) const {
    if (in.op != Op::OpExtInst || in.args.empty()) return std::string();
    auto it = m_.ext_sets.find(in.args[0].id);
    return it == m_.ext_sets.end() ? std::string() : it->second;
  }
  // the GLSL.std.450 instruction name of an OpExtInst ("Fma"), empty for anything else
  std::string ext_name(const Inst &in) const {
    if (in.args.size() < 2 || ext_set(in) != "GLSL.std.450") return std::string();
    return glsl450_name(in.args[1].literal());
  }
  // operand i of an ext inst (after set and instruction number)
  Id ext_arg(const Inst &in, size_t i) const { return in.args.size() > i + 2 ? in.args[i + 2].id : 0; }

  bool analyse_function(const Function &f, std::string *err);
  bool analyse_loop(const Block &header, LoopInfo *loop, std::string *err);
  std::optional<double> eval(Id id, const std::map<Id, double> &env, int depth) const;
  void analyse_fusion(const Function &f);
  void propagate_derived(const Function &f);
  Cost cost(const Inst &in, const Block &b) const;
  Cost ext_cost(const Inst &in) const;
  int div_cost(const Inst &in) const;
  Id output_variable(Id ptr) const;

  const Module &m_;
  const TypeInfo unknown_type_;
  std::map<std::string, const Rule *> core_rules_, ext_rules_;
  // per-function analysis state
  std::map<Id, const Inst *> defs_;
  std::map<Id, Id> def_block_;
  std::map<Id, int> use_count_;
  std::map<Id, const Block *> blocks_;
  std::set<Id> reachable_;
  std::vector<LoopInfo> loops_;
  std::set<Id> induction_;  // loop induction phis and their updates
  std::set<Id> derived_;  // values that fold to constants once loops are unrolled
  std::set<Id> fused_mul_;  // muls absorbed into a mad
  std::set<Id> free_add_;  // adds absorbed into dp2add
  std::set<Id> sat_clamp_;  // clamp(x,0,1) done as _sat
};

}  // namespace budget

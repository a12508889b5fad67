// tiershade budget: loops that survive spirv-opt's -O passes: body, induction variables and the
// constant trip count, found by simulating the counter (ps_2_x has no flow control, so a loop
// is paid trip count x body; docs/budget_model.md, "Counting model").
#include "budget/slot_counter.h"

#include <cmath>

namespace budget {

// Small evaluator for loop trip counts: constants, the induction values in
// env, and integer/float arithmetic and comparisons on them.
std::optional<double> Counter::eval(Id id, const std::map<Id, double> &env, int depth) const {
  if (depth > 64) return std::nullopt;
  auto e = env.find(id);
  if (e != env.end()) return e->second;
  if (const ConstInfo *c = constant(id)) {
    if (c->known && c->values.size() == 1) return c->values[0];
    return std::nullopt;
  }
  const Inst *d = def(id);
  if (!d) return std::nullopt;
  const Op op = d->op;
  std::vector<double> v;
  for (const Operand &a : d->args) {
    if (!a.is_id()) return std::nullopt;
    std::optional<double> x = eval(a.id, env, depth + 1);
    if (!x || !std::isfinite(*x) || std::fabs(*x) > 1e15) return std::nullopt;  // keep int casts defined
    v.push_back(*x);
  }
  auto need = [&](size_t n) { return v.size() == n; };
  auto as_int = [](double x) { return static_cast<long long>(x); };
  auto any = [&](std::initializer_list<Op> ops) {
    for (Op o : ops)
      if (op == o) return true;
    return false;
  };
  if (op == Op::OpCopyObject && need(1)) return v[0];
  if (any({Op::OpIAdd, Op::OpFAdd}) && need(2)) return v[0] + v[1];
  if (any({Op::OpISub, Op::OpFSub}) && need(2)) return v[0] - v[1];
  if (any({Op::OpIMul, Op::OpFMul}) && need(2)) return v[0] * v[1];
  if (any({Op::OpSDiv, Op::OpUDiv}) && need(2) && as_int(v[1]) != 0)
    return static_cast<double>(as_int(v[0]) / as_int(v[1]));
  if (op == Op::OpFDiv && need(2) && v[1] != 0.0) return v[0] / v[1];
  if (any({Op::OpSNegate, Op::OpFNegate}) && need(1)) return -v[0];
  const bool shift_ok = need(2) && v[0] >= 0.0 && v[1] >= 0.0 && v[1] < 32.0;
  if (op == Op::OpShiftLeftLogical && shift_ok) return static_cast<double>(as_int(v[0]) << as_int(v[1]));
  if (any({Op::OpShiftRightArithmetic, Op::OpShiftRightLogical}) && shift_ok)
    return static_cast<double>(as_int(v[0]) >> as_int(v[1]));
  if (any({Op::OpConvertSToF, Op::OpConvertUToF}) && need(1)) return v[0];
  if (any({Op::OpConvertFToS, Op::OpConvertFToU}) && need(1)) return std::trunc(v[0]);
  if (op == Op::OpLogicalNot && need(1)) return v[0] != 0.0 ? 0.0 : 1.0;
  if (op == Op::OpLogicalAnd && need(2)) return (v[0] != 0.0 && v[1] != 0.0) ? 1.0 : 0.0;
  if (op == Op::OpLogicalOr && need(2)) return (v[0] != 0.0 || v[1] != 0.0) ? 1.0 : 0.0;
  if (op == Op::OpSelect && need(3)) return v[0] != 0.0 ? v[1] : v[2];
  if (need(2)) {
    if (any({Op::OpSLessThan, Op::OpULessThan, Op::OpFOrdLessThan, Op::OpFUnordLessThan}))
      return v[0] < v[1] ? 1.0 : 0.0;
    if (any({Op::OpSLessThanEqual, Op::OpULessThanEqual, Op::OpFOrdLessThanEqual, Op::OpFUnordLessThanEqual}))
      return v[0] <= v[1] ? 1.0 : 0.0;
    if (any({Op::OpSGreaterThan, Op::OpUGreaterThan, Op::OpFOrdGreaterThan, Op::OpFUnordGreaterThan}))
      return v[0] > v[1] ? 1.0 : 0.0;
    if (any({Op::OpSGreaterThanEqual, Op::OpUGreaterThanEqual, Op::OpFOrdGreaterThanEqual,
             Op::OpFUnordGreaterThanEqual}))
      return v[0] >= v[1] ? 1.0 : 0.0;
    if (any({Op::OpIEqual, Op::OpFOrdEqual, Op::OpFUnordEqual, Op::OpLogicalEqual})) return v[0] == v[1] ? 1.0 : 0.0;
    if (any({Op::OpINotEqual, Op::OpFOrdNotEqual, Op::OpFUnordNotEqual, Op::OpLogicalNotEqual}))
      return v[0] != v[1] ? 1.0 : 0.0;
  }
  return std::nullopt;
}

// Finds the loop's body, its induction variables and its trip count.
bool Counter::analyse_loop(const Block &header, LoopInfo *loop, std::string *err) {
  loop->header = header.label;
  loop->merge = header.merge;
  const std::string where = "loop at block " + id_name(header.label);

  // Body: everything reachable from the header without passing the merge block.
  std::vector<Id> work{header.label};
  loop->body.insert(header.label);
  while (!work.empty()) {
    Id b = work.back();
    work.pop_back();
    auto it = blocks_.find(b);
    if (it == blocks_.end()) continue;
    for (Id s : it->second->succ)
      if (s != loop->merge && loop->body.insert(s).second) work.push_back(s);
  }

  // Induction candidates: header phis (value, parent) pairs with a constant
  // value from outside the loop and an update from inside.
  struct Phi {
    Id id = 0, init = 0, update = 0;
  };
  std::vector<Phi> cands;
  for (const Inst &in : header.insts) {
    if (in.op != Op::OpPhi) continue;
    if (in.args.size() != 4) continue;
    Phi p;
    p.id = in.result;
    for (size_t i = 0; i + 1 < in.args.size(); i += 2) {
      if (loop->body.count(in.args[i + 1].id))
        p.update = in.args[i].id;
      else
        p.init = in.args[i].id;
    }
    const ConstInfo *c = constant(p.init);
    if (p.update == 0 || !c || !c->known || c->values.size() != 1) continue;
    cands.push_back(p);
  }
  std::map<Id, double> env;
  for (bool changed = true; changed;) {
    changed = false;
    env.clear();
    for (const Phi &p : cands) env[p.id] = constant(p.init)->values[0];
    for (size_t i = 0; i < cands.size(); ++i) {
      if (!eval(cands[i].update, env, 0)) {
        cands.erase(cands.begin() + static_cast<long>(i));
        changed = true;
        break;
      }
    }
  }

  // The exit test: follow unconditional branches from the header; the first
  // conditional branch with the merge block as a target is a top test.
  // Otherwise look for a latch that branches to the header or the merge.
  const Block *exit_block = nullptr;
  bool top_tested = false;
  {
    const Block *b = &header;
    std::set<Id> seen;
    while (b && seen.insert(b->label).second) {
      loop->prefix.insert(b->label);
      const Inst &term = b->insts.back();
      if (term.op == Op::OpBranchConditional) {
        if (term.args.size() >= 3 && (term.args[1].id == loop->merge || term.args[2].id == loop->merge)) {
          exit_block = b;
          top_tested = true;
        }
        break;
      }
      if (term.op != Op::OpBranch || term.args.empty() || term.args[0].id == header.label) break;
      auto it = blocks_.find(term.args[0].id);
      b = it == blocks_.end() ? nullptr : it->second;
    }
  }
  if (!exit_block) {
    loop->prefix.clear();
    for (Id label : loop->body) {
      const Block *b = blocks_.at(label);
      const Inst &term = b->insts.back();
      if (term.op == Op::OpBranchConditional && term.args.size() >= 3 &&
          ((term.args[1].id == header.label && term.args[2].id == loop->merge) ||
           (term.args[2].id == header.label && term.args[1].id == loop->merge))) {
        exit_block = b;
        break;
      }
    }
  }
  if (!exit_block) {
    *err = "unbounded loop: the " + where +
        " has no exit test on a compile-time trip count (ps_2_x has no flow control; "
        "use a constant-bounded for loop)";
    return false;
  }
  const Inst &term = exit_block->insts.back();
  const Id cond = term.args[0].id;
  const bool exit_when_true = term.args[1].id == loop->merge;

  // Simulate.  Each pass runs the prefix (or the whole body for a bottom
  // test), evaluates the exit test, then runs the rest and steps.
  long runs = 0, rest = 0;
  for (;;) {
    ++runs;
    std::optional<double> c = eval(cond, env, 0);
    if (!c) {
      *err =
          "unbounded loop: the exit condition of the " + where + " is not a compile-time function of the loop counter";
      return false;
    }
    bool exits = (*c != 0.0) == exit_when_true;
    if (exits) break;
    if (top_tested) ++rest;
    if (runs > kMaxTrips) {
      *err = "unbounded loop: the " + where + " runs more than " + std::to_string(kMaxTrips) + " iterations";
      return false;
    }
    std::map<Id, double> next = env;
    for (const Phi &p : cands) {
      std::optional<double> u = eval(p.update, env, 0);
      if (!u) {
        *err = "unbounded loop: the counter update of the " + where + " cannot be evaluated";
        return false;
      }
      next[p.id] = *u;
    }
    env = next;
  }
  if (top_tested) {
    loop->trips_prefix = runs;
    loop->trips_body = rest;
  } else {
    loop->trips_prefix = runs;
    loop->trips_body = runs;
  }
  for (const Phi &p : cands) {
    induction_.insert(p.id);
    induction_.insert(p.update);
  }
  return true;
}

}  // namespace budget

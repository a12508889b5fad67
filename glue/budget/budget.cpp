// tiershade budget: the public counter (budget.h): GLSL 3.30 -> optimised SPIR-V in process
// (glsl_to_spirv.cpp) -> budget::Module (spirv_module.cpp) -> DX9 slots (slot_counter.cpp,
// loop_trips.cpp, weight_table.cpp). The model: docs/budget_model.md.
#include "budget/budget.h"

#include "budget/glsl_to_spirv.h"
#include "budget/interface.h"
#include "budget/slot_counter.h"
#include "budget/spirv_module.h"
#include "budget/weight_table.h"

bool budget_count_fragment(const std::string &glsl330_source, BudgetCounts *out, std::string *err) {
  std::string dummy;
  std::string &e = err ? *err : dummy;
  e.clear();
  if (!out) {
    e = "budget_count_fragment: out is null";
    return false;
  }
  *out = BudgetCounts();

  std::vector<uint32_t> spirv;
  if (!budget::glsl_to_optimized_spirv(glsl330_source, &spirv, &e)) return false;
  budget::Module m;
  if (!budget::read_spirv_module(spirv, &m, &e)) return false;
  budget::Counter counter(m);
  BudgetCounts r;
  if (!counter.count(&r, &e)) return false;
  // Constant registers: the uniforms the stage uses once its loops are unrolled (interface.h).
  ProgramInterface iface;
  if (!reflect_fragment_unrolled(glsl330_source, &iface, &e)) return false;
  r.constants = fragment_constant_registers(iface);
  ProgramInterface declared;
  if (!reflect_stage(glsl330_source, false, &declared, &e)) return false;
  r.uniform_vectors = fragment_uniform_vectors(declared);
  *out = r;
  return true;
}

std::string budget_weight_table_markdown() { return budget::weight_table_markdown(); }

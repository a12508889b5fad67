// tiershade budget: the DX9 weight table: which DX9 instructions each SPIR-V instruction becomes
// and how many slots it costs (docs/budget_model.md, "The weight table"), and its markdown form.
// Internal to glue/budget/; the rules marked `special` are computed in slot_counter.cpp.
#pragma once

#include <string>
#include <vector>

namespace budget {

// Each row covers one or more SPIR-V opcodes (ext = false) or GLSL.std.450
// extended instructions (ext = true), separated by spaces.  Rows with a
// `special` text have their cost computed by a dedicated rule in the counter;
// the others cost `fixed + per_comp * result components` slots of `unit`.
enum class Unit { Free, Alu, Tex };

struct Rule {
  const char *ops;
  bool ext;
  Unit unit;
  int fixed;
  int per_comp;
  const char *dx9;
  const char *special;  // nullptr: plain fixed/per-component cost
};

// Every row, in the order the table is printed.
const std::vector<Rule> &weight_rules();

// The "slots" column of a row ("1", "3 per result component", or the special text).
std::string rule_slots_text(const Rule &r);

// The whole table as markdown (budget_weight_table_markdown()).
std::string weight_table_markdown();

}  // namespace budget

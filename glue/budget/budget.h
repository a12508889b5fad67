// tiershade budget: instruction-slot counter for fragment shaders in a DX9-like model.
//
// tiershade reproduces Valve Source engine shading in shader-model tiers:
//   ps20 : the DX9 ps_2_0 budget, at most 64 arithmetic + 32 texture slots
//   ps2b : at most 512 slots in total
//   sm3  : no slot limit
// and, in every tier, DX9's float constant registers (32 on ps_2_0/ps_2_b, 224 on ps_3_0).
// This module estimates how many DX9 instruction slots a GLSL fragment shader
// would take, so each variant can be checked against its tier's budget.
//
// Route, all in process: GLSL 3.30 -> glslang (C interface, as glslangValidator -V)
// -> SPIR-V -> spvtools::Optimizer with the spirv-opt -O passes -> walk the
// optimised binary's instructions (spvBinaryParse) -> weight every instruction
// with a DX9 cost table (vec4 SIMD: one slot per vector instruction;
// scalar-only DX9 instructions such as pow/rcp/rsq/exp/log/sincos are paid per
// component).  The model, the weight table and its known error against fxc are
// described in docs/budget_model.md; budget_weight_table_markdown() prints the
// table.  Files: glsl_to_spirv (compile + optimise), spirv_module (binary ->
// instructions), weight_table, slot_counter + loop_trips (the counter),
// nir_count (the NIR cross-check below).
//
// A second, independent counter reads Mesa's scalar NIR (ST_DEBUG=nir) for a
// cross-check; its counts are scalar (roughly 3-4x a vec4 DX9 count).
//
// No files and no processes; glslang is initialised once per process, and the
// functions may be called from several threads at once.
#ifndef TIERSHADE_GLUE_BUDGET_H
#define TIERSHADE_GLUE_BUDGET_H

#include <map>
#include <string>

struct BudgetCounts {
  int alu = 0;  // DX9 arithmetic instruction slots
  int tex = 0;  // DX9 texture instruction slots (texld*, texkill)
  int total() const { return alu + tex; }  // instruction slots (constants are not slots)
  // DX9 float constant registers (c#): one per vec4-or-smaller uniform the stage uses, matCxR C,
  // arrays at their used size once constant-trip loops are unrolled and dead loads removed (max
  // constant index + 1; the declared size where an index stays dynamic, as in sm3's light loop).
  // ps_2_0 and ps_2_b have 32, ps_3_0 224 (docs/budget_model.md, "Constant registers").
  int constants = 0;
  // WebGL 1's measure of the same (issue 14): fragment uniform vectors of the uniforms the stage
  // declares and statically uses, arrays at their DECLARED size (interface.h,
  // fragment_uniform_vectors); an ES 2.0 implementation must accept 16 (docs/tiers.md).
  int uniform_vectors = 0;
  std::map<std::string, int> by_op;  // slots per op name (non-zero entries only;
      // their sum equals total()), for --verbose
};

// Counts one fragment shader.
// source: a complete fragment shader in GLSL 3.30 core ("#version 330" first;
// plain "#line N" / "#line N M" directives with integer M are fine).  A missing
// version line gets "#version 330" prepended; a desktop version below 330 is
// raised to 330 and "compatibility" becomes "core"; ES sources are rejected.
// Returns false with a message in *err (e.g. "GLSL compile failed:" and the
// glslang log, positions "0:L:" (source string 0) or "M:L:" after "#line L M"; or
// "unbounded loop ...") on failure; *out is then left as zero counts.
bool budget_count_fragment(const std::string &glsl330_source, BudgetCounts *out, std::string *err);

// The weight table as a markdown table (for docs and --help).
std::string budget_weight_table_markdown();

// Cross-check: counts scalar ALU and tex instructions in the NIR that Mesa
// prints to stderr under ST_DEBUG=nir ("NIR before handing off to driver")
// for the fragment shader.  nir_dump is the text captured by the caller; it
// may hold other stages too.  If it holds several fragment shaders they must
// all be the same shader (same source_sha1), else this fails.
// ALU: every ALU instruction except mov and vecN (swizzle/packing moves),
// weighted by its destination width.  tex: tex/txb/txl/txd/txf/txf_ms/tg4.
bool budget_count_nir_text(const std::string &nir_dump, int *scalar_alu, int *tex, std::string *err);

#endif  // TIERSHADE_GLUE_BUDGET_H

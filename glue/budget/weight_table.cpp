// tiershade budget: the DX9 weight table (data) and its markdown form. Where each cost comes
// from, and its known error against fxc: docs/budget_model.md, "Weight table".
#include "budget/weight_table.h"

#include <sstream>

namespace budget {

const std::vector<Rule> &weight_rules() {
  static const std::vector<Rule> kRules = {
      // --- free: register access, swizzles, modifiers --------------------------------------------
      {"OpLoad OpAccessChain OpInBoundsAccessChain OpCompositeExtract OpCopyObject OpCopyLogical "
       "OpVariable OpUndef OpSampledImage OpImage OpFunctionParameter",
       false, Unit::Free, 0, 0, "register / constant access, source swizzle", nullptr},
      {"OpVectorShuffle OpCompositeConstruct OpCompositeInsert", false, Unit::Alu, 0, 0,
       "write masks and swizzles; `mov r.w, c` for constant lanes",
       "0; 1 when it mixes constant lanes with computed lanes (e.g. `vec4(rgb, 1.0)`)"},
      {"OpStore", false, Unit::Alu, 0, 0, "`mov oC#` / `mov oDepth` (+ `cmp`)",
       "0; 1 per distinct Output variable written (ps_2_x writes oC#/oDepth only with mov, once), "
       "+1 `cmp` per extra block that stores the same output (flattened early returns)"},
      {"OpFNegate OpSNegate", false, Unit::Free, 0, 0, "`-r` source modifier", nullptr},
      {"OpLogicalNot", false, Unit::Free, 0, 0, "swap the `cmp` operands", nullptr},
      {"OpBitcast OpConvertSToF OpConvertUToF OpFConvert OpSConvert OpUConvert", false, Unit::Free, 0, 0,
       "none: DX9 registers are float, integers are floats", nullptr},
      {"OpTranspose", false, Unit::Free, 0, 0, "none: `dp4` rows instead of `mul`/`mad` columns", nullptr},
      {"OpImageQuerySize OpImageQuerySizeLod OpImageQueryLevels OpImageQuerySamples", false, Unit::Free, 0, 0,
       "a constant set by the application", nullptr},
      {"OpLabel OpBranch OpBranchConditional OpSelectionMerge OpLoopMerge OpReturn OpReturnValue "
       "OpUnreachable OpLine OpNoLine OpNop",
       false, Unit::Free, 0, 0, "none: ps_2_x has no flow control",
       "0; every block of an if/switch is counted (flattened), loops are unrolled (trip count x body)"},
      // --- arithmetic ------------------------------------------------------------------------------
      {"OpSwitch", false, Unit::Alu, 0, 0, "`add` forming selector - case for each `cmp`",
       "1 per case label other than 0; 0 with a constant selector"},
      {"OpFAdd OpFSub", false, Unit::Alu, 1, 0, "`add`", nullptr},
      {"OpFMul OpVectorTimesScalar", false, Unit::Alu, 1, 0, "`mul`, or the mul half of `mad`",
       "1; 0 when its only use is an OpFAdd/OpFSub in the same block (fused into `mad`; an add absorbs one mul)"},
      {"OpDot", false, Unit::Alu, 1, 0, "`dp3` / `dp4` / `dp2add`",
       "1; 2 for vec2 (`dp2add` is a 2-slot ps_2_0 macro), and a single-use OpFAdd/OpFSub of that result is then free"},
      {"OpFDiv", false, Unit::Alu, 0, 0, "`rcp` (scalar) + `mul`",
       "1 `rcp` per divisor component (1 if the divisor is a scalar splat) + 1 `mul`; 0 rcp if the divisor is "
       "constant; no mul if the dividend is the constant 1"},
      {"OpFMod OpFRem", false, Unit::Alu, 0, 0, "division + `frc` + `mul`", "OpFDiv cost + 2"},
      {"OpSelect", false, Unit::Alu, 1, 0, "`cmp`", nullptr},
      {"OpPhi", false, Unit::Alu, 0, 0, "`cmp` merging a flattened if/switch",
       "k-1 for k incoming values; 0 in a loop header (register reuse once unrolled)"},
      {"OpFOrdEqual OpFUnordEqual OpFOrdNotEqual OpFUnordNotEqual OpFOrdLessThan OpFUnordLessThan "
       "OpFOrdGreaterThan OpFUnordGreaterThan OpFOrdLessThanEqual OpFUnordLessThanEqual "
       "OpFOrdGreaterThanEqual OpFUnordGreaterThanEqual",
       false, Unit::Alu, 0, 0, "`add` forming a-b for `cmp` / `texkill`",
       "0 when one operand is the constant 0 (cmp/texkill test the value itself); 1 otherwise"},
      {"OpLogicalAnd OpLogicalOr OpLogicalEqual OpLogicalNotEqual", false, Unit::Alu, 1, 0,
       "`mul` / `add` / `cmp` on 0-1 masks", nullptr},
      {"OpAny OpAll", false, Unit::Alu, 2, 0, "`dp4` + `cmp`", nullptr},
      {"OpIsNan OpIsInf", false, Unit::Alu, 1, 0, "none in DX9 (harness only)", nullptr},
      {"OpIAdd OpISub OpIMul OpSDiv OpUDiv OpSMod OpSRem OpUMod OpShiftLeftLogical OpShiftRightLogical "
       "OpShiftRightArithmetic OpBitwiseAnd OpBitwiseOr OpBitwiseXor OpNot OpIEqual OpINotEqual OpSLessThan "
       "OpSLessThanEqual OpSGreaterThan OpSGreaterThanEqual OpULessThan OpULessThanEqual OpUGreaterThan "
       "OpUGreaterThanEqual",
       false, Unit::Alu, 1, 0, "none: DX9 has no integer ALU (harness code only)", nullptr},
      {"OpConvertFToS OpConvertFToU", false, Unit::Alu, 2, 0, "`frc` + `add` (floor; exact for x >= 0)", nullptr},
      {"OpMatrixTimesVector OpVectorTimesMatrix", false, Unit::Alu, 0, 0, "`m4x4`, `m3x3`, ... (one `dp` per row)",
       "1 per result component (mat4*vec4 = 4, mat3*vec3 = 3)"},
      {"OpMatrixTimesMatrix", false, Unit::Alu, 0, 0, "one `mNxM` per result column", "result columns x result rows"},
      {"OpMatrixTimesScalar OpOuterProduct", false, Unit::Alu, 0, 0, "`mul` per column", "1 per result column"},
      {"OpDPdx OpDPdy OpDPdxFine OpDPdyFine OpDPdxCoarse OpDPdyCoarse", false, Unit::Alu, 1, 0,
       "`dsx` / `dsy` (ps_2_x only; not in ps_2_0)", nullptr},
      {"OpFwidth OpFwidthFine OpFwidthCoarse", false, Unit::Alu, 5, 0, "`dsx`, `dsy`, `abs`, `abs`, `add`", nullptr},
      // --- texture -------------------------------------------------------------------------------
      {"OpImageSampleImplicitLod OpImageSampleExplicitLod OpImageSampleDrefImplicitLod "
       "OpImageSampleDrefExplicitLod OpImageSampleProjImplicitLod OpImageSampleProjExplicitLod "
       "OpImageSampleProjDrefImplicitLod OpImageSampleProjDrefExplicitLod OpImageFetch OpImageGather "
       "OpImageDrefGather",
       false, Unit::Tex, 1, 0, "`texld` / `texldp` / `texldb` (`texldl` in ps_3_0)", nullptr},
      {"OpKill OpTerminateInvocation OpDemoteToHelperInvocation", false, Unit::Tex, 1, 0,
       "`texkill` (a texture instruction in ps_2_0)", nullptr},
      {"OpFunctionCall", false, Unit::Free, 0, 0, "none", "error: spirv-opt -O inlines every call"},
      // --- GLSL.std.450 extended instructions -----------------------------------------------------
      {"Fma", true, Unit::Alu, 1, 0, "`mad`", nullptr},
      {"FMin FMax UMin UMax SMin SMax NMin NMax", true, Unit::Alu, 1, 0, "`min` / `max`", nullptr},
      {"FClamp NClamp", true, Unit::Alu, 0, 0, "`_sat` modifier, `mov_sat`, or `max` + `min`",
       "clamp(x,0,1): 0 if x is a single-use ALU result in the same block, or a vector built only from such "
       "results (`_sat`), else 1 (`mov_sat`); other bounds: 2"},
      {"UClamp SClamp", true, Unit::Alu, 2, 0, "`max` + `min`", nullptr},
      {"FMix", true, Unit::Alu, 2, 0, "`lrp` (2-slot macro)", nullptr},
      {"Step", true, Unit::Alu, 0, 0, "`cmp` (+ `add`)", "1 with a constant 0 edge, else 2"},
      {"SmoothStep", true, Unit::Alu, 0, 0, "`mad_sat`, `mad`, `mul`, `mul` (+ `add`, `add`, `rcp`)",
       "4 with constant edges, else 7"},
      {"FAbs SAbs", true, Unit::Alu, 1, 0, "`abs` (the `_abs` source modifier is ps_3_0 only)", nullptr},
      {"FSign SSign", true, Unit::Alu, 2, 0, "`cmp`, `cmp`", nullptr},
      {"Fract", true, Unit::Alu, 1, 0, "`frc`", nullptr},
      {"Floor Ceil Modf ModfStruct", true, Unit::Alu, 2, 0, "`frc` + `add`", nullptr},
      {"Round RoundEven", true, Unit::Alu, 3, 0, "`add`, `frc`, `add`", nullptr},
      {"Trunc", true, Unit::Alu, 4, 0, "`frc`, `add`, `cmp`, `add`", nullptr},
      {"Radians Degrees", true, Unit::Alu, 1, 0, "`mul`", nullptr},
      {"Exp2 Log2", true, Unit::Alu, 0, 1, "`exp` / `log` (scalar)", nullptr},
      {"Exp Log", true, Unit::Alu, 1, 1, "`mul` + scalar `exp` / `log`", nullptr},
      {"Pow", true, Unit::Alu, 0, 3, "`pow` (scalar 3-slot macro: log, mul, exp)", nullptr},
      {"InverseSqrt", true, Unit::Alu, 0, 1, "`rsq` (scalar)", nullptr},
      {"Sqrt", true, Unit::Alu, 0, 2, "`rsq` + `rcp` (scalar)", nullptr},
      {"Sin Cos", true, Unit::Alu, 0, 8, "`sincos` (scalar 8-slot macro)", nullptr},
      {"Tan", true, Unit::Alu, 0, 10, "`sincos` + `rcp` + `mul`", nullptr},
      {"Asin Acos", true, Unit::Alu, 0, 10, "polynomial + sqrt (rough)", nullptr},
      {"Atan", true, Unit::Alu, 0, 12, "rcp + polynomial + cmp (rough)", nullptr},
      {"Atan2", true, Unit::Alu, 0, 16, "as atan plus quadrant fix-up (rough)", nullptr},
      {"Sinh Cosh", true, Unit::Alu, 0, 4, "`exp`, `rcp`, `add`, `mul` (rough)", nullptr},
      {"Tanh", true, Unit::Alu, 0, 5, "`exp`, `add`, `rcp`, `mad` (rough)", nullptr},
      {"Asinh Acosh Atanh", true, Unit::Alu, 0, 6, "`log` + sqrt or rcp (rough)", nullptr},
      {"Length", true, Unit::Alu, 0, 0, "`dp3`, `rsq`, `rcp`", "3; 1 (`abs`) for a scalar"},
      {"Distance", true, Unit::Alu, 0, 0, "`add` + `dp3`, `rsq`, `rcp`", "4; 2 for scalars"},
      {"Normalize", true, Unit::Alu, 3, 0, "`nrm` (3-slot macro: dp3, rsq, mul)", nullptr},
      {"Cross", true, Unit::Alu, 2, 0, "`crs` (2-slot macro)", nullptr},
      {"FaceForward", true, Unit::Alu, 2, 0, "`dp3` + `cmp`", nullptr},
      {"Reflect", true, Unit::Alu, 3, 0, "`dp3`, `add`, `mad`", nullptr},
      {"Refract", true, Unit::Alu, 8, 0, "dp3, mad, mad, rsq, rcp, mad, mad, cmp (rough)", nullptr},
      {"Determinant", true, Unit::Alu, 0, 0, "`mul`/`mad` chains", "2 (2x2), 3 (3x3: crs + dp3), 12 (4x4, rough)"},
      {"MatrixInverse", true, Unit::Alu, 0, 0, "cofactors + rcp (rough)", "4 (2x2), 12 (3x3), 36 (4x4)"},
  };
  return kRules;
}

std::string rule_slots_text(const Rule &r) {
  if (r.special) return r.special;
  if (r.unit == Unit::Free) return "0";
  std::string u = r.unit == Unit::Tex ? " tex" : "";
  if (r.per_comp == 0) return std::to_string(r.fixed) + u;
  std::string pc = std::to_string(r.per_comp) + " per result component";
  if (r.fixed == 0) return pc + u;
  return std::to_string(r.fixed) + " + " + pc + u;
}

std::string weight_table_markdown() {
  std::ostringstream md;
  md << "| SPIR-V instruction | DX9 equivalent | slots |\n";
  md << "|---|---|---|\n";
  for (const Rule &r : weight_rules()) {
    std::istringstream ss(r.ops);
    std::string name, names;
    while (ss >> name) names += (names.empty() ? "" : ", ") + name;
    if (r.ext) names += " (GLSL.std.450)";
    md << "| " << names << " | " << r.dx9 << " | " << rule_slots_text(r) << " |\n";
  }
  md << "| any other instruction | unknown | 1, reported as `other:<name>` |\n";
  return md.str();
}

}  // namespace budget

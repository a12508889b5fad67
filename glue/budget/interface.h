// tiershade budget: the declared interface of a program, read from its source (issue 14): the
// vertex inputs, uniforms and samplers each stage declares and statically uses (referenced by
// code reachable from main, before any optimisation), arrays at their declared size; compiled
// with glslang (GLSL 3.30 -> SPIR-V for OpenGL, unoptimised) and read from the SPIR-V words.
// A driver's reflection (glGetActiveUniform...) may report less: it drops what its optimiser
// removes and trims arrays to the last element used (docs/bundles.md). Also the DX9 constant
// registers of a fragment stage (docs/budget_model.md, "Constant registers").
// No files, no GL; thread-safe as glsl_to_spirv is.
#pragma once
#include <set>
#include <string>
#include <vector>

struct InterfaceVar {
  std::string name;
  std::string type;  // GLSL type of one element: "vec4", "mat4", "sampler2D", "samplerCube", ...
  int array_size = 0;  // declared size; 0: not an array
  // Elements addressed: max constant index + 1, or array_size when indexed with a non-constant
  // or used whole (what a DX9 compiler allocates registers for); 0: not an array.
  int used_size = 0;
  int registers_per_element = 1;  // vec4 registers per element: scalars and vectors 1, matCxR C
  bool vertex = false, fragment = false;  // the stages that statically use it
  int registers(bool used) const { return registers_per_element * (array_size ? (used ? used_size : array_size) : 1); }
};

struct ProgramInterface {
  std::vector<InterfaceVar> attributes;  // vertex inputs, sorted by name
  std::vector<InterfaceVar> uniforms;  // non-opaque uniforms, sorted by name
  std::vector<InterfaceVar> samplers;  // sampler uniforms, sorted by name
};

// One stage (GLSL 3.30 source, as the assembler writes for Target::GLSL330): the inputs (vertex
// stage only; built-ins excluded), uniforms and samplers the stage statically uses, with that
// stage's flag set. On a compile failure false with glslang's log in *err.
bool reflect_stage(const std::string &glsl330_source, bool vertex, ProgramInterface *out, std::string *err);

// The fragment stage as a DX9 compiler allocates its constants: compiled, every loop marked for
// unrolling, through the spirv-opt -O passes (loops with a constant trip count unrolled, dead loads
// removed), then read as above. used_size is then the last element the remaining code addresses.
bool reflect_fragment_unrolled(const std::string &glsl330_source, ProgramInterface *out, std::string *err);

// Both stages, merged by name (the stage flags or'd; a uniform both stages use must agree in
// type and declared size, else false naming it).
bool reflect_program(const std::string &vertex330, const std::string &fragment330, ProgramInterface *out,
                     std::string *err);

// DX9 float constant registers of a fragment stage: every uniform it uses, arrays at their used
// size (ps_2_0 and ps_2_b had 32, ps_3_0 224; docs/budget_model.md). Give it the interface of
// reflect_fragment_unrolled for fxc's count.
int fragment_constant_registers(const ProgramInterface &fragment);
// The same in WebGL 1's measure of fragment uniform vectors: arrays at their declared size (an ES
// 2.0 implementation must accept 16; GLSL ES 1.00 appendix A.7 packing of vec4s is exact here,
// and a smaller type still takes one row).
int fragment_uniform_vectors(const ProgramInterface &fragment);

// The identifiers of a source after glslang's preprocessor (any version, ESSL 1.00 included):
// what the stage really contains once #if and macros are resolved (sampler3D, dFdx, ...).
bool preprocessed_identifiers(const std::string &source, bool vertex, std::set<std::string> *out, std::string *err);

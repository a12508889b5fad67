// tiershade budget: GLSL 3.30 fragment source -> SPIR-V -> optimised SPIR-V, in process:
// glslang's C interface (the settings of `glslangValidator -V -R -S frag --amb --aml`) and
// spvtools::Optimizer with the `spirv-opt -O` passes. Internal to glue/budget/.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace budget {

// Rewrites the #version line for glslang (keeps the line count; docs/budget_model.md, "Route").
bool prepare_source(const std::string &src, std::string *out, std::string *err);

// Compiles a prepared fragment shader to SPIR-V.  On failure *err holds "GLSL compile failed:"
// and glslang's log, whose positions read "0:L:" (source string 0; "M:L:" after "#line L M").
bool compile_glsl_fragment(const std::string &prepared_source, std::vector<uint32_t> *spirv, std::string *err);

// The same for either stage; opengl_client: SPIR-V for OpenGL (glslangValidator -G: loose
// uniforms stay separate variables) instead of -V's Vulkan relaxed rules.
bool compile_glsl_stage(const std::string &prepared_source, bool vertex, bool opengl_client, std::vector<uint32_t> *spirv,
                        std::string *err);

// The text glslang's preprocessor leaves (macros expanded, #if resolved), for any GLSL or GLSL ES
// version, ESSL 1.00 included.
bool preprocess_glsl(const std::string &source, bool vertex, std::string *out, std::string *err);

// Runs the performance passes of `spirv-opt -O` (after validating the module, as spirv-opt does).
bool optimize_spirv(const std::vector<uint32_t> &in, std::vector<uint32_t> *out, std::string *err);

// The three steps above: source text to optimised SPIR-V words.
bool glsl_to_optimized_spirv(const std::string &glsl330_source, std::vector<uint32_t> *spirv, std::string *err);

}  // namespace budget

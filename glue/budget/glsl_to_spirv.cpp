// tiershade budget: GLSL 3.30 fragment source -> optimised SPIR-V in process, with glslang's
// C interface (glslang/Include/glslang_c_interface.h) and SPIRV-Tools' spvtools::Optimizer
// (spirv-tools/optimizer.hpp). The settings are those of the commands the counter used to
// run: glslangValidator -V -R -S frag --amb --aml, then spirv-opt -O. The C interface, not
// glslang's C++ classes: Debian builds glslang without RTTI, and the SAN=1 build's UBSan vptr
// check needs the typeinfo of every polymorphic class used in our code (link error otherwise).
#include "budget/glsl_to_spirv.h"
#include "budget/trim.h"

#include <glslang/Include/glslang_c_interface.h>
#include <glslang/Public/resource_limits_c.h>
#include <spirv-tools/optimizer.hpp>

#include <memory>
#include <mutex>
#include <sstream>

namespace budget {

namespace {

// glslang wants glslang_initialize_process() once per process before any shader; afterwards
// shaders may be compiled on several threads at once (each shader has its own pool).  We never
// call glslang_finalize_process: the tables live until exit.
void init_glslang_once() {
  static std::once_flag once;
  std::call_once(once, [] { glslang_initialize_process(); });
}

// A glslang C object with its delete function.
template <typename T>
using Handle = std::unique_ptr<T, void (*)(T *)>;

// Non-empty lines of a glslang log, each ending in a newline.
std::string log_lines(const std::string &text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    line = trim(line);
    if (!line.empty()) out += line + "\n";
  }
  return out;
}

}  // namespace

// glslang -V wants desktop GLSL >= 330 (or ES >= 310).  We keep the line count
// unchanged so compile errors point at the caller's lines.
bool prepare_source(const std::string &src, std::string *out, std::string *err) {
  std::istringstream in(src);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);

  for (size_t i = 0; i < lines.size(); ++i) {
    std::string t = trim(lines[i]);
    if (t.empty() || t.rfind("//", 0) == 0) continue;  // blank or comment lines may precede #version
    if (t[0] == '#') {
      std::string rest = trim(t.substr(1));
      if (rest.rfind("version", 0) == 0) {
        std::istringstream vs(rest.substr(7));
        int version = 0;
        std::string profile;
        vs >> version >> profile;
        if (version <= 0) {
          *err = "malformed #version line: " + t;
          return false;
        }
        if (profile == "es") {
          *err = "ES shaders are not accepted; pass GLSL 3.30 core (got: " + t + ")";
          return false;
        }
        lines[i] = "#version " + std::to_string(version < 330 ? 330 : version) + " core";
        std::string joined;
        for (const std::string &l : lines) joined += l + "\n";
        *out = joined;
        return true;
      }
    }
    break;  // first real line is not #version
  }
  // No version line: GLSL would assume 110; we assume the caller meant 330.
  // "#line 1" (3.30 semantics: the next line is line 1) keeps line numbers.
  *out = "#version 330 core\n#line 1\n" + src;
  return true;
}

bool compile_glsl_fragment(const std::string &prepared_source, std::vector<uint32_t> *spirv, std::string *err) {
  return compile_glsl_stage(prepared_source, false, false, spirv, err);
}

bool compile_glsl_stage(const std::string &prepared_source, bool vertex, bool opengl_client, std::vector<uint32_t> *spirv,
                        std::string *err) {
  init_glslang_once();
  // -V: Vulkan 1.0 client, SPIR-V 1.0, Vulkan input semantics 100; -R: relaxed Vulkan rules
  // (uniforms outside blocks); --amb / --aml: automatic bindings and locations.
  glslang_input_t input = {};
  input.language = GLSLANG_SOURCE_GLSL;
  input.stage = vertex ? GLSLANG_STAGE_VERTEX : GLSLANG_STAGE_FRAGMENT;
  // The OpenGL client (glslangValidator -G) keeps loose uniforms as separate variables, as
  // the program interface reads them (glue/budget/interface.h); the budget keeps -V.
  input.client = opengl_client ? GLSLANG_CLIENT_OPENGL : GLSLANG_CLIENT_VULKAN;
  input.client_version = opengl_client ? GLSLANG_TARGET_OPENGL_450 : GLSLANG_TARGET_VULKAN_1_0;
  input.target_language = GLSLANG_TARGET_SPV;
  input.target_language_version = GLSLANG_TARGET_SPV_1_0;
  input.code = prepared_source.c_str();
  input.default_version = 100;  // what a source without #version means (never: see prepare_source)
  input.default_profile = GLSLANG_NO_PROFILE;
  input.force_default_version_and_profile = 0;
  input.forward_compatible = 0;
  input.messages = static_cast<glslang_messages_t>(
      opengl_client ? GLSLANG_MSG_SPV_RULES_BIT : (GLSLANG_MSG_SPV_RULES_BIT | GLSLANG_MSG_VULKAN_RULES_BIT));
  input.resource = glslang_default_resource();

  Handle<glslang_shader_t> shader(glslang_shader_create(&input), glslang_shader_delete);
  glslang_shader_set_options(shader.get(), GLSLANG_SHADER_AUTO_MAP_BINDINGS | GLSLANG_SHADER_AUTO_MAP_LOCATIONS |
                                               (opengl_client ? 0 : GLSLANG_SHADER_VULKAN_RULES_RELAXED));
  // The C interface parses the text glslang_shader_preprocess leaves (which keeps the
  // positions: it writes #line directives where lines or source strings change).
  if (!glslang_shader_preprocess(shader.get(), &input) || !glslang_shader_parse(shader.get(), &input)) {
    *err = "GLSL compile failed:\n" + log_lines(glslang_shader_get_info_log(shader.get())) +
        log_lines(glslang_shader_get_info_debug_log(shader.get()));
    return false;
  }
  Handle<glslang_program_t> program(glslang_program_create(), glslang_program_delete);
  glslang_program_add_shader(program.get(), shader.get());
  if (!glslang_program_link(program.get(), input.messages) || !glslang_program_map_io(program.get())) {
    *err = "GLSL link failed:\n" + log_lines(glslang_program_get_info_log(program.get())) +
        log_lines(glslang_program_get_info_debug_log(program.get()));
    return false;
  }
  glslang_spv_options_t options = {};  // no debug info, no glslang-side optimisation (as -V without -Os)
  options.disable_optimizer = true;
  glslang_program_SPIRV_generate_with_options(program.get(), input.stage, &options);
  const size_t words = glslang_program_SPIRV_get_size(program.get());
  if (words == 0) {
    const char *msg = glslang_program_SPIRV_get_messages(program.get());
    *err = "GLSL to SPIR-V failed:\n" + log_lines(msg ? msg : "(no message)");
    return false;
  }
  spirv->assign(words, 0u);
  glslang_program_SPIRV_get(program.get(), spirv->data());
  return true;
}

bool preprocess_glsl(const std::string &source, bool vertex, std::string *out, std::string *err) {
  init_glslang_once();
  glslang_input_t input = {};
  input.language = GLSLANG_SOURCE_GLSL;
  input.stage = vertex ? GLSLANG_STAGE_VERTEX : GLSLANG_STAGE_FRAGMENT;
  input.client = GLSLANG_CLIENT_NONE;  // any version, ESSL 1.00 included: no SPIR-V rules
  input.target_language = GLSLANG_TARGET_NONE;
  input.code = source.c_str();
  input.default_version = 100;
  input.default_profile = GLSLANG_NO_PROFILE;
  input.messages = GLSLANG_MSG_DEFAULT_BIT;
  input.resource = glslang_default_resource();
  Handle<glslang_shader_t> shader(glslang_shader_create(&input), glslang_shader_delete);
  if (!glslang_shader_preprocess(shader.get(), &input)) {
    *err = "GLSL preprocessing failed:\n" + log_lines(glslang_shader_get_info_log(shader.get()));
    return false;
  }
  *out = glslang_shader_get_preprocessed_code(shader.get());
  return true;
}

bool optimize_spirv(const std::vector<uint32_t> &in, std::vector<uint32_t> *out, std::string *err) {
  // spirv-opt's default target environment (SPIR-V 1.5, its --target-env default).
  spvtools::Optimizer opt(SPV_ENV_UNIVERSAL_1_5);
  std::string log;
  opt.SetMessageConsumer([&log](spv_message_level_t, const char *, const spv_position_t &pos, const char *msg) {
    log += "instruction " + std::to_string(pos.index) + ": " + msg + "\n";
  });
  opt.RegisterPerformancePasses();
  spvtools::OptimizerOptions options;  // validates the input first, as spirv-opt does
  if (!opt.Run(in.data(), in.size(), out, options)) {
    *err = "SPIR-V optimiser (the spirv-opt -O passes) failed:\n" + (log.empty() ? "(no message)\n" : log);
    return false;
  }
  return true;
}

bool glsl_to_optimized_spirv(const std::string &glsl330_source, std::vector<uint32_t> *spirv, std::string *err) {
  std::string source;
  std::vector<uint32_t> unoptimized;
  return prepare_source(glsl330_source, &source, err) && compile_glsl_fragment(source, &unoptimized, err) &&
      optimize_spirv(unoptimized, spirv, err);
}

}  // namespace budget

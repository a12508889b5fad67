// tiershade budget: GLSL 3.30 fragment source -> optimised SPIR-V in process, with glslang's
// C++ API (glslang/Public/ShaderLang.h, SPIRV/GlslangToSpv.h) and SPIRV-Tools'
// spvtools::Optimizer (spirv-tools/optimizer.hpp). The settings are those of the commands the
// counter used to run: glslangValidator -V -R -S frag --amb --aml, then spirv-opt -O.
#include "budget/glsl_to_spirv.h"
#include "budget/trim.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/optimizer.hpp>

#include <mutex>
#include <sstream>

namespace budget {

namespace {

// glslang wants InitializeProcess() once per process before any TShader; afterwards shaders
// may be compiled on several threads at once (each TShader has its own pool).  We never call
// FinalizeProcess: the tables live until exit.
void init_glslang_once() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

// The name glslang gives the source string in its messages ("fragment.frag:15: ..."), as when
// glslangValidator compiled the file fragment.frag.
constexpr const char *kSourceName = "fragment.frag";

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
                if (version <= 0) { *err = "malformed #version line: " + t; return false; }
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
    init_glslang_once();
    const EShLanguage stage = EShLangFragment;
    glslang::TShader shader(stage);
    const char *text = prepared_source.c_str();
    const int length = static_cast<int>(prepared_source.size());
    const char *name = kSourceName;
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    // -V: Vulkan 1.0 client, SPIR-V 1.0, Vulkan input semantics 100; -R: relaxed Vulkan rules
    // (uniforms outside blocks); --amb / --aml: automatic bindings and locations.
    shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader.setEnvInputVulkanRulesRelaxed();
    shader.setAutoMapBindings(true);
    shader.setAutoMapLocations(true);
    const EShMessages messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    const int default_version = 100;  // what a source without #version means (never: see prepare_source)
    if (!shader.parse(GetDefaultResources(), default_version, false, messages)) {
        *err = "GLSL compile failed:\n" + log_lines(shader.getInfoLog()) + log_lines(shader.getInfoDebugLog());
        return false;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages) || !program.mapIO()) {
        *err = "GLSL link failed:\n" + log_lines(program.getInfoLog()) + log_lines(program.getInfoDebugLog());
        return false;
    }
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;  // no debug info, no glslang-side optimisation (as -V without -Os)
    spirv->clear();
    glslang::GlslangToSpv(*program.getIntermediate(stage), *spirv, &logger, &options);
    if (spirv->empty()) {
        *err = "GLSL to SPIR-V failed:\n" + log_lines(logger.getAllMessages());
        return false;
    }
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

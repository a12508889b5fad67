// tiershade glue: the GLSL source assembler.
// Resolves #include "file" from the shader library, prepends the target's
// #version, precision and portability lines and the variant's #defines, and
// emits #line directives whose source-string number indexes `files`, so that a
// compiler message "3:17(5): error" can be mapped back to "shaders/x.glsl:17".
#pragma once
#include <string>
#include <utility>
#include <vector>

enum class Target { ESSL100, ESSL300, GLSL330 };
enum class Stage { Vertex, Fragment };

const char *target_name(Target t);
bool parse_target(const std::string &s, Target *out);

struct Define { std::string name; std::string value; };

struct Assembled {
  std::string text;
  std::vector<std::string> files;  // source-string number -> "shaders/<file>"
};

// Reads a library file by name (embedded copy, or $TIERSHADE_SHADER_DIR/<name> when set).
bool shader_library_read(const std::string &name, std::string *out);
std::vector<std::string> shader_library_files();

// float_precision: "highp" (always, where results are compared with C) or "mediump"
// (accuracy studies: llvmpipe computes mediump in fp16 on GLES).
bool assemble(const std::string &entry, Target target, Stage stage, const std::vector<Define> &defines,
              Assembled *out, std::string *err, const std::string &float_precision = "highp");

// Rewrites a Mesa/glslang info log so that "N:L(C)" prefixes name the original file and line.
std::string map_compile_log(const std::string &log, const Assembled &a);

// tiershade shaderlib: the GLSL source assembler.
// Resolves #include "file" from the shader library and writes, in order: the target's
// #version, the entry file's #extension lines, the defines that select target, stage and
// float precision (TS_ESSL100|TS_ESSL300|TS_GLSL330, TS_VERTEX|TS_FRAGMENT,
// TS_FLOAT_PRECISION), the variant's #defines, the portability header
// shaders/ts_portability.glsl, then the entry file. #line directives carry a source-string
// number that indexes `files` (0 is the entry file, 1 the portability header), so that a
// compiler message "3:17(5): error" can be mapped back to "shaders/x.glsl:17".
#pragma once
#include <string>
#include <utility>
#include <vector>

enum class Target { ESSL100, ESSL300, GLSL330 };
enum class Stage { Vertex, Fragment };

const char *target_name(Target t);
bool parse_target(const std::string &s, Target *out);

struct Define {
  std::string name;
  std::string value;
};

// The shim header every assembled shader starts with ("ts_portability.glsl").
extern const char *const kPortabilityHeader;

struct Assembled {
  std::string text;
  std::vector<std::string> files;  // source-string number -> "shaders/<file>"
};

// Reads a library file by name (embedded copy, or $TIERSHADE_SHADER_DIR/<name> when set).
bool shader_library_read(const std::string &name, std::string *out);
std::vector<std::string> shader_library_files();

// float_precision: "highp" (always, where results are compared with C) or "mediump"
// (accuracy studies: llvmpipe computes mediump in fp16 on GLES).
bool assemble(const std::string &entry, Target target, Stage stage, const std::vector<Define> &defines, Assembled *out,
              std::string *err, const std::string &float_precision = "highp");

// Rewrites a Mesa/glslang info log so that "N:L(C)" prefixes name the original file and line.
std::string map_compile_log(const std::string &log, const Assembled &a);

// tiershade glue: GLSL source assembler (see assembler.h).
// Portability layer in the spirit of bgfx's shader macros: the library code uses
// TS_VARYING_IN/OUT, TS_ATTRIBUTE, TS_TEX2D, TS_FRAG_COLOR, and every target
// gets `precision highp` so GLES results can be compared with C float32
// (llvmpipe computes mediump in fp16: ../shared/docs/platform_notes.md section 3).
#include "shaderlib/assembler.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "shaderlib/shader_sources.h"

const char *target_name(Target t) {
  switch (t) {
    case Target::ESSL100: return "essl100";
    case Target::ESSL300: return "essl300";
    case Target::GLSL330: return "glsl330";
  }
  return "?";
}
bool parse_target(const std::string &s, Target *out) {
  if (s == "essl100") *out = Target::ESSL100;
  else if (s == "essl300") *out = Target::ESSL300;
  else if (s == "glsl330") *out = Target::GLSL330;
  else return false;
  return true;
}

bool shader_library_read(const std::string &name, std::string *out) {
  if (const char *dir = std::getenv("TIERSHADE_SHADER_DIR")) {
    std::ifstream f(std::string(dir) + "/" + name, std::ios::binary);
    if (!f) return false;
    std::ostringstream ss;
    ss << f.rdbuf();
    *out = ss.str();
    return true;
  }
  for (const EmbeddedFile *e = kShaderFiles; e->name; ++e) {
    if (name == e->name) {
      *out = e->text;
      return true;
    }
  }
  return false;
}

std::vector<std::string> shader_library_files() {
  std::vector<std::string> v;
  for (const EmbeddedFile *e = kShaderFiles; e->name; ++e) v.push_back(e->name);
  return v;
}

namespace {

std::string prelude(Target t, Stage s, const std::string &prec) {
  std::ostringstream o;
  switch (t) {
    case Target::ESSL100:
      o << "#version 100\n";
      o << "precision " << prec << " float;\nprecision highp int;\n";
      // Samplers default to lowp in ES fragment shaders, and llvmpipe really returns
      // fp16 texels for them: every compared value must be highp.
      o << "precision highp sampler2D;\nprecision highp samplerCube;\n";
      o << "#define TS_ESSL100 1\n";
      if (s == Stage::Vertex) {
        o << "#define TS_ATTRIBUTE attribute\n#define TS_VARYING_OUT varying\n";
      } else {
        o << "#define TS_VARYING_IN varying\n#define TS_FRAG_COLOR gl_FragColor\n";
        o << "#define TS_DECLARE_FRAG_COLOR\n";
      }
      o << "#define TS_TEX2D(s, uv) texture2D(s, uv)\n#define TS_TEXCUBE(s, d) textureCube(s, d)\n";
      break;
    case Target::ESSL300:
    case Target::GLSL330:
      o << (t == Target::ESSL300 ? "#version 300 es\n" : "#version 330 core\n");
      o << "precision " << prec << " float;\nprecision highp int;\n";
      if (t == Target::ESSL300) o << "precision highp sampler2D;\nprecision highp samplerCube;\n";
      o << (t == Target::ESSL300 ? "#define TS_ESSL300 1\n" : "#define TS_GLSL330 1\n");
      o << "#define TS_HAS_TEXEL_FETCH 1\n";
      if (s == Stage::Vertex) {
        o << "#define TS_ATTRIBUTE in\n#define TS_VARYING_OUT out\n";
      } else {
        o << "#define TS_VARYING_IN in\n#define TS_FRAG_COLOR ts_FragColor\n";
        o << "#define TS_DECLARE_FRAG_COLOR out vec4 ts_FragColor;\n";
      }
      o << "#define TS_TEX2D(s, uv) texture(s, uv)\n#define TS_TEXCUBE(s, d) texture(s, d)\n";
      break;
  }
  return o.str();
}

// Recognises `#include "name"` (spaces allowed around '#' and the keyword).
bool parse_include(const std::string &line, std::string *name) {
  size_t p = line.find_first_not_of(" \t");
  if (p == std::string::npos || line[p] != '#') return false;
  p = line.find_first_not_of(" \t", p + 1);
  if (p == std::string::npos || line.compare(p, 7, "include") != 0) return false;
  p = line.find_first_not_of(" \t", p + 7);
  if (p == std::string::npos || line[p] != '"') return false;
  const size_t q = line.find('"', p + 1);
  if (q == std::string::npos || q == p + 1) return false;
  if (line.find_first_not_of(" \t\r", q + 1) != std::string::npos) return false;
  *name = line.substr(p + 1, q - p - 1);
  return true;
}

// True for an `#extension NAME : behavior` directive line.
bool is_extension_directive(const std::string &line) {
  size_t p = line.find_first_not_of(" \t");
  if (p == std::string::npos || line[p] != '#') return false;
  p = line.find_first_not_of(" \t", p + 1);
  return p != std::string::npos && line.compare(p, 9, "extension") == 0;
}

// `extensions` collects the entry file's #extension lines (depth 0): ESSL (and Mesa for every
// version) wants them before any non-preprocessor token, so assemble() puts them right after
// #version, ahead of the prelude's precision statements; a blank line keeps their place.
bool expand(const std::string &name, int depth, std::vector<std::string> &stack, Assembled *out,
            std::ostringstream &o, std::string *err, const std::string &from, std::string *extensions) {
  if (depth > 16) {
    *err = from + ": includes nested deeper than 16 levels";
    return false;
  }
  for (const auto &s : stack) {
    if (s == name) {
      *err = from + ": include cycle through " + name;
      return false;
    }
  }
  std::string text;
  if (!shader_library_read(name, &text)) {
    *err = from + ": cannot find shader file '" + name + "'";
    return false;
  }
  int id = -1;
  for (size_t i = 0; i < out->files.size(); ++i)
    if (out->files[i] == "shaders/" + name) id = static_cast<int>(i);
  if (id < 0) {
    id = static_cast<int>(out->files.size());
    out->files.push_back("shaders/" + name);
  }
  stack.push_back(name);
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  o << "#line 1 " << id << "\n";
  while (std::getline(in, line)) {
    ++lineno;
    std::string child;
    if (parse_include(line, &child)) {
      if (!expand(child, depth + 1, stack, out, o, err, "shaders/" + name + ":" + std::to_string(lineno),
                  extensions))
        return false;
      o << "#line " << (lineno + 1) << " " << id << "\n";
    } else if (depth == 0 && is_extension_directive(line)) {
      *extensions += line + "\n";
      o << "\n";
    } else {
      o << line << "\n";
    }
  }
  stack.pop_back();
  return true;
}

}  // namespace

bool assemble(const std::string &entry, Target target, Stage stage, const std::vector<Define> &defines,
              Assembled *out, std::string *err, const std::string &float_precision) {
  *out = Assembled();
  if (float_precision != "highp" && float_precision != "mediump" && float_precision != "lowp") {
    *err = "unknown float precision '" + float_precision + "'";
    return false;
  }
  std::ostringstream o;
  const std::string pre = prelude(target, stage, float_precision);
  const size_t version_end = pre.find('\n') + 1;  // the prelude starts with the #version line
  o << pre.substr(version_end);
  for (const auto &d : defines) o << "#define " << d.name << " " << d.value << "\n";
  std::vector<std::string> stack;
  std::string extensions;
  if (!expand(entry, 0, stack, out, o, err, "assembler", &extensions)) return false;
  out->text = pre.substr(0, version_end) + extensions + o.str();
  return true;
}

// Finds the first "S:L:" or "S:L(C):" location (S, L decimal, at the line start or after
// a blank) and rewrites it to "shaders/<file>:L:".
static bool map_location(std::string *line, const Assembled &a) {
  const std::string &s = *line;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!isdigit(static_cast<unsigned char>(s[i])) || (i > 0 && !isspace(static_cast<unsigned char>(s[i - 1]))))
      continue;
    size_t j = i;
    while (j < s.size() && isdigit(static_cast<unsigned char>(s[j]))) ++j;
    if (j >= s.size() || s[j] != ':' || j - i > 6) continue;
    size_t k = j + 1;
    while (k < s.size() && isdigit(static_cast<unsigned char>(s[k]))) ++k;
    if (k == j + 1 || k - j > 8) continue;
    size_t e = k;
    if (e < s.size() && s[e] == '(') {
      const size_t close = s.find(')', e);
      if (close == std::string::npos) continue;
      e = close + 1;
    }
    if (e >= s.size() || s[e] != ':') continue;
    const size_t id = std::stoul(s.substr(i, j - i));
    if (id >= a.files.size()) return false;
    *line = s.substr(0, i) + a.files[id] + ":" + s.substr(j + 1, k - j - 1) + ":" + s.substr(e + 1);
    return true;
  }
  return false;
}

std::string map_compile_log(const std::string &log, const Assembled &a) {
  // Mesa: "3:17(5): error: ..."; glslang: "ERROR: 3:17: ...".
  std::string result;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    map_location(&line, a);
    result += line + "\n";
  }
  return result;
}

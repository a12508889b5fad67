// tiershade shaderlib: GLSL source assembler (see assembler.h).
// The language differences between targets live in shaders/ts_portability.glsl; this file
// writes only #version and the defines that select the target, stage and precision.
#include "shaderlib/assembler.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "base/enum_names.h"
#include "shaderlib/shader_sources.h"

static const EnumName<Target> kTargetNames[] = {
    {Target::ESSL100, "essl100"}, {Target::ESSL300, "essl300"}, {Target::GLSL330, "glsl330"}};

const char *target_name(Target t) { return enum_name(kTargetNames, t); }
bool parse_target(const std::string &s, Target *out) { return enum_parse(kTargetNames, s, out); }

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

// The lines that select the target, the stage and the float precision, after #version: what
// shaders/ts_portability.glsl (kPortabilityHeader) turns into each target's words.
std::string selection_defines(Target t, Stage s, const std::string &prec) {
  std::string o;
  switch (t) {
    case Target::ESSL100:
      o += "#define TS_ESSL100 1\n";
      break;
    case Target::ESSL300:
      o += "#define TS_ESSL300 1\n";
      break;
    case Target::GLSL330:
      o += "#define TS_GLSL330 1\n";
      break;
  }
  o += s == Stage::Vertex ? "#define TS_VERTEX 1\n" : "#define TS_FRAGMENT 1\n";
  o += "#define TS_FLOAT_PRECISION " + prec + "\n";
  return o;
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
// #version, ahead of the portability header's precision statements; a blank line keeps their
// place.
bool expand(const std::string &name, int depth, std::vector<std::string> &stack, Assembled *out, std::ostringstream &o,
            std::string *err, const std::string &from, std::string *extensions) {
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
      if (!expand(child, depth + 1, stack, out, o, err, "shaders/" + name + ":" + std::to_string(lineno), extensions))
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

const char *const kPortabilityHeader = "ts_portability.glsl";

bool assemble(const std::string &entry, Target target, Stage stage, const std::vector<Define> &defines, Assembled *out,
              std::string *err, const std::string &float_precision) {
  *out = Assembled();
  if (float_precision != "highp" && float_precision != "mediump" && float_precision != "lowp") {
    *err = "unknown float precision '" + float_precision + "'";
    return false;
  }
  const char *version = target == Target::ESSL100 ? "#version 100\n"
      : target == Target::ESSL300                 ? "#version 300 es\n"
                                                  : "#version 330 core\n";
  std::ostringstream o;
  o << selection_defines(target, stage, float_precision);
  for (const auto &d : defines) o << "#define " << d.name << " " << d.value << "\n";
  // Source string 0 is the entry file (compiler messages "0:L" name it), the header comes next.
  out->files.push_back("shaders/" + entry);
  std::vector<std::string> stack;
  std::string extensions, header_extensions;
  if (!expand(kPortabilityHeader, 0, stack, out, o, err, "assembler (portability header)", &header_extensions))
    return false;
  if (!header_extensions.empty()) {
    *err = std::string("shaders/") + kPortabilityHeader + ": #extension belongs in the shader that needs it";
    return false;
  }
  if (!expand(entry, 0, stack, out, o, err, "assembler", &extensions)) return false;
  out->text = version + extensions + o.str();
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

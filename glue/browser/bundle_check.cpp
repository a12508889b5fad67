// tiershade browser: bundle manifests against Chromium's reflection (see bundle_check.h).
#include "browser/bundle_check.h"

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "browser/chromium.h"
#include "gl/type_names.h"
#include "shaderlib/assembler.h"

using json = nlohmann::json;

namespace {

bool read_text(const std::string &path, std::string *out, std::string *err) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *err = path + ": cannot open";
    return false;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  *out = ss.str();
  return true;
}

// One declared entry: type, declared array size (0: not an array); and Mesa's reflection of it.
struct Declared {
  std::string type;
  int array_size = 0;
  bool trim_listed = false;  // under may_trim
  int mesa_size = 1;  // what Mesa reported: 0 not active, else the size (arrays: elements)
};

struct Program {
  std::string where;  // "DIR: shader name"
  int webgl = 0;
  std::string vs, fs;
  std::vector<std::string> attribute_order;
  std::map<std::string, Declared> attributes, uniforms;  // uniforms holds the samplers too
};

// The manifest's variants as programs, their declared interface and may_trim.
bool read_bundle(const std::string &dir, std::vector<Program> *out, bool *skipped, std::string *err) {
  const std::string mpath = dir + "/manifest.json";
  std::string text;
  if (!read_text(mpath, &text, err)) return false;
  json m;
  try {
    m = json::parse(text);
  } catch (const std::exception &e) {
    *err = mpath + ": not JSON (" + e.what() + ")";
    return false;
  }
  try {
    const std::string target = m.at("target").get<std::string>();
    if (target != "essl100" && target != "essl300") {
      *skipped = true;
      return true;
    }
    *skipped = false;
    const int webgl = target == "essl100" ? 1 : 2;
    const json &vars = m.at("variants");
    for (size_t i = 0; i < vars.size(); ++i) {
      const json &v = vars[i];
      Program p;
      p.where = dir + ": " + v.at("shader").get<std::string>() + " " + v.at("name").get<std::string>();
      p.webgl = webgl;
      if (!read_text(dir + "/" + v.at("vertex").get<std::string>(), &p.vs, err) ||
          !read_text(dir + "/" + v.at("fragment").get<std::string>(), &p.fs, err))
        return false;
      for (const json &a : v.at("attributes")) {
        const std::string n = a.at("name").get<std::string>();
        p.attribute_order.push_back(n);
        p.attributes[n].type = a.at("type").get<std::string>();
      }
      for (const json &u : v.at("uniforms")) {
        Declared &d = p.uniforms[u.at("name").get<std::string>()];
        d.type = u.at("type").get<std::string>();
        d.array_size = u.at("array_size").get<int>();
        d.mesa_size = d.array_size ? d.array_size : 1;
      }
      for (const json &s : v.at("samplers")) p.uniforms[s.at("name").get<std::string>()].type = s.at("type").get<std::string>();
      const json &t = v.at("may_trim");
      auto listed = [&](std::map<std::string, Declared> &in, const std::string &n, int mesa, const char *what) {
        auto it = in.find(n);
        if (it == in.end()) {
          *err = mpath + ": variants[" + std::to_string(i) + "].may_trim." + what + ": '" + n +
                 "' is not in the declared interface";
          return false;
        }
        it->second.trim_listed = true;
        it->second.mesa_size = mesa;
        return true;
      };
      for (const json &a : t.at("attributes"))
        if (!listed(p.attributes, a.get<std::string>(), 0, "attributes")) return false;
      for (const json &u : t.at("uniforms"))
        if (!listed(p.uniforms, u.at("name").get<std::string>(), u.at("array_size").get<int>(), "uniforms")) return false;
      for (const json &s : t.at("samplers"))
        if (!listed(p.uniforms, s.get<std::string>(), 0, "samplers")) return false;
      out->push_back(std::move(p));
    }
  } catch (const std::exception &e) {
    *err = mpath + ": " + e.what();
    return false;
  }
  return true;
}

// What the page reported for one program: name -> (type name, size), arrays by their base name.
struct Active {
  std::string type;
  int size = 1;
  bool array = false;
};

bool parse_active(const json &list, std::map<std::string, Active> *out, std::string *err) {
  for (const json &e : list) {
    std::string name = e.at(0).get<std::string>();
    Active a;
    const unsigned type = e.at(1).get<unsigned>();
    a.type = gl_type_glsl_name(static_cast<GLenum>(type));
    if (a.type.empty()) a.type = "GL type 0x" + [&] {
      char b[16];
      snprintf(b, sizeof b, "%x", type);
      return std::string(b);
    }();
    a.size = e.at(2).get<int>();
    if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0) {
      name.resize(name.size() - 3);
      a.array = true;
    }
    if (out->count(name)) {
      *err = "the browser reported '" + name + "' twice";
      return false;
    }
    (*out)[name] = a;
  }
  return true;
}

// Checks one program's active set against its manifest entry (adds to out's counts and problems).
void check_program(const Program &p, const std::map<std::string, Active> &attrs,
                   const std::map<std::string, Active> &unis, bool distinct, BundleCheckOutcome *out) {
  bool differs = false;
  std::string diff;
  auto check = [&](const char *what, const std::map<std::string, Declared> &decl, const std::map<std::string, Active> &act) {
    for (const auto &a : act) {
      if (distinct) ++out->active_entries;
      const auto it = decl.find(a.first);
      const std::string entry = std::string(what) + " '" + a.first + "' (" + a.second.type + ", size " +
                                std::to_string(a.second.size) + ")";
      if (it == decl.end()) {
        ++out->outside_declared;
        out->problems.push_back(p.where + ": active " + entry + " is not in the declared interface");
        differs = true;
        diff += " +" + a.first;
        continue;
      }
      const Declared &d = it->second;
      const bool size_ok = d.array_size ? a.second.size <= d.array_size : (a.second.size == 1 && !a.second.array);
      if (d.type != a.second.type || !size_ok) {
        ++out->outside_declared;
        out->problems.push_back(p.where + ": active " + entry + " against the declared " + d.type +
                                (d.array_size ? "[" + std::to_string(d.array_size) + "]" : std::string()));
      }
      if (a.second.size != d.mesa_size) {
        differs = true;
        diff += " " + a.first + (d.mesa_size ? "[" + std::to_string(a.second.size) + " vs Mesa's " +
                                                   std::to_string(d.mesa_size) + "]"
                                             : " (Mesa: inactive)");
      }
    }
    for (const auto &d : decl) {
      const auto it = act.find(d.first);
      const int full = d.second.array_size ? d.second.array_size : 1;
      if (it == act.end() && d.second.mesa_size) {
        differs = true;
        diff += " -" + d.first;
      }
      if (it != act.end() && it->second.size == full) continue;
      if (d.second.trim_listed) {
        ++out->trimmed_by_browser;
        continue;
      }
      ++out->required_inactive;
      out->problems.push_back(p.where + ": declared " + what + " '" + d.first + "' (" + d.second.type +
                              (d.second.array_size ? "[" + std::to_string(d.second.array_size) + "]" : std::string()) +
                              ") is not under may_trim but the browser reports it " +
                              (it == act.end() ? std::string("inactive") : "at size " + std::to_string(it->second.size)));
    }
  };
  check("attribute", p.attributes, attrs);
  check("uniform", p.uniforms, unis);
  if (differs && distinct) {
    ++out->differ_from_mesa;
    out->mesa_differences.push_back(p.where + ":" + diff);
  }
}

}  // namespace

bool check_bundles_in_chromium(const std::vector<std::string> &dirs, int timeout_s, BundleCheckOutcome *out,
                               std::string *err) {
  std::vector<Program> programs;
  for (const auto &d : dirs) {
    bool skipped = false;
    if (!read_bundle(d, &programs, &skipped, err)) return false;
    ++out->bundles;
    if (skipped) ++out->skipped_bundles;
  }
  out->programs = static_cast<int>(programs.size());
  // Distinct programs: the same sources and the same manifest entry (scenes share variants).
  std::map<std::string, size_t> first;
  std::vector<size_t> job_of(programs.size());
  json job = {{"programs", json::array()}};
  std::vector<size_t> job_program;
  for (size_t i = 0; i < programs.size(); ++i) {
    const Program &p = programs[i];
    const std::string key = std::to_string(p.webgl) + "\n" + p.vs + "\n" + p.fs;
    auto it = first.find(key);
    if (it != first.end()) {
      job_of[i] = it->second;
      continue;
    }
    job_of[i] = job_program.size();
    first[key] = job_program.size();
    job_program.push_back(i);
    job["programs"].push_back({{"webgl", p.webgl}, {"vs", p.vs}, {"fs", p.fs}, {"attributes", p.attribute_order}});
  }
  out->distinct = static_cast<int>(job_program.size());
  if (job_program.empty()) return true;
  std::string html, js;
  if (!shader_library_read("glue/browser/webgl_reflect.html", &html) ||
      !shader_library_read("glue/browser/webgl_reflect.js", &js)) {
    *err = "the reflection page (glue/browser/webgl_reflect.html, .js) is not in this binary";
    return false;
  }
  std::string text;
  if (!chromium_run_page({{"webgl_reflect.html", html}, {"webgl_reflect.js", js}, {"job.js", "var TS_JOB = " + job.dump() + ";\n"}},
                         "webgl_reflect.html", timeout_s, &text, err))
    return false;
  std::vector<json> result(job_program.size());
  std::vector<std::string> failed(job_program.size());
  bool done = false;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line == "DONE") {
      done = true;
    } else if (line.compare(0, 2, "I ") == 0 && line.size() > 4) {
      out->renderer[line[2] == '1' ? 1 : 2] = line.substr(4);
    } else if (line.compare(0, 2, "X ") == 0) {
      *err = "the reflection page failed: " + line.substr(2);
      return false;
    } else if (line.compare(0, 2, "P ") == 0 || line.compare(0, 2, "E ") == 0) {
      char *end = nullptr;
      const long k = strtol(line.c_str() + 2, &end, 10);
      if (!end || *end != ' ' || k < 0 || static_cast<size_t>(k) >= job_program.size()) {
        *err = "the reflection page wrote a line for no program: " + line.substr(0, 80);
        return false;
      }
      try {
        if (line[0] == 'E')
          failed[k] = json::parse(end + 1).get<std::string>();
        else
          result[k] = json::parse(end + 1);
      } catch (const std::exception &e) {
        *err = "the reflection page wrote a malformed line (" + std::string(e.what()) + "): " + line.substr(0, 80);
        return false;
      }
    }
  }
  if (!done) {
    *err = "the reflection page did not run to its end (no DONE line)";
    return false;
  }
  // Every manifest entry is checked (a shared program's entries in two bundles could differ); the
  // counts of active entries and of differences from Mesa are per distinct program.
  for (size_t i = 0; i < programs.size(); ++i) {
    const size_t k = job_of[i];
    const Program &p = programs[i];
    if (!failed[k].empty()) {
      out->problems.push_back(p.where + ": does not build in WebGL " + std::to_string(p.webgl) + ": " + failed[k]);
      continue;
    }
    std::map<std::string, Active> attrs, unis;
    try {
      if (!parse_active(result[k].at("attributes"), &attrs, err) || !parse_active(result[k].at("uniforms"), &unis, err)) {
        *err = p.where + ": " + *err;
        return false;
      }
    } catch (const std::exception &e) {
      *err = p.where + ": the reflection page's result: " + e.what();
      return false;
    }
    check_program(p, attrs, unis, job_program[k] == i, out);
  }
  return true;
}

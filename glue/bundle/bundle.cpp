// tiershade bundle: shader bundles for engines (see bundle.h and docs/bundles.md).
#include "bundle/bundle.h"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "budget/budget.h"
#include "io/atomic_dir.h"
#include "families/family.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/type_names.h"
#include "gl/program_info.h"

using json = nlohmann::ordered_json;

std::string bundle_file_stem(const Variant &v) {
  uint32_t h = 2166136261u;  // FNV-1a, 32 bits
  for (unsigned char c : v.name()) {
    h ^= c;
    h *= 16777619u;
  }
  char b[16];
  snprintf(b, sizeof b, "%08x", h);
  return std::string(tier_name(v.tier)) + "_" + b;
}

namespace {

Api api_for(Target t) { return t == Target::ESSL100 ? Api::GLES2 : t == Target::ESSL300 ? Api::GLES3 : Api::GL33; }

const char *glsl_version(Target t) {
  return t == Target::ESSL100 ? "100" : t == Target::ESSL300 ? "300 es" : "330 core";
}

// One variant: sources, GL introspection and slots -> its manifest entry.
bool bundle_variant(GlRenderer &r, Target target, const BundleEntry &e, DirWriter &w, json *out, std::string *err) {
  const Variant &v = *e.variant;
  const std::string where = v.shader->name + " " + v.name() + ": ";
  const auto defs = variant_defines(v, InputMode::Production);
  Assembled vs, fs, fs330;
  if (!assemble(v.shader->vertex, target, Stage::Vertex, defs, &vs, err) ||
      !assemble(v.shader->fragment, target, Stage::Fragment, defs, &fs, err) ||
      !assemble(v.shader->fragment, Target::GLSL330, Stage::Fragment, defs, &fs330, err)) {
    *err = where + *err;
    return false;
  }
  const GLuint prog = r.build_program(vs, fs, err);
  if (!prog) {
    *err = where + *err;
    return false;
  }
  std::vector<ProgramVar> attribs, uniforms;
  const bool ok = program_attributes(r.gl(), prog, &attribs, err) && program_uniforms(r.gl(), prog, &uniforms, err);
  r.delete_program(prog);
  if (!ok) {
    *err = where + *err;
    return false;
  }
  BudgetCounts slots;
  if (!budget_count_fragment(fs330.text, &slots, err)) {
    *err = where + "slot count: " + *err;
    return false;
  }
  const std::string stem = v.shader->name + "/" + bundle_file_stem(v);
  if (!w.mkdir(v.shader->name, err) || !w.write(stem + ".vert", vs.text, err) || !w.write(stem + ".frag", fs.text, err))
    return false;

  json j;
  j["shader"] = v.shader->name;
  j["tier"] = tier_name(v.tier);
  j["name"] = v.name();
  j["vertex"] = stem + ".vert";
  j["fragment"] = stem + ".frag";
  json d = json::object();
  for (const auto &def : defs) d[def.name] = std::stoi(def.value);
  j["defines"] = d;
  j["why"] = e.why;
  json ja = json::array();
  for (const auto &a : attribs) ja.push_back({{"name", a.name}, {"type", gl_type_glsl_name(a.type)}});
  j["attributes"] = ja;
  json ju = json::array(), js = json::array();
  for (const auto &u : uniforms) {
    if (gl_type_is_sampler(u.type)) {
      const int unit = static_cast<int>(js.size());
      js.push_back({{"name", u.name}, {"type", gl_type_glsl_name(u.type)}, {"unit", unit}});
    } else {
      ju.push_back(
          {{"name", u.name}, {"type", gl_type_glsl_name(u.type)}, {"array_size", u.is_array ? u.array_size : 0}});
    }
  }
  j["uniforms"] = ju;
  j["samplers"] = js;
  json o = {{"name", target == Target::ESSL100 ? "gl_FragColor" : "ts_FragColor"}, {"type", "vec4"}};
  if (target != Target::ESSL100) o["location"] = 0;
  j["outputs"] = json::array({o});
  j["slots"] = {{"alu", slots.alu}, {"tex", slots.tex}};
  *out = j;
  return true;
}

}  // namespace

bool write_bundle(const std::vector<BundleEntry> &entries, Target target, const std::string &dir,
                  const std::string &source_desc, std::string *err) {
  for (const auto &e : entries) {
    if (!e.variant || !e.variant->shader) {
      *err = "internal: a bundle entry without a variant";
      return false;
    }
  }
  DirWriter w;
  if (!w.begin(dir, "manifest.json", "bundle", err)) return false;
  auto ctx = GlContext::create(Backend::EGL, api_for(target), err);
  if (!ctx) {
    *err = std::string("EGL ") + api_name(api_for(target)) + " context for " + target_name(target) + ": " + *err;
    return false;
  }
  json variants = json::array();
  {
    GlRenderer r(*ctx);
    std::set<std::string> done;
    for (const auto &e : entries) {
      const std::string key = e.variant->shader->name + "|" + e.variant->name();
      if (!done.insert(key).second) continue;
      json j;
      if (!bundle_variant(r, target, e, w, &j, err)) return false;
      variants.push_back(j);
    }
  }
  json m;
  m["tiershade_bundle"] = 1;
  m["target"] = target_name(target);
  m["glsl_version"] = glsl_version(target);
  m["api"] = api_name(api_for(target));
  m["source"] = source_desc;
  m["sampler_units"] = "each variant's samplers in the listed order (sorted by name) take units 0..n-1";
  m["variants"] = variants;
  if (!w.write("manifest.json", m.dump(2) + "\n", err)) return false;
  return w.commit(err);
}

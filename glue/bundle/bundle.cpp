// tiershade bundle: shader bundles for engines (see bundle.h and docs/bundles.md).
#include "bundle/bundle.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "budget/budget.h"
#include "budget/interface.h"
#include "bundle/webgl.h"
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
  bool offered = true;
  std::string why_not;
  if (!target_offers(v, target, &offered, &why_not, err)) {
    *err = where + *err;
    return false;
  }
  if (!offered) {
    *err = where + "not offered on " + target_name(target) + ": " + why_not;
    return false;
  }
  // The declared interface, from the GLSL 3.30 text of both stages (the declarations are the same
  // on every target: ts_portability.glsl changes only how textures are read and written).
  Assembled vs330;
  ProgramInterface iface;
  if (!assemble(v.shader->vertex, Target::GLSL330, Stage::Vertex, defs, &vs330, err) ||
      !reflect_program(vs330.text, fs330.text, &iface, err)) {
    *err = where + "declared interface: " + *err;
    return false;
  }
  std::vector<ExtensionNeed> exts;
  if (!variant_extensions(v, target, &iface, &exts, err)) {
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
  // Mesa's active set must lie inside the declared interface (a name, type and size it reports
  // beyond the source's declarations would be a reflection bug here).
  json trim_a = json::array(), trim_u = json::array(), trim_s = json::array();
  auto find_gl = [](const std::vector<ProgramVar> &vars, const std::string &name) -> const ProgramVar * {
    for (const auto &x : vars)
      if (x.name == name) return &x;
    return nullptr;
  };
  auto declared = [&](const std::vector<InterfaceVar> &d, const ProgramVar &g) {
    for (const auto &x : d)
      if (x.name == g.name)
        return x.type == gl_type_glsl_name(g.type) && (x.array_size ? x.array_size >= g.array_size : !g.is_array);
    return false;
  };
  for (const auto &g : attribs)
    if (!declared(iface.attributes, g)) {
      *err = where + "Mesa reports attribute '" + g.name + "', not in the declared interface";
      return false;
    }
  for (const auto &g : uniforms)
    if (!declared(gl_type_is_sampler(g.type) ? iface.samplers : iface.uniforms, g)) {
      *err = where + "Mesa reports uniform '" + g.name + "' (" + gl_type_glsl_name(g.type) +
          "), not in the declared interface";
      return false;
    }
  for (const auto &a : iface.attributes)
    if (!find_gl(attribs, a.name)) trim_a.push_back(a.name);
  for (const auto &u : iface.uniforms) {
    const ProgramVar *g = find_gl(uniforms, u.name);
    if (!g)
      trim_u.push_back({{"name", u.name}, {"array_size", 0}});
    else if (u.array_size && g->array_size < u.array_size)
      trim_u.push_back({{"name", u.name}, {"array_size", g->array_size}});
  }
  for (const auto &u : iface.samplers)
    if (!find_gl(uniforms, u.name)) trim_s.push_back(u.name);

  const std::string stem = v.shader->name + "/" + bundle_file_stem(v);
  if (!w.mkdir(v.shader->name, err) || !w.write(stem + ".vert", vs.text, err) || !w.write(stem + ".frag", fs.text, err))
    return false;

  auto stages = [](const InterfaceVar &x) {
    json st = json::array();
    if (x.vertex) st.push_back("vertex");
    if (x.fragment) st.push_back("fragment");
    return st;
  };
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
  // Attributes in the order a_position, a_normal, a_uv, a_tangent, a_lightmap, a_corner, then by name.
  static const char *kOrder[] = {"a_position", "a_normal", "a_uv", "a_tangent", "a_lightmap", "a_corner"};
  std::vector<const InterfaceVar *> attr_order;
  for (const char *n : kOrder)
    for (const auto &a : iface.attributes)
      if (a.name == n) attr_order.push_back(&a);
  for (const auto &a : iface.attributes)
    if (std::find(std::begin(kOrder), std::end(kOrder), a.name) == std::end(kOrder)) attr_order.push_back(&a);
  json ja = json::array();
  for (const auto *a : attr_order) ja.push_back({{"name", a->name}, {"type", a->type}});
  j["attributes"] = ja;
  json ju = json::array(), js = json::array();
  for (const auto &u : iface.uniforms)
    ju.push_back({{"name", u.name}, {"type", u.type}, {"array_size", u.array_size}, {"stages", stages(u)}});
  for (const auto &u : iface.samplers)
    js.push_back({{"name", u.name}, {"type", u.type}, {"unit", static_cast<int>(js.size())}, {"stages", stages(u)}});
  j["uniforms"] = ju;
  j["samplers"] = js;
  j["may_trim"] = {{"reported_by", std::string("Mesa llvmpipe, ") + api_name(api_for(target))},
                   {"attributes", trim_a},
                   {"uniforms", trim_u},
                   {"samplers", trim_s}};
  json o = {{"name", target == Target::ESSL100 ? "gl_FragColor" : "ts_FragColor"}, {"type", "vec4"}};
  if (target != Target::ESSL100) o["location"] = 0;
  j["outputs"] = json::array({o});
  json je = json::array();
  for (const auto &x : exts) {
    json one = {{"name", x.name}};
    if (!x.alternatives.empty()) one["or"] = x.alternatives;
    one["why"] = x.why;
    je.push_back(one);
  }
  j["extensions"] = je;
  j["slots"] = {{"alu", slots.alu}, {"tex", slots.tex}};
  j["constant_registers"] = slots.constants;
  int vert_vectors = 0;
  for (const auto &u : iface.uniforms)
    if (u.vertex) vert_vectors += u.registers(false);
  j["uniform_vectors"] = {{"vertex", vert_vectors}, {"fragment", fragment_uniform_vectors(iface)}};
  j["texture_units"] = {{"fragment", [&] {
                           int n = 0;
                           for (const auto &u : iface.samplers) n += u.fragment ? (u.array_size ? u.array_size : 1) : 0;
                           return n;
                         }()}};
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
  json all_ext = json::array();
  for (const auto &v : variants)
    for (const auto &x : v["extensions"])
      if (std::find(all_ext.begin(), all_ext.end(), x["name"]) == all_ext.end()) all_ext.push_back(x["name"]);
  m["extensions"] = all_ext;
  m["variants"] = variants;
  if (!w.write("manifest.json", m.dump(2) + "\n", err)) return false;
  return w.commit(err);
}

// tiershade tests: the declared program interface from source (glue/budget/interface.h), the DX9
// constant-register count of the budget, and what a browser needs for a variant
// (glue/bundle/webgl.h): sampler3D variants not offered on essl100, extensions derived from the
// samplers, outputs and geometry a variant uses. No GL context; about 1 s.
// Run: build/tests/test_interface. Prints "PASS name" / "FAIL name: detail"; exits 1 on a failure.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "budget/budget.h"
#include "budget/interface.h"
#include "bundle/webgl.h"
#include "families/family.h"
#include "shaderlib/variants.h"
#include "unit_check.h"

using unit_check::check;

namespace {

const InterfaceVar *find(const std::vector<InterfaceVar> &v, const std::string &name) {
  for (const auto &x : v)
    if (x.name == name) return &x;
  return nullptr;
}

std::string names(const std::vector<InterfaceVar> &v) {
  std::string s;
  for (const auto &x : v) s += x.name + "[" + std::to_string(x.array_size) + "/" + std::to_string(x.used_size) + "] ";
  return s;
}

const char kFragment[] = R"(#version 330 core
uniform vec4 u_const_index[20];   // elements 0 and 3 used: used size 4 of 20
uniform vec4 u_dynamic[8];        // indexed by a uniform: all 8
uniform mat4 u_matrix;            // 4 registers
uniform vec4 u_unused;            // declared, never used: not in the interface
uniform vec4 u_dead_function;     // used only in a function nobody calls
uniform vec4 u_vertex_only;       // fragment does not use it
uniform int u_index;
uniform sampler2D u_tex;          // used through a function parameter
uniform sampler2D u_tex_unused;
in vec2 v_uv;
out vec4 o;
vec4 sample_it(sampler2D s, vec2 p) { return texture(s, p); }
vec4 never_called() { return u_dead_function; }
void main() {
  o = u_const_index[0] + u_const_index[3] + u_dynamic[u_index] + u_matrix * vec4(v_uv, 0.0, 1.0)
      + sample_it(u_tex, v_uv);
}
)";

const char kVertex[] = R"(#version 330 core
in vec3 a_position;
in vec2 a_uv;
in vec3 a_unused;                 // declared, not read
uniform mat4 u_matrix;
uniform vec4 u_vertex_only;
out vec2 v_uv;
void main() {
  v_uv = a_uv + u_vertex_only.xy;
  gl_Position = u_matrix * vec4(a_position, 1.0);
}
)";

void test_reflection() {
  ProgramInterface f;
  std::string err;
  bool ok = reflect_stage(kFragment, false, &f, &err);
  check(ok, "reflect a fragment stage", err);
  if (!ok) return;
  const InterfaceVar *ci = find(f.uniforms, "u_const_index"), *dy = find(f.uniforms, "u_dynamic"),
                     *m = find(f.uniforms, "u_matrix");
  check(ci && ci->array_size == 20 && ci->used_size == 4 && ci->type == "vec4" && ci->fragment && !ci->vertex,
        "constant indices: declared 20, used 4", names(f.uniforms));
  check(dy && dy->array_size == 8 && dy->used_size == 8, "a dynamic index uses the declared size", names(f.uniforms));
  check(m && m->type == "mat4" && m->registers_per_element == 4 && m->array_size == 0, "mat4: 4 registers",
        names(f.uniforms));
  check(!find(f.uniforms, "u_unused") && !find(f.uniforms, "u_dead_function") && !find(f.uniforms, "u_vertex_only"),
        "declared but not statically used from main: absent", names(f.uniforms));
  check(f.samplers.size() == 1 && f.samplers[0].name == "u_tex" && f.samplers[0].type == "sampler2D",
        "a sampler passed to a function is used; an unused one is not", names(f.samplers));
  // u_const_index 4 + u_dynamic 8 + u_matrix 4 + u_index 1 = 17 registers; the WebGL measure
  // takes u_const_index at its declared 20: 20 + 8 + 4 + 1 = 33.
  check(fragment_constant_registers(f) == 17, "DX9 constant registers 4 + 8 + 4 + 1",
        std::to_string(fragment_constant_registers(f)));
  check(fragment_uniform_vectors(f) == 33, "fragment uniform vectors 20 + 8 + 4 + 1",
        std::to_string(fragment_uniform_vectors(f)));

  ProgramInterface p;
  ok = reflect_program(kVertex, kFragment, &p, &err);
  check(ok, "reflect a program", err);
  if (!ok) return;
  const InterfaceVar *pm = find(p.uniforms, "u_matrix"), *vo = find(p.uniforms, "u_vertex_only");
  check(pm && pm->vertex && pm->fragment, "a uniform of both stages is flagged for both", names(p.uniforms));
  check(vo && vo->vertex && !vo->fragment, "a vertex-only uniform", names(p.uniforms));
  check(p.attributes.size() == 2 && find(p.attributes, "a_position") && find(p.attributes, "a_uv") &&
            find(p.attributes, "a_uv")->type == "vec2",
        "attributes: the two read, not the unused one (nor gl_ built-ins)", names(p.attributes));
  check(!reflect_stage("#version 330 core\nout vec4 o;\nvoid main() { o = nope; }\n", false, &f, &err) &&
            err.find("nope") != std::string::npos,
        "a compile error names the identifier", err);
}

void test_budget_constants() {
  // 40 vec4s indexed dynamically: over ps_2_0's 32 constant registers.
  BudgetCounts c;
  std::string err;
  bool ok = budget_count_fragment(
      "#version 330 core\nuniform vec4 u[40];\nuniform int k;\nout vec4 o;\nvoid main() { o = u[k]; }\n", &c, &err);
  check(ok && c.constants == 41, "budget counts 40 + 1 constant registers", err + " " + std::to_string(c.constants));
  ok = budget_count_fragment("#version 330 core\nuniform vec4 u[40];\nout vec4 o;\nvoid main() { o = u[2]; }\n", &c, &err);
  check(ok && c.constants == 3, "a constant index counts the array to it", err + " " + std::to_string(c.constants));
}

void test_identifiers() {
  std::set<std::string> ids;
  std::string err;
  bool ok = preprocessed_identifiers(
      "#version 100\n#define A 0\n#if A\nuniform sampler3D s3;\n#endif\n// sampler3D in a comment\n"
      "precision highp float;\nuniform sampler2D s2;\nvoid main() { gl_FragColor = texture2D(s2, vec2(1.5e3)); }\n",
      false, &ids, &err);
  check(ok && !ids.count("sampler3D") && ids.count("sampler2D") && ids.count("texture2D") && !ids.count("e3"),
        "ESSL 1.00 preprocessed: #if and comments resolved", err);
}

const Variant *named(const std::vector<Variant> &vs, const std::string &name) {
  for (const auto &v : vs)
    if (v.name() == name) return &v;
  return nullptr;
}

bool has_ext(const std::vector<ExtensionNeed> &e, const std::string &name) {
  return std::any_of(e.begin(), e.end(), [&](const ExtensionNeed &x) { return x.name == name; });
}

std::string ext_names(const std::vector<ExtensionNeed> &e) {
  std::string s;
  for (const auto &x : e) s += x.name + " ";
  return s;
}

void test_webgl() {
  std::vector<ShaderDecl> decls;
  std::string err;
  if (!load_shader_decls(&decls, &err)) {
    check(false, "load shader declarations", err);
    return;
  }
  // Every colour-correction variant: essl100 offers exactly those with LUT_ATLAS = 1.
  for (const auto &d : decls) {
    if (d.name != "color_correction") continue;
    const auto vars = enumerate_variants(d, all_tiers(), &err);
    int wrong = 0, refused = 0;
    std::string detail;
    for (const auto &v : vars) {
      bool off100 = true, off300 = true;
      std::string why;
      if (!target_offers(v, Target::ESSL100, &off100, &why, &err) || !target_offers(v, Target::ESSL300, &off300, &why, &err)) {
        detail = err;
        ++wrong;
        continue;
      }
      refused += !off100;
      if (off100 != (v.value("LUT_ATLAS") == 1) || !off300) {
        ++wrong;
        detail += v.name() + " ";
      }
    }
    check(!vars.empty() && wrong == 0 && refused > 0, "essl100 offers the atlas colour correction, not the 3D LUTs",
          std::to_string(refused) + " refused; wrong: " + detail);
  }
  std::vector<Variant> ml;
  for (const auto &d : decls)
    if (d.name == "model_lighting") ml = enumerate_variants(d, all_tiers(), &err);
  const Variant *tex = named(ml, "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=0,NUM_LIGHTS=2");
  const Variant *flat = named(ml, "ps20:ALBEDO_TEXTURE=0,HALF_LAMBERT=1,OUTPUT_MODE=0,NUM_LIGHTS=2");
  if (!tex || !flat) {
    check(false, "model_lighting ps20 variants", "not found");
    return;
  }
  for (const Variant *v : {tex, flat}) {
    Assembled vs, fs;
    ProgramInterface iface;
    std::vector<ExtensionNeed> e100, e300;
    const auto defs = variant_defines(*v, InputMode::Production);
    bool ok = assemble(v->shader->vertex, Target::GLSL330, Stage::Vertex, defs, &vs, &err) &&
        assemble(v->shader->fragment, Target::GLSL330, Stage::Fragment, defs, &fs, &err) &&
        reflect_program(vs.text, fs.text, &iface, &err) &&
        variant_extensions(*v, Target::ESSL100, &iface, &e100, &err) &&
        variant_extensions(*v, Target::ESSL300, &iface, &e300, &err);
    const bool textured = v == tex;
    check(ok && has_ext(e100, "OES_texture_float") == textured && has_ext(e100, "OES_texture_float_linear") == textured &&
              has_ext(e100, "OES_element_index_uint") && has_ext(e100, "WEBGL_color_buffer_float") &&
              !has_ext(e100, "OES_texture_3D"),
          std::string("WebGL 1 extensions of ps20 model_lighting ") + (textured ? "with" : "without") + " an albedo texture",
          err + ext_names(e100));
    check(ok && !has_ext(e300, "OES_texture_float") && !has_ext(e300, "OES_element_index_uint") &&
              has_ext(e300, "EXT_color_buffer_float"),
          std::string("WebGL 2 extensions of ps20 model_lighting ") + (textured ? "with" : "without") + " an albedo texture",
          err + ext_names(e300));
    // The declared interface holds the whole light array the source declares (5 x 4 vec4s), which
    // only ps20's vertex stage reads (per-vertex attenuation); its fragment stage reads the packed
    // u_light_pack[4 x 2] (common_lights.glsl ts_light_unpack), so that it fits WebGL 1's 16.
    const InterfaceVar *lights = ok ? find(iface.uniforms, "u_lights") : nullptr;
    check(lights && lights->array_size == 20 && lights->vertex && !lights->fragment,
          "model_lighting ps20 declares u_lights[20], used by the vertex stage only", names(iface.uniforms));
    const InterfaceVar *pack = ok ? find(iface.uniforms, "u_light_pack") : nullptr;
    check(pack && pack->array_size == 8 && !pack->vertex && pack->fragment,
          "model_lighting ps20 declares u_light_pack[8], used by the fragment stage only", names(iface.uniforms));
  }
}

}  // namespace

int main() {
  test_reflection();
  test_budget_constants();
  test_identifiers();
  test_webgl();
  return unit_check::finish();
}

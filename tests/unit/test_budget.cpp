// tiershade tests: unit test for glue/budget/: counts small known shaders and checks the DX9 slot model
// (weights, mad fusion, _sat, loops, flattening, errors), the in-process compile's error
// positions (also mapped back to shaders/<file>:<line> through the assembler), and the Mesa
// NIR cross-check parser.
//
// Built by the Makefile (build/tests/test_budget); links glslang and SPIRV-Tools, runs no
// external program.
// Run:  build/tests/test_budget [fixtures-dir]     (default: <dir of this file>/fixtures)
// Prints "PASS name" / "FAIL name: details" per check (unit_check.h); exits 1 on any failure.
#include "budget/budget.h"

#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "shaderlib/assembler.h"
#include "unit_check.h"

namespace {

std::string describe(const BudgetCounts &c) {
  std::ostringstream s;
  s << "alu=" << c.alu << " tex=" << c.tex << " {";
  for (const auto &kv : c.by_op) s << " " << kv.first << ":" << kv.second;
  s << " }";
  return s.str();
}

int op(const BudgetCounts &c, const std::string &name) {
  auto it = c.by_op.find(name);
  return it == c.by_op.end() ? 0 : it->second;
}

// The by_op counts a check wants: (op name, count).
using OpCounts = std::vector<std::pair<std::string, int>>;

// Counts `src` and checks alu/tex (pass -1 to skip one), plus the invariant
// that by_op sums to total(); with `ops`, then a check `ops_name` that each op has its count.
// Returns the counts for further checks.
BudgetCounts expect(const std::string &name, const std::string &src, int alu, int tex, const OpCounts &ops = {},
                    const std::string &ops_name = "") {
  BudgetCounts c;
  std::string err;
  bool ok = budget_count_fragment(src, &c, &err);
  if (!ok) {
    check(false, name, "count failed: " + err);
  } else {
    int sum = 0;
    for (const auto &kv : c.by_op) sum += kv.second;
    bool good = (alu < 0 || c.alu == alu) && (tex < 0 || c.tex == tex) && sum == c.total();
    std::ostringstream want;
    want << "want alu=" << alu << " tex=" << tex << ", got " << describe(c) << " (by_op sum " << sum << ")";
    check(good, name, want.str());
  }
  if (!ops.empty()) {
    bool ops_ok = ok;
    for (const auto &o : ops) ops_ok = ops_ok && op(c, o.first) == o.second;
    check(ops_ok, ops_name, describe(c));
  }
  return c;
}

void expect_error(const std::string &name, const std::string &src, const std::string &needle) {
  BudgetCounts c;
  std::string err;
  bool ok = budget_count_fragment(src, &c, &err);
  check(!ok && err.find(needle) != std::string::npos && c.total() == 0, name,
        ok ? "unexpected success: " + describe(c) : "error text lacks \"" + needle + "\": " + err);
}

std::string read_text(const std::string &path, bool *ok) {
  std::ifstream f(path, std::ios::binary);
  *ok = static_cast<bool>(f);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Reconstruction of the platform-notes section 5 test shader (2 normalizes,
// dot, max, 2 textures, mix, pow).  Its NIR matches the notes exactly:
// 26 fmul, 12 fadd, 2 frsq, 1 fmax, 1 fpow, 2 tex.
const char *const kPlatformNotesShader = R"(#version 330
uniform sampler2D u_base;
uniform sampler2D u_detail;
uniform vec3 u_lightDir;
uniform float u_specExp;
in vec2 v_uv;
in vec3 v_normal;
out vec4 fragColor;
void main() {
    vec3 n = normalize(v_normal);
    vec3 l = normalize(u_lightDir);
    float ndl = max(dot(n, l), 0.0);
    vec4 base = texture(u_base, v_uv);
    vec4 detail = texture(u_detail, v_uv * 4.0);
    vec3 c = mix(base.rgb, detail.rgb, 0.25);
    float spec = pow(ndl, u_specExp);
    fragColor = vec4(c * ndl + spec, base.a);
}
)";

// Common declarations for the small shaders below.
const std::string kHead = R"(#version 330
uniform sampler2D s;
uniform float u_e;
uniform vec3 u_l;
uniform vec4 u_off[4];
uniform mat4 u_m4;
uniform mat3 u_m3;
uniform int u_n;
in vec2 v_uv;
in vec4 v_a;
in vec4 v_b;
in vec4 v_c;
out vec4 o;
)";

std::string shader(const std::string &body) { return kHead + "void main() {\n" + body + "\n}\n"; }

void test_weights() {
  expect("scalar pow = 3 (+1 output mov)", shader("o = vec4(pow(v_a.x, u_e));"), 4, 0,
         {{"Pow", 3}}, "scalar pow by_op");
  expect("vec3 pow = 3x3 = 9", shader("o = vec4(pow(v_a.xyz, vec3(u_e)), v_a.w);"), 10, 0,
         {{"Pow", 9}}, "vec3 pow by_op");
  expect("normalize+dot+max+texture+scalar pow",
         shader("vec3 n = normalize(v_a.xyz);\n"
                "float ndl = max(dot(n, u_l), 0.0);\n"
                "vec4 t = texture(s, v_uv);\n"
                "o = t * pow(ndl, u_e);"),
         3 + 1 + 1 + 3 + 1 + 1, 1,
         {{"Normalize", 3},
          {"OpDot", 1},
          {"FMax", 1},
          {"Pow", 3},
          {"OpImageSampleImplicitLod", 1},
          {"output mov (oC#/oDepth)", 1}},
         "normalize/dot/max/pow by_op");
  expect("sin(vec2) = 2 sincos = 16", shader("o = vec4(sin(v_a.xy), v_a.zw);"), 17, 0);
  expect("exp2/log2/inversesqrt per component", shader("o = exp2(v_a) + log2(v_b) + inversesqrt(v_c);"),
         4 + 4 + 4 + 2 + 1, 0);
  expect("sqrt vec3 = 6 (rsq+rcp)", shader("o = vec4(sqrt(v_a.xyz), 0.0) + v_b;"), 6 + 1 + 1 + 1, 0);
  expect("mix = lrp 2", shader("o = mix(v_a, v_b, v_c);"), 2 + 1, 0);
  expect("length vec3 = 3", shader("o = v_b * length(v_a.xyz);"), 3 + 1 + 1, 0);
  expect("mat4*vec4 = 4", shader("o = u_m4 * v_a;"), 4 + 1, 0);
  expect("mat3*vec3 = 3", shader("o = vec4(u_m3 * v_a.xyz, v_a.w);"), 3 + 1, 0);
  expect("cross = crs 2", shader("o = vec4(cross(v_a.xyz, v_b.xyz), v_a.w);"), 2 + 1, 0);
  expect("floor = frc+add 2, fract = 1", shader("o = floor(v_a) + fract(v_b);"), 2 + 1 + 1 + 1, 0);
  expect("negate is a free source modifier", shader("o = -v_a * v_b.x;"), 1 + 1, 0);
  expect("abs is an instruction in ps_2_x", shader("o = abs(v_a);"), 1 + 1, 0);
}

void test_fusion_and_modifiers() {
  expect("mad fusion: vec*scalar + vec = 1", shader("o = v_a * v_b.x + v_c;"), 1 + 1, 0,
         {{"OpVectorTimesScalar", 0}}, "mad fusion leaves no mul");
  expect("mad fusion: vec*vec + vec (Fma) = 1", shader("o = v_a * v_b + v_c;"), 1 + 1, 0);
  expect("no fusion when the mul has two uses", shader("vec4 m = v_a * v_b.x;\no = (m + v_c) * m.yzwx;"), 1 + 1 + 1 + 1,
         0);
  expect("an add absorbs one mul only", shader("o = v_a * v_b.x + v_c * v_b.y;"), 1 + 1 + 1, 0);
  expect("dp2add: vec2 dot + add = 2", shader("o = vec4(dot(v_a.xy, v_b.xy) + v_c.x);"), 2 + 1, 0,
         {{"OpFAdd", 0}, {"OpDot", 2}}, "dp2add by_op");
  expect("_sat: clamp(mad, 0, 1) is free", shader("o = clamp(v_a * v_b + v_c, 0.0, 1.0);"), 1 + 1, 0,
         {{"FClamp", 0}}, "_sat by_op");
  expect("clamp(input, 0, 1) = mov_sat 1", shader("o = clamp(v_a, 0.0, 1.0);"), 1 + 1, 0);
  expect("_sat on each lane: clamp(vec3(dot, dot, dot), 0, 1) is free",
         shader("vec3 d = clamp(vec3(dot(v_a.xyz, v_b.xyz), dot(v_a.xyz, v_c.xyz), dot(v_b.xyz, v_c.xyz)), "
                "0.0, 1.0);\no = vec4(d * d, v_a.w);"),
         3 + 1 + 1, 0);
  expect("clamp(x, 0.2, 0.8) = max+min 2", shader("o = clamp(v_a * v_b, 0.2, 0.8);"), 1 + 2 + 1, 0);
  expect("divide by scalar uniform = rcp+mul 2", shader("o = v_a / u_e;"), 2 + 1, 0);
  expect("divide vec4 by vec4 = 4 rcp + mul", shader("o = v_a / v_b;"), 4 + 1 + 1, 0);
  expect("vec4(rgb, 1.0) costs a mov for the constant lane", shader("o = vec4(v_a.xyz * v_b.x, 1.0);"), 1 + 1 + 1,
         0, {{"OpCompositeConstruct (constant lanes)", 1}}, "constant-lane mov by_op");
}

void test_control_flow() {
  expect("constant loop of 4 taps is unrolled",
         shader("vec4 acc = vec4(0.0);\n"
                "for (int i = 0; i < 4; i++) acc += texture(s, v_uv + u_off[i].xy) * u_off[i].z;\n"
                "o = acc;"),
         4 * 2 + 1, 4);
  expect("nested loops 3x2 taps",
         shader("vec4 a = vec4(0.0);\n"
                "for (int y = 0; y < 3; ++y) for (int x = 0; x < 2; ++x)\n"
                "  a += texture(s, v_uv + vec2(float(x), float(y)) * u_off[0].xy);\n"
                "o = a;"),
         6 * 2 + 1, 6);
  expect("do-while runs 3 times",
         shader("float k = 0.0; int i = 0;\n"
                "do { k += v_a[i] * u_off[i].x; i++; } while (i < 3);\n"
                "o = vec4(k);"),
         3 + 1, 0);
  expect("float loop counter, 5 trips",
         shader("vec4 a = vec4(0.0);\n"
                "for (float f = 0.0; f < 2.5; f += 0.5) a += texture(s, v_uv * f);\n"
                "o = a;"),
         5 * 2 + 1, 5);
  expect_error("loop with a uniform bound is an error",
               shader("vec4 a = vec4(0.0);\n"
                      "for (int i = 0; i < u_n; i++) a += texture(s, v_uv * float(i));\n"
                      "o = a;"),
               "unbounded loop");
  expect("discard = texkill (1 tex) + compare",
         shader("vec4 t = texture(s, v_uv);\nif (t.a < 0.5) discard;\no = t;"), 1 + 1, 2,
         {{"OpKill", 1}}, "texkill by_op");
  expect("discard on a compare with 0 needs no add",
         shader("vec4 t = texture(s, v_uv);\nif (t.a < 0.0) discard;\no = t;"), 1, 2);
  expect("if/else: both sides counted + phi cmp",
         shader("vec3 c;\n"
                "if (v_a.z > u_e) c = normalize(v_a.xyz); else c = texture(s, v_uv).rgb * 2.0;\n"
                "o = vec4(c, v_a.w);"),
         1 + 3 + 1 + 1 + 1, 1, {{"OpPhi", 1}}, "if/else phi by_op");
  expect("switch: case compares + (k-1) cmps at the merge",
         shader("vec4 a = v_a;\n"
                "switch (u_n) { case 0: a *= 2.0; break; case 1: a = normalize(a); break; "
                "default: a = sqrt(a); }\n"
                "o = a;"),
         1 + 3 + 8 + 1 + 2 + 1, 0, {{"OpPhi", 2}, {"OpSwitch", 1}}, "switch by_op");
  expect("early return: output written on two paths needs a cmp",
         shader("if (v_a.x > 0.5) { o = v_a; return; }\no = texture(s, v_uv);"), 1 + 1 + 1, 1,
         {{"output merge cmp", 1}}, "early return by_op");
  expect("two outputs = two movs",
         "#version 330\nin vec4 v_a;\nlayout(location = 0) out vec4 o0;\nlayout(location = 1) out vec4 o1;\n"
         "void main() { o0 = v_a * 2.0; o1 = v_a + 1.0; }\n",
         2 + 2, 0);
}

void test_sources_and_errors() {
  std::string err;
  BudgetCounts c;
  bool ok = budget_count_fragment(shader("o = v_a + foo;"), &c, &err);
  check(!ok && err.find("GLSL compile failed") != std::string::npos &&
            err.find("'foo' : undeclared identifier") != std::string::npos &&
            err.find("ERROR: 0:15:") != std::string::npos && err.find("/tmp") == std::string::npos,
        "compile error returns false with the glslang message", ok ? "unexpected success" : err);
  ok = budget_count_fragment("#version 330\nout vec4 o;\n#line 100 7\nvoid main() { o = bar; }\n", &c, &err);
  check(!ok && err.find("7:100") != std::string::npos, "#line N M is honoured in messages",
        ok ? "unexpected success" : err);
  expect("missing #version gets 330 prepended", "in vec4 v_a;\nout vec4 o;\nvoid main() { o = v_a * v_a.x; }\n", 1 + 1,
         0);
  ok = budget_count_fragment("out vec4 o;\nvoid main() { o = baz; }\n", &c, &err);
  check(!ok && err.find("ERROR: 0:2:") != std::string::npos, "missing #version keeps line numbers",
        ok ? "unexpected success" : err);
  expect("#version 150 is raised to 330",
         "// header comment\n#version 150\nin vec4 v_a;\nout vec4 o;\nvoid main() { o = v_a * 3.0; }\n", 1 + 1, 0);
  expect_error("ES sources are rejected",
               "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main(){o=vec4(1);}\n", "ES shaders");
  expect("constant output: only the mov", "#version 330\nout vec4 o;\nvoid main() { o = vec4(0.5); }\n", 1, 0);
}

// A compile error in an included library file is reported at that file's line: the assembler
// numbers each file's source string in its #line directives, glslang reports "S:L:", and
// map_compile_log names the file.  The library is a private copy (TIERSHADE_SHADER_DIR).
void test_error_positions_through_the_assembler() {
  char tmpl[] = "/tmp/tiershade-test-budget-XXXXXX";
  const char *dir = mkdtemp(tmpl);
  check(dir != nullptr, "assembler errors: temp shader dir");
  if (!dir) return;
  const std::string d = dir;
  bool written = true;
  for (const std::string &name : shader_library_files()) {  // the real library, for the prelude
    std::string text;
    written = written && shader_library_read(name, &text);
    std::ofstream(d + "/" + name, std::ios::binary) << text;
  }
  std::ofstream(d + "/budget_test_main.fs", std::ios::binary)
      << "out vec4 o;\n#include \"budget_test_inc.glsl\"\nvoid main() { o = helper(); }\n";
  std::ofstream(d + "/budget_test_inc.glsl", std::ios::binary)
      << "// a helper with an error on line 3\nvec4 helper() {\n  return undeclared_thing;\n}\n";
  const char *old = getenv("TIERSHADE_SHADER_DIR");
  const std::string saved = old ? old : "";
  setenv("TIERSHADE_SHADER_DIR", dir, 1);
  Assembled a;
  std::string err;
  bool assembled = assemble("budget_test_main.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(written && assembled, "assembler errors: test shader assembles", err);
  BudgetCounts c;
  bool ok = assembled && budget_count_fragment(a.text, &c, &err);
  const std::string mapped = map_compile_log(err, a);
  check(assembled && !ok && mapped.find("shaders/budget_test_inc.glsl:3:") != std::string::npos &&
            mapped.find("undeclared_thing") != std::string::npos,
        "assembler errors: the budget's compile error names shaders/budget_test_inc.glsl:3", mapped);
  if (old)
    setenv("TIERSHADE_SHADER_DIR", saved.c_str(), 1);
  else
    unsetenv("TIERSHADE_SHADER_DIR");
  for (const std::string &name : shader_library_files()) std::remove((d + "/" + name).c_str());
  std::remove((d + "/budget_test_main.fs").c_str());
  std::remove((d + "/budget_test_inc.glsl").c_str());
  check(rmdir(dir) == 0, "assembler errors: temp shader dir removed", d);
}

// The counter may run on several threads at once (glslang is initialised once per process):
// every thread gets the counts of the serial run.
void test_threads() {
  const std::string srcs[2] = {
      kPlatformNotesShader,
      shader("vec4 a = vec4(0.0);\nfor (int i = 0; i < 4; i++) a += texture(s, v_uv + u_off[i].xy);\no = a;")};
  BudgetCounts serial[2];
  std::string err;
  bool ok = budget_count_fragment(srcs[0], &serial[0], &err) && budget_count_fragment(srcs[1], &serial[1], &err);
  check(ok, "threads: serial counts", err);
  if (!ok) return;
  constexpr int kThreads = 4, kRounds = 3;
  std::vector<int> mismatches(kThreads, 0);
  std::vector<std::thread> pool;
  for (int t = 0; t < kThreads; ++t) {
    pool.emplace_back([&, t] {
      for (int r = 0; r < kRounds; ++r) {
        const int k = (t + r) % 2;
        BudgetCounts c;
        std::string e;
        if (!budget_count_fragment(srcs[k], &c, &e) || c.alu != serial[k].alu || c.tex != serial[k].tex ||
            c.by_op != serial[k].by_op)
          ++mismatches[t];
      }
    });
  }
  for (std::thread &th : pool) th.join();
  int bad = 0;
  for (int m : mismatches) bad += m;
  check(bad == 0, "threads: 4 threads x 3 counts equal the serial counts",
        std::to_string(bad) + " of " + std::to_string(kThreads * kRounds) + " differ");
}

void test_platform_notes_shader() {
  BudgetCounts c = expect("platform-notes test shader = 16 ALU + 2 tex", kPlatformNotesShader, 16, 2);
  std::cout << "INFO platform-notes test shader: " << describe(c) << "\n";
}

void test_table() {
  std::string md = budget_weight_table_markdown();
  check(md.rfind("| SPIR-V instruction | DX9 equivalent | slots |\n|---|---|---|\n", 0) == 0 &&
            md.find("| Normalize (GLSL.std.450) | `nrm`") != std::string::npos &&
            md.find("| Pow (GLSL.std.450) |") != std::string::npos && md.find("OpKill") != std::string::npos,
        "weight table markdown", md.substr(0, 200));
}

void test_nir(const std::string &fixtures) {
  bool ok = false;
  std::string dump = read_text(fixtures + "/nir_platform_notes_shader.txt", &ok);
  check(ok, "NIR fixture readable", fixtures + "/nir_platform_notes_shader.txt");
  if (!ok) return;
  int alu = -1, tex = -1;
  std::string err;
  bool r = budget_count_nir_text(dump, &alu, &tex, &err);
  check(r && alu == 42 && tex == 2, "NIR fixture: 42 scalar ALU + 2 tex",
        "got " + std::to_string(alu) + " / " + std::to_string(tex) + " " + err);
  std::cout << "INFO NIR cross-check of the platform-notes test shader: " << alu << " scalar ALU, " << tex << " tex\n";

  // The same shader printed twice (same source_sha1) is fine.
  r = budget_count_nir_text(dump + dump, &alu, &tex, &err);
  check(r && alu == 42 && tex == 2, "NIR: repeated identical fragment shader", err);

  // A different fragment shader in the same dump is refused.
  std::string other = dump;
  size_t p = other.rfind("source_sha1: {");
  if (p != std::string::npos) other.replace(p, 16, "source_sha1: {0xff");
  r = budget_count_nir_text(dump + other, &alu, &tex, &err);
  check(!r && err.find("different fragment shaders") != std::string::npos, "NIR: two different shaders", err);

  r = budget_count_nir_text("NIR before handing off to driver:\nshader: MESA_SHADER_VERTEX\nimpl main {\n}\n", &alu,
                            &tex, &err);
  check(!r && err.find("MESA_SHADER_FRAGMENT") != std::string::npos, "NIR: no fragment section", err);

  // Newer Mesa syntax ("con 32x4 %5 = ...", "@intrinsic") and vector ALU widths.
  const char *newer =
      "NIR before handing off to driver:\n"
      "shader: MESA_SHADER_FRAGMENT\n"
      "source_sha1: {0x1}\n"
      "impl main {\n"
      "    block b0:  // preds:\n"
      "    32x4  %0 = @load_deref (%1) (access=none)\n"
      "    con 32x4  %2 = load_const (0x3f800000, 0x3f800000, 0x3f800000, 0x3f800000)\n"
      "    32x4  %3 = fmul %0, %2\n"
      "    32     %4 = fadd %3.x, %3.y\n"
      "    32x2  %5 = vec2 %4, %4\n"
      "    32x4  %6 = (float32)txl %5 (coord), %4 (lod), 0 (texture), 0 (sampler)\n"
      "    32     %7 = mov %6.w\n"
      "    @store_deref (%1, %6) (wrmask=xyzw, access=none)\n"
      "}\n";
  r = budget_count_nir_text(newer, &alu, &tex, &err);
  check(r && alu == 5 && tex == 1, "NIR: newer Mesa syntax",
        "got " + std::to_string(alu) + " / " + std::to_string(tex) + " " + err);
}

}  // namespace

int main(int argc, char **argv) {
  std::string fixtures;
  if (argc > 1) {
    fixtures = argv[1];
  } else {
    std::string here = __FILE__;
    size_t slash = here.find_last_of('/');
    fixtures = (slash == std::string::npos ? std::string(".") : here.substr(0, slash)) + "/fixtures";
  }
  test_weights();
  test_fusion_and_modifiers();
  test_control_flow();
  test_sources_and_errors();
  test_error_positions_through_the_assembler();
  test_threads();
  test_platform_notes_shader();
  test_table();
  test_nir(fixtures);
  std::cout.flush();
  return finish();
}

// tiershade tests: unit tests for the glue: the GLSL assembler (glue/shaderlib/assembler.*), compile-log
// mapping on real Mesa llvmpipe contexts (glue/gl/context.*, glue/gl/float_target.*),
// both GL backends in one process, and the variant system (glue/shaderlib/variants.*).
//
// Usage: build/tests/test_glue        (make build/tests/test_glue)
//   Prints "PASS name" or "FAIL name: detail" per check; exits 1 if any failed.
//
// Shader files for the include / cycle / compile-error checks are written to a
// private mkdtemp() directory that TIERSHADE_SHADER_DIR points at; the variable
// is unset afterwards so the variant checks use the embedded library, and the
// directory is removed at the end.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "shaderlib/assembler.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "shaderlib/variants.h"
#include "unit_check.h"

namespace {

bool contains(const std::string &hay, const std::string &needle) { return hay.find(needle) != std::string::npos; }

size_t count_of(const std::string &hay, const std::string &needle) {
  size_t n = 0;
  for (size_t p = hay.find(needle); p != std::string::npos; p = hay.find(needle, p + needle.size())) ++n;
  return n;
}

std::vector<std::string> split_lines(const std::string &s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line)) v.push_back(line);
  return v;
}

std::string quote(const std::string &s) { return "'" + s + "'"; }

// ---- private shader directory ----------------------------------------------
std::string g_dir;
std::vector<std::string> g_written;
std::string g_header;  // the library's portability header, copied into g_dir

void write_shader(const std::string &name, const std::string &text) {
  const std::string path = g_dir + "/" + name;
  FILE *f = fopen(path.c_str(), "wb");
  if (!f) {
    check(false, "setup.write_" + name, "cannot create " + path);
    return;
  }
  fwrite(text.data(), 1, text.size(), f);
  fclose(f);
  g_written.push_back(path);
}

void remove_dir() {
  for (const auto &p : g_written) unlink(p.c_str());
  if (!g_dir.empty()) rmdir(g_dir.c_str());
}

// ---- assembler ---------------------------------------------------------------

void test_targets_and_prelude() {
  Target t;
  check(parse_target("essl100", &t) && t == Target::ESSL100 && std::string(target_name(t)) == "essl100",
        "assembler.parse_target_essl100");
  check(parse_target("essl300", &t) && t == Target::ESSL300 && std::string(target_name(t)) == "essl300",
        "assembler.parse_target_essl300");
  check(parse_target("glsl330", &t) && t == Target::GLSL330 && std::string(target_name(t)) == "glsl330",
        "assembler.parse_target_glsl330");
  check(!parse_target("hlsl", &t) && !parse_target("", &t) && !parse_target("ESSL100", &t),
        "assembler.parse_target_rejects_unknown");

  write_shader("plain.fs", "// plain entry\nvoid main() {}\n");
  struct Case {
    Target t;
    const char *first;
    const char *target_define;
  };
  const Case cases[] = {{Target::ESSL100, "#version 100", "#define TS_ESSL100 1\n"},
                        {Target::ESSL300, "#version 300 es", "#define TS_ESSL300 1\n"},
                        {Target::GLSL330, "#version 330 core", "#define TS_GLSL330 1\n"}};
  for (const auto &c : cases) {
    for (Stage st : {Stage::Vertex, Stage::Fragment}) {
      const std::string tag = std::string(target_name(c.t)) + (st == Stage::Vertex ? "_vertex" : "_fragment");
      Assembled a;
      std::string err;
      const bool ok = assemble("plain.fs", c.t, st, {}, &a, &err);
      check(ok, "assembler.prelude_" + tag + "_assembles", err);
      if (!ok) continue;
      const auto lines = split_lines(a.text);
      check(!lines.empty() && lines[0] == c.first, "assembler.prelude_" + tag + "_version_first_line",
            "first line " + (lines.empty() ? std::string("<none>") : quote(lines[0])) + ", want " + quote(c.first));
      // The assembler writes only #version and the selecting defines: one target, one stage,
      // the precision; the words of each language come from the portability header.
      int targets = 0;
      for (const auto &o : cases) targets += contains(a.text, o.target_define) ? 1 : 0;
      check(contains(a.text, c.target_define) && targets == 1, "assembler.prelude_" + tag + "_one_target_define",
            std::to_string(targets) + " target defines");
      const bool vertex = contains(a.text, "#define TS_VERTEX 1\n"),
                 fragment = contains(a.text, "#define TS_FRAGMENT 1\n");
      check(vertex == (st == Stage::Vertex) && fragment == (st == Stage::Fragment),
            "assembler.prelude_" + tag + "_stage_define");
      check(contains(a.text, "#define TS_FLOAT_PRECISION highp\n"), "assembler.prelude_" + tag + "_highp_float");
      // order: selecting defines, then the header (source string 1), then the entry (string 0)
      const size_t sel = a.text.find(c.target_define);
      const size_t header = a.text.find("#line 1 1\n");
      const size_t line0 = a.text.find("#line 1 0\n");
      check(sel != std::string::npos && header != std::string::npos && line0 != std::string::npos && sel < header &&
                header < line0,
            "assembler.prelude_" + tag + "_defines_header_entry_order");
      check(header != std::string::npos && a.text.compare(header + 10, g_header.size(), g_header) == 0,
            "assembler.prelude_" + tag + "_header_text_verbatim");
      const std::vector<std::string> want_files = {"shaders/plain.fs", std::string("shaders/") + kPortabilityHeader};
      check(a.files == want_files, "assembler.prelude_" + tag + "_files",
            a.files.empty() ? "no files" : a.files[0] + " (" + std::to_string(a.files.size()) + " files)");
      // no language words outside the header
      const std::string outside = a.text.substr(0, header == std::string::npos ? 0 : header);
      check(!contains(outside, "precision") && !contains(outside, "varying") && !contains(outside, "texture"),
            "assembler.prelude_" + tag + "_no_language_words_outside_header", "prelude: " + outside);
    }
  }
}

// The header is looked up like any library file, and may not carry #extension lines (those
// belong in the shader that needs the extension, which the assembler hoists after #version).
void test_portability_header_errors() {
  Assembled a;
  std::string err;
  write_shader(kPortabilityHeader, "// a header that wants an extension\n#extension GL_OES_texture_3D : enable\n");
  bool ok = assemble("plain.fs", Target::ESSL100, Stage::Fragment, {}, &a, &err);
  check(!ok && contains(err, kPortabilityHeader) && contains(err, "#extension"), "assembler.header_extension_rejected",
        ok ? "assembled" : "message: " + err);
  const std::string path = g_dir + "/" + kPortabilityHeader;
  unlink(path.c_str());
  err.clear();
  ok = assemble("plain.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(!ok && contains(err, kPortabilityHeader) && contains(err, "cannot find"), "assembler.missing_header_named",
        ok ? "assembled" : "message: " + err);
  write_shader(kPortabilityHeader, g_header);
}

void test_defines() {
  Assembled a;
  std::string err;
  const std::vector<Define> defs = {{"ALPHA", "1"}, {"BETA_COUNT", "3"}, {"GAMMA", "vec3(1.0, 2.0, 3.0)"}};
  const bool ok = assemble("plain.fs", Target::GLSL330, Stage::Fragment, defs, &a, &err);
  check(ok, "assembler.defines_assemble", err);
  if (!ok) return;
  const size_t entry = a.text.find("#line 1 1\n");  // the portability header
  size_t last = 0;
  bool ordered = true;
  for (const auto &d : defs) {
    const std::string line = "\n#define " + d.name + " " + d.value + "\n";
    const size_t p = a.text.find(line);
    check(p != std::string::npos, "assembler.define_" + d.name + "_present",
          "no line " + quote(line.substr(1, line.size() - 2)));
    if (p == std::string::npos || p < last || p > entry) ordered = false;
    last = p;
  }
  check(ordered, "assembler.defines_in_order_before_source");
  check(a.text.find("#version") == 0 && a.text.find("#define ALPHA") > a.text.find("#define TS_FLOAT_PRECISION") &&
            a.text.find("#define GAMMA") < a.text.find("#line 1 1\n"),
        "assembler.defines_after_selection_before_header");
}

void test_precision_option() {
  Assembled a;
  std::string err;
  bool ok = assemble("plain.fs", Target::ESSL300, Stage::Fragment, {}, &a, &err, "mediump");
  check(ok && contains(a.text, "#define TS_FLOAT_PRECISION mediump\n") &&
            !contains(a.text, "#define TS_FLOAT_PRECISION highp") &&
            contains(a.text, "precision TS_FLOAT_PRECISION float;\n") &&
            contains(a.text, "precision highp sampler2D;\n"),
        "assembler.mediump_float_keeps_highp_samplers", err);
  ok = assemble("plain.fs", Target::ESSL100, Stage::Fragment, {}, &a, &err);
  check(ok && contains(a.text, "#define TS_FLOAT_PRECISION highp\n"), "assembler.default_precision_highp", err);
  err.clear();
  ok = assemble("plain.fs", Target::ESSL300, Stage::Fragment, {}, &a, &err, "ultrap");
  check(!ok && contains(err, "ultrap"), "assembler.unknown_precision_rejected", ok ? "accepted" : "message: " + err);
}

void test_includes() {
  // entry.fs includes a.glsl (line 2) and b.glsl (line 4); b.glsl includes a.glsl again.
  write_shader("entry.fs",
               "// entry line 1\n"
               "#include \"a.glsl\"\n"
               "float entry_line3;\n"
               "  #  include   \"b.glsl\"  \n"
               "void main() {}\n");
  write_shader("a.glsl",
               "#ifndef A_GLSL\n"
               "#define A_GLSL\n"
               "float marker_a;\n"
               "#endif\n");
  write_shader("b.glsl",
               "#include \"a.glsl\"\n"
               "float marker_b;\n"
               "#pragma once\n"
               "float after_pragma;\n");
  Assembled a;
  std::string err;
  const bool ok = assemble("entry.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(ok, "assembler.includes_assemble", err);
  if (!ok) return;
  check(count_of(a.text, "float marker_a;") == 2, "assembler.include_expanded_once_per_include",
        "a.glsl included twice, its body appears " + std::to_string(count_of(a.text, "float marker_a;")) + " times");
  check(count_of(a.text, "float marker_b;") == 1, "assembler.include_single_expansion");
  check(!contains(a.text, "#include"), "assembler.no_include_directive_left");
  const std::vector<std::string> want_files = {"shaders/entry.fs", std::string("shaders/") + kPortabilityHeader,
                                               "shaders/a.glsl", "shaders/b.glsl"};
  std::string got_files;
  for (const auto &f : a.files) got_files += f + " ";
  check(a.files == want_files, "assembler.files_one_entry_per_file", "files: " + got_files);

  // The body after the prelude, exactly: #line N S before every file and after every include.
  const std::string want_body =
      "#line 1 0\n"
      "// entry line 1\n"
      "#line 1 2\n"
      "#ifndef A_GLSL\n#define A_GLSL\nfloat marker_a;\n#endif\n"
      "#line 3 0\n"
      "float entry_line3;\n"
      "#line 1 3\n"
      "#line 1 2\n"
      "#ifndef A_GLSL\n#define A_GLSL\nfloat marker_a;\n#endif\n"
      "#line 2 3\n"
      "float marker_b;\n"
      "#pragma once\n"  // passed through on its own line (or blanked): line numbers kept
      "float after_pragma;\n"
      "#line 5 0\n"
      "void main() {}\n";
  const size_t body = a.text.find("#line 1 0\n");
  std::string got_body = body == std::string::npos ? std::string() : a.text.substr(body);
  const size_t blank = got_body.find("float marker_b;\n\nfloat after_pragma;");
  if (blank != std::string::npos) got_body.insert(blank + 16, "#pragma once");  // blanked is fine too
  check(got_body == want_body, "assembler.line_directives_exact", "body was:\n" + got_body);
  check(count_of(a.text, "#line ") == 8, "assembler.line_directive_count",
        std::to_string(count_of(a.text, "#line ")) + " #line directives");
}

void test_include_errors() {
  Assembled a;
  std::string err;

  write_shader("missing.fs", "// line 1\n// line 2\n#include \"does_not_exist.glsl\"\nvoid main() {}\n");
  bool ok = assemble("missing.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(!ok, "assembler.missing_include_fails");
  check(contains(err, "shaders/missing.fs:3") && contains(err, "does_not_exist.glsl"),
        "assembler.missing_include_names_file_and_line", "message: " + err);

  write_shader("mid.glsl", "// mid\n#include \"gone.glsl\"\n");
  write_shader("missing2.fs", "#include \"mid.glsl\"\n");
  err.clear();
  ok = assemble("missing2.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(!ok && contains(err, "shaders/mid.glsl:2") && contains(err, "gone.glsl"),
        "assembler.missing_nested_include_names_including_file", "message: " + err);

  err.clear();
  ok = assemble("no_such_entry.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(!ok && contains(err, "no_such_entry.fs"), "assembler.missing_entry_fails", "message: " + err);

  write_shader("cyc_a.glsl", "// a\n#include \"cyc_b.glsl\"\n");
  write_shader("cyc_b.glsl", "#include \"cyc_a.glsl\"\n");
  write_shader("cyc.fs", "#include \"cyc_a.glsl\"\nvoid main() {}\n");
  err.clear();
  ok = assemble("cyc.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(!ok, "assembler.include_cycle_fails");
  check(contains(err, "cycle") && contains(err, "cyc_a.glsl") && contains(err, "shaders/cyc_b.glsl:1"),
        "assembler.include_cycle_message", "message: " + err);

  write_shader("self.fs", "// self\n// self\n#include \"self.fs\"\n");
  err.clear();
  ok = assemble("self.fs", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(!ok && contains(err, "cycle") && contains(err, "shaders/self.fs:3"), "assembler.self_include_is_a_cycle",
        "message: " + err);

  // Chain deep0 -> deep1 -> ... ; 16 levels of nesting are allowed, 17 are not.
  const int kFiles = 19;
  for (int i = 0; i < kFiles; ++i) {
    const std::string next = i + 1 < kFiles ? "#include \"deep" + std::to_string(i + 1) + ".glsl\"\n" : "";
    write_shader("deep" + std::to_string(i) + ".glsl", "float deep" + std::to_string(i) + ";\n" + next);
  }
  // deep2 -> ... -> deep18 is 16 includes deep.
  err.clear();
  ok = assemble("deep2.glsl", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(ok, "assembler.depth_16_allowed", err);
  err.clear();
  ok = assemble("deep1.glsl", Target::GLSL330, Stage::Fragment, {}, &a, &err);
  check(!ok && contains(err, "deeper"), "assembler.depth_17_rejected", ok ? "assembled" : "message: " + err);
  check(!ok && contains(err, "shaders/deep17.glsl:2"), "assembler.depth_error_names_file_and_line", "message: " + err);
}

void test_map_compile_log() {
  Assembled a;
  a.files = {"shaders/entry.fs", "shaders/lib.glsl"};
  const std::string mesa = "0:5(12): error: `foo' undeclared\n1:17(3): error: type mismatch\n";
  const std::string m = map_compile_log(mesa, a);
  check(contains(m, "shaders/entry.fs:5:") && contains(m, "`foo' undeclared"), "map_log.mesa_string_0", "mapped: " + m);
  check(contains(m, "shaders/lib.glsl:17:") && contains(m, "type mismatch"), "map_log.mesa_string_1", "mapped: " + m);
  check(!contains(m, "0:5(") && !contains(m, "1:17("), "map_log.mesa_prefix_replaced", "mapped: " + m);
  check(split_lines(m).size() == 2, "map_log.line_count_kept", "mapped: " + m);

  const std::string gl = map_compile_log("ERROR: 1:7: 'x' : undeclared identifier\n", a);
  check(contains(gl, "ERROR: shaders/lib.glsl:7:") && contains(gl, "'x' : undeclared identifier"),
        "map_log.glslang_format", "mapped: " + gl);

  const std::string oob = map_compile_log("9:4(1): error: from a string we do not know\n", a);
  check(contains(oob, "9:4(1): error: from a string we do not know"), "map_log.unknown_string_kept", "mapped: " + oob);

  const std::string plain = map_compile_log("warning: nothing to map here\n", a);
  check(plain == "warning: nothing to map here\n", "map_log.plain_line_kept", "mapped: " + plain);

  check(map_compile_log("", a).empty(), "map_log.empty_log");

  // A log is driver output: a source-string number too big for an integer must not crash.
  try {
    const std::string huge = map_compile_log("123456789012345678901234567890:1(1): error: x\n", a);
    check(contains(huge, "error: x"), "map_log.huge_string_number_no_throw", "mapped: " + huge);
  } catch (const std::exception &e) {
    check(false, "map_log.huge_string_number_no_throw", std::string("threw ") + e.what());
  }
}

// ---- real compiles on llvmpipe ------------------------------------------------

struct Ctx {
  std::unique_ptr<GlContext> ctx;
  std::unique_ptr<GlRenderer> r;
  std::string err;
  bool ok() const { return ctx && r; }
};

Ctx make_ctx(Backend b, Api api) {
  Ctx c;
  c.ctx = GlContext::create(b, api, &c.err);
  if (c.ctx) c.r = std::make_unique<GlRenderer>(*c.ctx);
  return c;
}

// The context for one backend/API, checked as "<group>.<backend>_<api>_context".
Ctx checked_ctx(Backend b, Api api, const std::string &group, std::string *tag) {
  *tag = std::string(backend_name(b)) + "_" + api_name(api);
  Ctx c = make_ctx(b, api);
  check(c.ok(), group + "." + *tag + "_context", c.err);
  return c;
}

void release(Ctx &c) {
  if (c.ctx) c.ctx->make_current();
  c.r.reset();
  c.ctx.reset();
}

Target target_of(Api api) {
  return api == Api::GLES2 ? Target::ESSL100 : api == Api::GLES3 ? Target::ESSL300 : Target::GLSL330;
}

void write_gl_shaders() {
  write_shader("t_quad.vs",
               "// full-screen triangle for the glue tests\n"
               "TS_ATTRIBUTE vec2 a_corner;\n"
               "void main() { gl_Position = vec4(a_corner, 0.0, 1.0); }\n");
  // Error inside an included file at line 4.
  write_shader("t_err_lib.glsl",
               "// helper with a deliberate error\n"
               "float t_value() {\n"
               "    float a = 1.0;\n"
               "    return a + undeclared_symbol_xyz;\n"
               "}\n");
  write_shader("t_err_entry.fs",
               "// broken entry: the error is in t_err_lib.glsl line 4\n"
               "#include \"t_err_lib.glsl\"\n"
               "TS_DECLARE_FRAG_COLOR\n"
               "void main() { TS_FRAG_COLOR = vec4(t_value()); }\n");
  // Error in the entry itself, after an include (tests the #line after the include).
  write_shader("t_ok_lib.glsl",
               "// fine helper\n"
               "float t_ok() { return 0.5; }\n");
  write_shader("t_err_after.fs",
               "// broken entry\n"
               "#include \"t_ok_lib.glsl\"\n"
               "TS_DECLARE_FRAG_COLOR\n"
               "void main() {\n"
               "    TS_FRAG_COLOR = vec4(t_ok()) + another_undeclared_abc;\n"
               "}\n");
  // Constant colour plus one texel, for the backend checks. TS_TEST_COLOR comes from a define.
  write_shader("t_const.fs",
               "// constant colour + texel\n"
               "uniform sampler2D u_tex;\n"
               "TS_DECLARE_FRAG_COLOR\n"
               "void main() { TS_FRAG_COLOR = TS_TEST_COLOR + TS_TEX2D(u_tex, vec2(0.5, 0.5)); }\n");
}

// Every macro of shaders/ts_portability.glsl in one program: a varying through TS_VARYING in
// both stages, 2D, cube and 3D lookups (ESSL 1.00: GL_OES_texture_3D, enabled by the entry and
// hoisted after #version), TS_SAMPLER3D_PRECISION, TS_FRAG_COLOR, texelFetch where it exists.
void write_portability_shaders() {
  write_shader("t_port.vs",
               "// the varying written by the vertex stage\n"
               "TS_ATTRIBUTE vec2 a_corner;\n"
               "TS_VARYING vec2 v_corner;\n"
               "void main() { v_corner = a_corner; gl_Position = vec4(a_corner, 0.0, 1.0); }\n");
  write_shader("t_port.fs",
               "// reads the varying and one texel of each kind\n"
               "#extension GL_OES_texture_3D : enable\n"
               "TS_SAMPLER3D_PRECISION\n"
               "uniform sampler2D u_tex;\n"
               "uniform samplerCube u_cube;\n"
               "uniform sampler3D u_vol;\n"
               "TS_VARYING vec2 v_corner;\n"
               "TS_DECLARE_FRAG_COLOR\n"
               "void main() {\n"
               "    vec4 c = TS_TEX2D(u_tex, vec2(0.5)) + TS_TEXCUBE(u_cube, vec3(1.0, 0.0, 0.0)) +\n"
               "             TS_TEX3D(u_vol, vec3(0.5));\n"
               "#ifdef TS_HAS_TEXEL_FETCH\n"
               "    c += texelFetch(u_tex, ivec2(0), 0);\n"
               "#else\n"
               "    c += TS_TEX2D(u_tex, vec2(0.5));\n"
               "#endif\n"
               "    TS_FRAG_COLOR = c + vec4(0.0, 0.0, 0.0, step(-1.0, v_corner.x));\n"
               "}\n");
}

void test_portability_macros(Backend b, Api api) {
  std::string tag;
  Ctx c = checked_ctx(b, api, "portability", &tag);
  if (!c.ok()) return;
  // Assembled and built as one pair: the fragment text is kept for the order check.
  Assembled pair[2];
  std::string err;
  const bool assembled = assemble("t_port.vs", target_of(api), Stage::Vertex, {}, &pair[0], &err) &&
      assemble("t_port.fs", target_of(api), Stage::Fragment, {}, &pair[1], &err);
  const GLuint p = assembled ? c.r->build_program(pair[0], pair[1], &err) : 0;
  check(p != 0, "portability." + tag + "_builds", err);
  if (!p) {
    release(c);
    return;
  }
  const std::string &fs = pair[1].text;
  check(api != Api::GLES2 || fs.find("#extension GL_OES_texture_3D") < fs.find("#define TS_ESSL100"),
        "portability." + tag + "_extension_before_defines");
  TextureDesc tex, cube, vol;
  tex.sampler = "u_tex";
  tex.w = tex.h = 1;
  tex.rgba = {0.5f, 0.25f, 0.125f, 0.0f};
  cube.sampler = "u_cube";
  cube.kind = TexKind::Cube;
  cube.w = cube.h = 1;
  cube.rgba.assign(6 * 4, 0.0f);
  cube.rgba[0] = 2.0f;  // +X face, red
  vol.sampler = "u_vol";
  vol.kind = TexKind::Tex3D;
  vol.w = vol.h = vol.d = 1;
  vol.rgba = {0.0f, 0.0f, 4.0f, 0.0f};
  const GLuint t2 = c.r->upload_texture(tex), tc = c.r->upload_texture(cube), t3 = c.r->upload_texture(vol);
  ImageF img;
  const bool ok = c.r->draw(p, {{"u_tex", t2}, {"u_cube", tc}, {"u_vol", t3}}, 2, 2, &img, &err);
  check(ok, "portability." + tag + "_draw", err);
  if (ok) {
    // 2 x texel + cube + volume + (0, 0, 0, 1): exact in float
    const float want[4] = {3.0f, 0.5f, 4.25f, 1.0f};
    bool all = img.rgba.size() == 16;
    std::string detail = "size " + std::to_string(img.w) + "x" + std::to_string(img.h);
    for (size_t i = 0; all && i < img.rgba.size(); ++i)
      if (img.rgba[i] != want[i % 4]) {
        all = false;
        detail = "value " + std::to_string(i) + " is " + std::to_string(img.rgba[i]) + ", want " +
            std::to_string(want[i % 4]);
      }
    check(all, "portability." + tag + "_pixels", detail);
  }
  for (GLuint id : {t2, tc, t3}) c.r->delete_texture(id);
  c.r->delete_program(p);
  release(c);
}

void test_compile_error_mapping(Backend b, Api api) {
  std::string tag;
  Ctx c = checked_ctx(b, api, "gl", &tag);
  if (!c.ok()) return;
  const Target t = target_of(api);
  Assembled vs, fs;
  std::string err;
  bool ok = assemble("t_quad.vs", t, Stage::Vertex, {}, &vs, &err) &&
      assemble("t_err_entry.fs", t, Stage::Fragment, {}, &fs, &err);
  check(ok, "gl." + tag + "_assemble_broken", err);
  if (ok) {
    err.clear();
    const GLuint p = c.r->build_program(vs, fs, &err);
    check(p == 0, "gl." + tag + "_broken_shader_rejected");
    if (p) c.r->delete_program(p);
    check(contains(err, "shaders/t_err_lib.glsl:4:"), "gl." + tag + "_error_maps_to_included_file_line", "log: " + err);
    check(contains(err, "fragment"), "gl." + tag + "_error_names_stage", "log: " + err);
  }
  err.clear();
  ok = assemble("t_quad.vs", t, Stage::Vertex, {}, &vs, &err) &&
      assemble("t_err_after.fs", t, Stage::Fragment, {}, &fs, &err);
  if (ok) {
    const GLuint p = c.r->build_program(vs, fs, &err);
    if (p) c.r->delete_program(p);
    check(p == 0 && contains(err, "shaders/t_err_after.fs:5:"), "gl." + tag + "_error_after_include_maps_to_entry_line",
          "log: " + err);
  } else {
    check(false, "gl." + tag + "_error_after_include_maps_to_entry_line", err);
  }
  release(c);
}

// Renders t_const.fs (colour from a define + one RGBA32F texel) into 3x2 pixels.
void render_constant(Ctx &c, Api api, const std::string &tag) {
  const Target t = target_of(api);
  Assembled vs, fs;
  std::string err;
  const std::vector<Define> defs = {{"TS_TEST_COLOR", "vec4(0.25, 0.5, 0.75, 1.0)"}};
  if (!assemble("t_quad.vs", t, Stage::Vertex, {}, &vs, &err) ||
      !assemble("t_const.fs", t, Stage::Fragment, defs, &fs, &err)) {
    check(false, "backends." + tag + "_assemble", err);
    return;
  }
  const GLuint p = c.r->build_program(vs, fs, &err);
  check(p != 0, "backends." + tag + "_build_program", err);
  if (!p) return;
  TextureDesc tex;
  tex.sampler = "u_tex";
  tex.w = tex.h = 1;
  tex.rgba = {0.125f, 2.5f, -3.0f, 6.0f};
  const GLuint tid = c.r->upload_texture(tex);
  ImageF img;
  const bool ok = c.r->draw(p, {{"u_tex", tid}}, 3, 2, &img, &err);
  check(ok, "backends." + tag + "_draw", err);
  if (ok) {
    const float want[4] = {0.375f, 3.0f, -2.25f, 7.0f};
    bool all = img.w == 3 && img.h == 2 && img.rgba.size() == 24;
    std::string detail = "size " + std::to_string(img.w) + "x" + std::to_string(img.h);
    for (size_t i = 0; all && i < img.rgba.size(); ++i) {
      if (img.rgba[i] != want[i % 4]) {
        all = false;
        char b[128];
        snprintf(b, sizeof b, "value %zu is %.9g, want %.9g", i, img.rgba[i], want[i % 4]);
        detail = b;
      }
    }
    check(all, "backends." + tag + "_expected_pixels", detail);
  }
  c.r->delete_texture(tid);
  c.r->delete_program(p);
}

void test_backends_in_one_process() {
  // One context after another, OSMesa and EGL alternating, each released before the next.
  const struct {
    Backend backend;
    Api api;
    const char *tag;
  } kSequence[] = {{Backend::OSMesa, Api::GL33, "osmesa_first"}, {Backend::EGL, Api::GLES3, "egl_gles3"},
                   {Backend::OSMesa, Api::GL33, "osmesa_again"}, {Backend::EGL, Api::GLES2, "egl_gles2"},
                   {Backend::EGL, Api::GL33, "egl_gl33"}};
  for (const auto &step : kSequence) {
    Ctx c = make_ctx(step.backend, step.api);
    check(c.ok(), std::string("backends.") + step.tag + "_context", c.err);
    if (c.ok()) render_constant(c, step.api, step.tag);
    release(c);
  }
  {
    // Two live contexts, one per backend: switch between them with make_current().
    Ctx o = make_ctx(Backend::OSMesa, Api::GL33);
    Ctx e = make_ctx(Backend::EGL, Api::GLES3);
    check(o.ok() && e.ok(), "backends.two_live_contexts", o.err + " " + e.err);
    if (o.ok() && e.ok()) {
      render_constant(e, Api::GLES3, "live_egl_gles3");
      check(o.ctx->make_current(), "backends.live_osmesa_make_current");
      render_constant(o, Api::GL33, "live_osmesa_after_egl");
      check(e.ctx->make_current(), "backends.live_egl_make_current");
      render_constant(e, Api::GLES3, "live_egl_after_osmesa");
    }
    release(e);
    release(o);
  }
  std::string err;
  check(!GlContext::create(Backend::OSMesa, Api::GLES2, &err) && contains(err, "gl33"), "backends.osmesa_gles2_refused",
        "message: " + err);
  err.clear();
  check(!GlContext::create(Backend::CPU, Api::GL33, &err) && !err.empty(), "backends.cpu_has_no_context",
        "message: " + err);
  std::string why;
  check(config_supported(Backend::EGL, Api::GLES2, &why) && !config_supported(Backend::OSMesa, Api::GLES3, &why),
        "backends.config_supported");
}

// ---- variants ------------------------------------------------------------------

void expr_ok(const std::string &e, const std::map<std::string, int> &vars, int want) {
  int v = -12345;
  std::string err;
  const bool ok = eval_expr(e, vars, &v, &err);
  check(ok && v == want, "expr.value " + quote(e),
        ok ? "got " + std::to_string(v) + ", want " + std::to_string(want) : "error: " + err);
}

void expr_err(const std::string &e, const std::map<std::string, int> &vars, const std::string &want_in_msg) {
  int v = 0;
  std::string err;
  const bool ok = eval_expr(e, vars, &v, &err);
  check(!ok && contains(err, want_in_msg), "expr.error " + quote(e),
        ok ? "accepted, value " + std::to_string(v) : "message " + quote(err) + " lacks " + quote(want_in_msg));
}

void test_eval_expr() {
  const std::map<std::string, int> vars = {{"A", 2}, {"B", 0}, {"NUM_LIGHTS", 3}};
  expr_ok("1 + 2 * 3", vars, 7);
  expr_ok("(1 + 2) * 3", vars, 9);
  expr_ok("2 * 3 + 1", vars, 7);
  expr_ok("10 - 3 - 4", vars, 3);
  expr_ok("-3 + 5", vars, 2);
  expr_ok("1 + 2 == 3", vars, 1);
  expr_ok("1 || 1 && 0", vars, 1);
  expr_ok("(1 || 1) && 0", vars, 0);
  expr_ok("0 && 1 || 1", vars, 1);
  expr_ok("A == 2 && B == 0", vars, 1);
  expr_ok("A==2&&B==1", vars, 0);
  expr_ok("A != B", vars, 1);
  expr_ok("NUM_LIGHTS > 2", vars, 1);
  expr_ok("NUM_LIGHTS >= 3 && NUM_LIGHTS <= 3", vars, 1);
  expr_ok("NUM_LIGHTS < 3 || A > 2", vars, 0);
  expr_ok("!0", vars, 1);
  expr_ok("!A", vars, 0);
  expr_ok("!B", vars, 1);
  expr_ok("!A == 0", vars, 1);
  expr_ok("!(A == 0)", vars, 1);
  expr_ok("!!A", vars, 1);
  expr_ok("A * NUM_LIGHTS - 1", vars, 5);
  expr_ok("((A))", vars, 2);
  expr_ok("  A  ", vars, 2);
  expr_err("FOO == 1", vars, "FOO");
  expr_err("A == UNKNOWN_COMBO", vars, "UNKNOWN_COMBO");
  expr_err("1 2", vars, "2");
  expr_err("A == 1 )", vars, ")");
  expr_err("A = 1", vars, "=");
  expr_err("A == 1 garbage", vars, "garbage");
  expr_err("(1 + 2", vars, ")");
  expr_err("", vars, "operand");
  expr_err("1 +", vars, "operand");
  expr_err("&& 1", vars, "operand");
  expr_err("12345678901", vars, "large");
}

// Last check of the program: under UBSan (-fno-sanitize-recover) a signed overflow in the
// evaluator aborts the process, so nothing may come after it.
void test_eval_expr_overflow() {
  const std::map<std::string, int> vars = {{"A", 1000000}};
  for (const char *e : {"1000000 * 1000000 * 1000000", "A * A", "A * 3000 + A * 3000", "0 - A * 2000 - A * 2000"}) {
    int v = 0;
    std::string err;
    const bool ok = eval_expr(e, vars, &v, &err);
    check(!ok && !err.empty(), std::string("expr.overflow_is_an_error '") + e + "'",
          ok ? "accepted, value " + std::to_string(v) + " (int overflow)" : "no message");
  }
}

const char *kSmallDecl =
    "# a small declaration\n"
    "shader   small\n"
    "fragment small.fs\n"
    "vertex   small.vs\n"
    "static   S 0..1\n"
    "dynamic  D 0..2        # innermost\n";

void decl_err(const std::string &name, const std::string &text, const std::string &where, const std::string &what) {
  ShaderDecl d;
  std::string err;
  const bool ok = parse_shader_decl("shaders/t.variants", text, &d, &err);
  check(!ok && contains(err, where) && contains(err, what), "decl.error_" + name,
        ok ? "accepted" : "message " + quote(err) + " wants " + quote(where) + " and " + quote(what));
}

void test_parse_decl() {
  ShaderDecl d;
  std::string err;
  bool ok = parse_shader_decl("shaders/small.variants", kSmallDecl, &d, &err);
  check(ok, "decl.small_parses", err);
  if (ok) {
    check(d.name == "small" && d.fragment == "small.fs" && d.vertex == "small.vs" && d.file == "shaders/small.variants",
          "decl.small_fields");
    check(d.tiers == all_tiers(), "decl.small_default_tiers_all");
    check(d.combos.size() == 2 && d.combos[0].name == "S" && !d.combos[0].dynamic && d.combos[0].min == 0 &&
              d.combos[0].max == 1 && d.combos[1].name == "D" && d.combos[1].dynamic && d.combos[1].max == 2,
          "decl.small_combos");
  }

  const std::string head = "shader t\nfragment t.fs\nvertex t.vs\n";  // lines 1-3
  decl_err("unknown_key", head + "colour red\n", "shaders/t.variants:4:", "colour");
  decl_err("unknown_key_line_after_comments", "# c\n\n" + head + "static A 0..1\nbogus_key 1\n",
           "shaders/t.variants:7:", "bogus_key");
  decl_err("range_no_dots", head + "static A 0-1\n", "shaders/t.variants:4:", "0-1");
  decl_err("range_not_number", head + "static A 0..x\n", "shaders/t.variants:4:", "0..x");
  decl_err("range_trailing", head + "static A 0..1x\n", "shaders/t.variants:4:", "0..1x");
  decl_err("range_empty", head + "static A 3..1\n", "shaders/t.variants:4:", "3..1");
  decl_err("range_too_large", head + "static A 0..1000\n", "shaders/t.variants:4:", "0..1000");
  decl_err("range_overflow", head + "static A 0..99999999999999999999\n", "shaders/t.variants:4:", "range");
  decl_err("range_missing", head + "dynamic A\n", "shaders/t.variants:4:", "MIN..MAX");
  decl_err("unknown_tier_tiers_line", head + "tiers ps20 ps30\n", "shaders/t.variants:4:", "ps30");
  decl_err("unknown_tier_combo", head + "static A 0..1\ndynamic B 0..2 ps20 sm4\n", "shaders/t.variants:5:", "sm4");
  decl_err("unknown_tier_skip", head + "static A 0..1\nskip ps21: A == 1\n", "shaders/t.variants:5:", "ps21");
  decl_err("duplicate_combo", head + "static A 0..1\nstatic B 0..1\ndynamic A 0..3\n", "shaders/t.variants:6:", "'A'");
  decl_err("skip_bad_expression", head + "static A 0..1\nskip ps20: A == \n", "shaders/t.variants:5:", "skip");
  decl_err("skip_unknown_combo", head + "static A 0..1\nskip ps2b: A == 1 && NOPE > 0\n",
           "shaders/t.variants:5:", "NOPE");
  decl_err("skip_trailing_garbage", head + "static A 0..1\nskip sm3: A == 1 1\n",
           "shaders/t.variants:5:", "unexpected");
  decl_err("skip_no_colon", head + "static A 0..1\nskip ps20 A == 1\n", "shaders/t.variants:5:", "skip");
  // "skip: EXPR" (no tiers, colon right after the key) is the all-tier form of "skip [tiers]: EXPR".
  {
    ShaderDecl d2;
    std::string e2;
    const bool ok2 = parse_shader_decl("shaders/t.variants", head + "static A 0..1\nskip: A == 1\n", &d2, &e2);
    check(ok2 && d2.skips.size() == 1 && d2.skips[0].tiers.empty() && d2.skips[0].line == 5,
          "decl.skip_without_tiers_colon_form", ok2 ? "parsed, but the rule is wrong" : "message " + quote(e2));
    const bool ok3 = parse_shader_decl("shaders/t.variants", head + "static A 0..1\nskip ps20 sm3: A == 1\n", &d2, &e2);
    check(ok3 && d2.skips.size() == 1 && d2.skips[0].tiers.size() == 2 && d2.skips[0].tiers[1] == Tier::SM3,
          "decl.skip_with_tiers", e2);
  }
  decl_err("no_shader_line", "fragment t.fs\nvertex t.vs\n", "shaders/t.variants", "shader");
  decl_err("no_fragment_line", "shader t\nvertex t.vs\n", "shaders/t.variants", "fragment");
  decl_err("no_vertex_line", "shader t\nfragment t.fs\n", "shaders/t.variants", "vertex");
}

std::vector<Variant> enumerate_text(const std::string &text, ShaderDecl *d, const std::vector<Tier> &tiers,
                                    std::string *err) {
  if (!parse_shader_decl("shaders/e.variants", text, d, err)) return {};
  return enumerate_variants(*d, tiers, err);
}

// The number of variants of `d` on tier `t` that its .variants file declares: every value of every
// combo the tier has (absent combos read as 0), minus the combinations a skip rule of the tier
// removes. Counted recursively, independently of enumerate_variants' odometer.
size_t count_by_rules(const ShaderDecl &d, Tier t, size_t i = 0, std::map<std::string, int> *vars = nullptr) {
  std::map<std::string, int> own;
  if (!vars) vars = &own;
  const auto in = [t](const std::vector<Tier> &ts) {
    return ts.empty() || std::find(ts.begin(), ts.end(), t) != ts.end();
  };
  if (i == 0 && !in(d.tiers)) return 0;
  if (i == d.combos.size()) {
    for (const SkipRule &r : d.skips) {
      int x = 0;
      std::string e;
      if (in(r.tiers) && (!eval_expr(r.expr, *vars, &x, &e) || x)) return 0;
    }
    return 1;
  }
  const Combo &c = d.combos[i];
  if (!in(c.tiers)) {
    (*vars)[c.name] = 0;
    return count_by_rules(d, t, i + 1, vars);
  }
  size_t n = 0;
  for (int v = c.min; v <= c.max; ++v) {
    (*vars)[c.name] = v;
    n += count_by_rules(d, t, i + 1, vars);
  }
  return n;
}

void test_enumerate() {
  ShaderDecl d;
  std::string err;
  auto v = enumerate_text(kSmallDecl, &d, all_tiers(), &err);
  check(v.size() == 18, "enum.small_count", std::to_string(v.size()) + " variants, want 18; " + err);
  const char *want_ps20[] = {"ps20:S=0,D=0", "ps20:S=0,D=1", "ps20:S=0,D=2",
                             "ps20:S=1,D=0", "ps20:S=1,D=1", "ps20:S=1,D=2"};
  bool order = v.size() == 18;
  std::string detail;
  for (int i = 0; order && i < 6; ++i)
    if (v[i].name() != want_ps20[i]) {
      order = false;
      detail = "variant " + std::to_string(i) + " is " + v[i].name() + ", want " + want_ps20[i];
    }
  check(order, "enum.small_order_dynamic_innermost", detail);
  check(
      v.size() == 18 && v[6].name() == "ps2b:S=0,D=0" && v[12].name() == "sm3:S=0,D=0" && v[17].name() == "sm3:S=1,D=2",
      "enum.small_tier_outermost", v.size() == 18 ? v[6].name() + " " + v[12].name() : "");
  check(v.size() == 18 && v[4].tier == Tier::PS20 && v[4].value("S") == 1 && v[4].value("D") == 1 &&
            v[4].value("NOPE", 7) == 7 && v[4].shader == &d,
        "enum.variant_value_and_fallback");

  // Only the requested tiers, in the order given.
  v = enumerate_variants(d, {Tier::SM3, Tier::PS20}, &err);
  check(v.size() == 12 && v[0].tier == Tier::SM3 && v[6].tier == Tier::PS20, "enum.requested_tiers_only",
        std::to_string(v.size()) + " variants");

  // A dynamic combo declared before a static one is still innermost.
  v = enumerate_text("shader m\nfragment m.fs\nvertex m.vs\ntiers ps20\ndynamic D 0..1\nstatic S 0..2\n", &d,
                     all_tiers(), &err);
  bool dyn_inner = v.size() == 6;
  for (size_t i = 0; dyn_inner && i < v.size(); ++i)
    if (v[i].value("S") != static_cast<int>(i / 2) || v[i].value("D") != static_cast<int>(i % 2)) dyn_inner = false;
  std::string got;
  for (const auto &x : v) got += x.name() + " ";
  check(dyn_inner, "enum.dynamic_innermost_whatever_declaration_order", "order: " + got + err);

  // Skip rules per tier; combos that exist in some tiers only; absent combos read 0.
  const std::string text =
      "shader k\nfragment k.fs\nvertex k.vs\n"
      "tiers ps20 ps2b sm3\n"
      "static  S 0..1\n"
      "static  O 0..2\n"
      "dynamic L 0..4 ps20 ps2b\n"
      "skip ps20: O != 0\n"
      "skip ps20: L > 2\n"
      "skip ps2b sm3: S == 1 && O == 2\n"
      "skip : L == 0 && S == 1 && O == 1\n";  // no tiers: every tier
  v = enumerate_text(text, &d, {Tier::PS20}, &err);
  // ps20: O=0 only, L 0..2: S(2) x L(3) = 6; last rule needs O==1: none removed.
  check(v.size() == 6, "enum.skip_ps20_count", std::to_string(v.size()) + " variants, want 6; " + err);
  bool ps20_ok = !v.empty();
  for (const auto &x : v)
    if (x.value("O") != 0 || x.value("L") > 2) ps20_ok = false;
  check(ps20_ok, "enum.skip_ps20_rules_hold");
  v = enumerate_text(text, &d, {Tier::PS2B}, &err);
  // ps2b: S(2) x O(3) x L(5) = 30, minus S=1,O=2 (5), minus L=0,S=1,O=1 (1) = 24.
  check(v.size() == 24, "enum.skip_ps2b_count", std::to_string(v.size()) + " variants, want 24; " + err);
  v = enumerate_text(text, &d, {Tier::SM3}, &err);
  // sm3: L absent (reads 0): S(2) x O(3) = 6, minus S=1,O=2, minus S=1,O=1 = 4.
  check(v.size() == 4, "enum.skip_sm3_absent_combo_reads_zero", std::to_string(v.size()) + " variants, want 4; " + err);
  bool no_l = !v.empty();
  for (const auto &x : v)
    if (x.values.size() != 2 || x.value("L", -1) != -1) no_l = false;
  check(no_l, "enum.combo_absent_from_tier_not_in_values", v.empty() ? "" : v[0].name());

  // A shader restricted to some tiers enumerates nothing in the others.
  v = enumerate_text("shader r\nfragment r.fs\nvertex r.vs\ntiers sm3\nstatic A 0..1\n", &d, {Tier::PS20, Tier::PS2B},
                     &err);
  check(v.empty(), "enum.shader_tiers_respected", std::to_string(v.size()) + " variants");
  v = enumerate_variants(d, all_tiers(), &err);
  check(v.size() == 2 && v[0].tier == Tier::SM3, "enum.shader_tiers_only_sm3");

  // No combos at all: one variant per tier.
  v = enumerate_text("shader n\nfragment n.fs\nvertex n.vs\n", &d, all_tiers(), &err);
  check(v.size() == 3 && v[0].name() == "ps20:", "enum.no_combos_one_per_tier", v.empty() ? "none" : v[0].name());
}

void test_model_lighting() {
  std::vector<ShaderDecl> decls;
  std::string err;
  const bool ok = load_shader_decls(&decls, &err);
  check(ok, "model_lighting.load_decls", err);
  if (!ok) return;
  const ShaderDecl *ml = nullptr;
  for (const auto &d : decls)
    if (d.name == "model_lighting") ml = &d;
  check(ml != nullptr, "model_lighting.declared");
  if (!ml) return;
  check(ml->fragment == "model_lighting.fs" && ml->vertex == "model_lighting.vs" &&
            ml->file == "shaders/model_lighting.variants",
        "model_lighting.entry_files");
  bool sorted = true;
  for (size_t i = 1; i < decls.size(); ++i)
    if (decls[i - 1].name > decls[i].name) sorted = false;
  check(sorted, "model_lighting.decls_sorted_by_name");

  const auto ps20 = enumerate_variants(*ml, {Tier::PS20}, &err);
  const auto ps2b = enumerate_variants(*ml, {Tier::PS2B}, &err);
  const auto sm3 = enumerate_variants(*ml, {Tier::SM3}, &err);
  // The counts come from the .variants file itself: a product of the combo ranges minus what the
  // skip rules remove, counted by brute force (count_by_rules) rather than written in the test.
  check(!ps20.empty() && ps20.size() == count_by_rules(*ml, Tier::PS20), "model_lighting.ps20_count_from_rules",
        std::to_string(ps20.size()) + " enumerated, " + std::to_string(count_by_rules(*ml, Tier::PS20)) + " by rules");
  check(!ps2b.empty() && ps2b.size() == count_by_rules(*ml, Tier::PS2B), "model_lighting.ps2b_count_from_rules",
        std::to_string(ps2b.size()) + " enumerated, " + std::to_string(count_by_rules(*ml, Tier::PS2B)) + " by rules");
  check(!sm3.empty() && sm3.size() == count_by_rules(*ml, Tier::SM3), "model_lighting.sm3_count_from_rules",
        std::to_string(sm3.size()) + " enumerated, " + std::to_string(count_by_rules(*ml, Tier::SM3)) + " by rules");
  for (const ShaderDecl &d : decls) {
    size_t want = 0;
    for (Tier t : all_tiers()) want += count_by_rules(d, t);
    const size_t got = enumerate_variants(d, all_tiers(), &err).size();
    check(got > 0 && got == want, "variants." + d.name + ".count_from_rules",
          std::to_string(got) + " enumerated, " + std::to_string(want) + " by rules");
  }
  bool ps20_rules = !ps20.empty();
  for (const auto &v : ps20)
    if (v.value("OUTPUT_MODE", -1) != 0 || v.value("NUM_LIGHTS", -1) < 0 || v.value("NUM_LIGHTS", -1) > 2)
      ps20_rules = false;
  check(ps20_rules, "model_lighting.ps20_linear_output_and_at_most_2_lights");
  bool sm3_loop = !sm3.empty();
  for (const auto &v : sm3)
    if (v.value("NUM_LIGHTS", -1) != -1) sm3_loop = false;
  check(sm3_loop, "model_lighting.sm3_has_no_NUM_LIGHTS_combo");
  const auto all = enumerate_variants(*ml, all_tiers(), &err);
  check(all.size() == ps20.size() + ps2b.size() + sm3.size(), "model_lighting.all_tiers_is_the_sum",
        std::to_string(all.size()));
  check(!ps20.empty() && ps20[0].name() == "ps20:ALBEDO_TEXTURE=0,HALF_LAMBERT=0,OUTPUT_MODE=0,NUM_LIGHTS=0" &&
            ps20[1].name() == "ps20:ALBEDO_TEXTURE=0,HALF_LAMBERT=0,OUTPUT_MODE=0,NUM_LIGHTS=1",
        "model_lighting.first_names", ps20.empty() ? "" : ps20[0].name() + " " + ps20[1].name());

  // find_variant by name and by index in the all-tier list.
  Variant v;
  err.clear();
  const std::string name =
      "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=0,OUTPUT_MODE=2,PHONG=0,PHONG_EXPONENT_MAP=0,RIM_LIGHT=0,ENVMAP=0,LIGHT_WARP="
      "0,"
      "NUM_LIGHTS=4";
  bool f = find_variant(decls, "model_lighting", name, &v, &err);
  check(f && v.name() == name && v.tier == Tier::PS2B && v.value("OUTPUT_MODE") == 2 && v.value("NUM_LIGHTS") == 4,
        "find_variant.by_name", err);
  // A short name: the combos left out take their minimum.
  f = find_variant(decls, "model_lighting", "ps2b:ALBEDO_TEXTURE=1,OUTPUT_MODE=2,NUM_LIGHTS=4", &v, &err);
  check(f && v.name() == name, "find_variant.by_short_name", f ? v.name() : err);
  err.clear();
  f = find_variant(decls, "model_lighting", "ps2b:ALBEDO_TEXTURE=1,NO_SUCH_COMBO=1", &v, &err);
  check(!f && contains(err, "no variant"), "find_variant.short_name_unknown_combo", "message: " + err);
  f = find_variant(decls, "model_lighting", "12", &v, &err);
  check(f && v.name() == all.at(12).name() && v.tier == Tier::PS2B, "find_variant.by_index_12", f ? v.name() : err);
  f = find_variant(decls, "model_lighting", "0", &v, &err);
  check(f && v.name() == all.at(0).name(), "find_variant.by_index_0", f ? v.name() : err);
  f = find_variant(decls, "model_lighting", "275", &v, &err);
  check(f && v.name() == all.at(275).name() && v.tier == Tier::SM3, "find_variant.by_index_last", f ? v.name() : err);
  err.clear();
  f = find_variant(decls, "model_lighting", "276", &v, &err);
  check(!f && contains(err, "'276'") && contains(err, "model_lighting"), "find_variant.index_out_of_range_message",
        "message: " + err);
  err.clear();
  f = find_variant(decls, "model_lighting", "ps20:ALBEDO_TEXTURE=7", &v, &err);
  check(!f && contains(err, "no variant 'ps20:ALBEDO_TEXTURE=7'"), "find_variant.unknown_name_message",
        "message: " + err);
  err.clear();
  f = find_variant(decls, "model_lighting", "ps20:ALBEDO_TEXTURE=0,HALF_LAMBERT=0,OUTPUT_MODE=1,NUM_LIGHTS=0", &v,
                   &err);
  check(!f && !err.empty(), "find_variant.skipped_variant_not_found", "message: " + err);
  err.clear();
  f = find_variant(decls, "no_such_shader", "0", &v, &err);
  check(!f && contains(err, "no_such_shader"), "find_variant.unknown_shader_message", "message: " + err);

  // The real fragment shader assembles for every target from the embedded library.
  for (Target t : {Target::ESSL100, Target::ESSL300, Target::GLSL330}) {
    Assembled a;
    err.clear();
    std::vector<Define> defs;
    for (const auto &kv : ps20.at(0).values) defs.push_back({kv.first, std::to_string(kv.second)});
    const bool aok = assemble(ml->fragment, t, Stage::Fragment, defs, &a, &err);
    check(aok && !a.files.empty() && a.files[0] == "shaders/model_lighting.fs" &&
              contains(a.text, "#define NUM_LIGHTS 0\n") && !contains(a.text, "#include"),
          std::string("model_lighting.embedded_assembles_") + target_name(t), err);
  }
}

void test_tiers() {
  Tier t;
  check(parse_tier("ps20", &t) && t == Tier::PS20 && parse_tier("ps2b", &t) && t == Tier::PS2B &&
            parse_tier("sm3", &t) && t == Tier::SM3,
        "tiers.parse");
  check(!parse_tier("ps30", &t) && !parse_tier("", &t) && !parse_tier("PS20", &t), "tiers.parse_rejects");
  check(std::string(tier_name(Tier::PS20)) == "ps20" && std::string(tier_name(Tier::PS2B)) == "ps2b" &&
            std::string(tier_name(Tier::SM3)) == "sm3",
        "tiers.names");
}

}  // namespace

int main() {
  char tmpl[] = "/tmp/tiershade_test_glue.XXXXXX";
  if (!mkdtemp(tmpl)) {
    printf("FAIL setup: mkdtemp failed: %s\n", strerror(errno));
    return 1;
  }
  g_dir = tmpl;
  check(shader_library_read(kPortabilityHeader, &g_header) && !g_header.empty(), "setup.embedded_portability_header");
  write_shader(kPortabilityHeader, g_header);
  setenv("TIERSHADE_SHADER_DIR", g_dir.c_str(), 1);

  test_targets_and_prelude();
  test_portability_header_errors();
  test_defines();
  test_precision_option();
  test_includes();
  test_include_errors();
  test_map_compile_log();
  write_gl_shaders();
  test_compile_error_mapping(Backend::OSMesa, Api::GL33);
  test_compile_error_mapping(Backend::EGL, Api::GLES2);
  test_compile_error_mapping(Backend::EGL, Api::GLES3);
  write_portability_shaders();
  test_portability_macros(Backend::OSMesa, Api::GL33);
  test_portability_macros(Backend::EGL, Api::GLES2);
  test_portability_macros(Backend::EGL, Api::GLES3);
  test_backends_in_one_process();

  unsetenv("TIERSHADE_SHADER_DIR");
  remove_dir();

  test_tiers();
  test_eval_expr();
  test_parse_decl();
  test_enumerate();
  test_model_lighting();
  test_eval_expr_overflow();

  return finish();
}

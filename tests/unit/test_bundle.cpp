// tiershade tests: shader bundles end to end without a scene. For each API it writes
// a bundle of three variants (model_lighting ps20 with per-vertex lights, sm3 Phong with every
// texture and the tangent frame, the last sm3 world_lighting variant), renders two overlapping
// spheres per variant through tiershade's production programs into RGBA32F + depth, writes
// the draw dump, and runs the bare program (bare_gl_render, next to this binary), which must
// reproduce the frame bit for bit; a dump with one corrupted uniform and one with a swapped
// variant must not. Prints PASS/FAIL lines; exit 1 if any failed.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bundle/bundle.h"
#include "conform/conform.h"
#include "bundle/draw_dump.h"
#include "gl/program_info.h"
#include "unit_check.h"

namespace {

void sphere(float cx, float cz, DumpDraw *d) {
  const int nu = 16, nv = 10;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      const float th = 3.14159265f * j / nv, ph = 6.2831853f * i / nu;
      const float n[3] = {std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)};
      d->position.insert(d->position.end(), {cx + 0.6f * n[0], 0.6f * n[1], cz + 0.6f * n[2]});
      d->normal.insert(d->normal.end(), n, n + 3);
      d->uv.insert(d->uv.end(), {2.f * i / nu, 1.f * j / nv});
      d->tangent.insert(d->tangent.end(), {-std::sin(ph), 0.f, std::cos(ph), 1.f});
      d->lightmap.insert(d->lightmap.end(), {1.f * i / nu, 1.f * j / nv, 0.01f, 0.f});
    }
  }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = j * (nu + 1) + i, b = a + nu + 1;
      d->indices.insert(d->indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
}

TextureDesc random_texture(const ProgramVar &s, Rng &rng) {
  TextureDesc t;
  t.sampler = s.name;
  t.kind = s.type == GL_SAMPLER_CUBE ? TexKind::Cube : s.type == GL_SAMPLER_3D ? TexKind::Tex3D : TexKind::Tex2D;
  t.w = t.h = t.kind == TexKind::Tex2D ? 8 : 4;
  t.d = t.kind == TexKind::Tex3D ? 4 : 1;
  t.linear = true;
  t.repeat = t.kind == TexKind::Tex2D;
  const size_t n = static_cast<size_t>(t.w) * t.h * t.d * (t.kind == TexKind::Cube ? 6 : 1) * 4;
  for (size_t i = 0; i < n; ++i) t.rgba.push_back(rng.uniform(0.05f, 1.f));
  return t;
}

// Renders the draws (shader/variant and geometry set) with generic uniforms; fills uniforms,
// textures and the frame.
bool render(GlContext &ctx, const std::vector<Variant> &vars, DumpFrame *f, std::string *err) {
  const GlFns &g = ctx.gl();
  GlRenderer r(ctx);
  GLuint color = 0, depth = 0, fbo = 0, vao = 0;
  g.GenTextures(1, &color);
  g.BindTexture(GL_TEXTURE_2D, color);
  g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, f->w, f->h, 0, GL_RGBA, GL_FLOAT, nullptr);
  g.GenRenderbuffers(1, &depth);
  g.BindRenderbuffer(GL_RENDERBUFFER, depth);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, f->w, f->h);
  g.GenFramebuffers(1, &fbo);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  g.GenVertexArrays(1, &vao);
  g.BindVertexArray(vao);
  g.Viewport(0, 0, f->w, f->h);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LESS);
  g.ClearColor(f->clear[0], f->clear[1], f->clear[2], f->clear[3]);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  Rng rng(7);
  std::vector<GLuint> objects;
  for (size_t i = 0; i < f->draws.size(); ++i) {
    DumpDraw &d = f->draws[i];
    const Variant &v = vars[i / 2];
    GLuint p = build_production_program(r, ctx.api(), v, err);
    if (!p) return false;
    std::vector<ProgramVar> attrs, unis;
    if (!program_attributes(g, p, &attrs, err) || !program_uniforms(g, p, &unis, err)) return false;
    for (size_t k = 0; k < attrs.size(); ++k) g.BindAttribLocation(p, static_cast<GLuint>(k), attrs[k].name.c_str());
    g.LinkProgram(p);
    g.UseProgram(p);
    int unit = 0;
    for (const auto &u : unis) {
      const GLint loc = g.GetUniformLocation(p, u.name.c_str());
      const int n = u.is_array ? u.array_size : 1;
      if (u.type == GL_SAMPLER_2D || u.type == GL_SAMPLER_CUBE || u.type == GL_SAMPLER_3D) {
        d.textures.push_back(std::make_shared<const TextureDesc>(random_texture(u, rng)));
        g.ActiveTexture(GL_TEXTURE0 + unit);
        objects.push_back(r.upload_texture(*d.textures.back()));
        g.Uniform1i(loc, unit++);
      } else if (u.type == GL_FLOAT_MAT4) {
        const float m[16] = {u.name == "u_model" ? 1.f : 0.5f,
                             0,
                             0,
                             0,
                             0,
                             u.name == "u_model" ? 1.f : 0.8f,
                             0,
                             0,
                             0,
                             0,
                             u.name == "u_model" ? 1.f : -0.25f,
                             0,
                             0,
                             0,
                             0,
                             1};
        g.UniformMatrix4fv(loc, 1, GL_FALSE, m);
      } else if (u.type == GL_FLOAT_VEC4) {
        std::vector<float> x;
        for (int k = 0; k < 4 * n; ++k) x.push_back(rng.uniform(0.05f, 1.f));
        if (u.name == "u_params") x = {1.f, 2.f, 0.5f, 0.5f};
        g.Uniform4fv(loc, n, x.data());
      } else {
        *err = "test: uniform " + u.name + " of an unexpected type";
        return false;
      }
    }
    g.ActiveTexture(GL_TEXTURE0);
    if (!dump_capture_uniforms(g, p, &d.uniforms, err)) return false;
    for (size_t k = 0; k < attrs.size(); ++k) {
      const std::vector<float> &a = attrs[k].name == "a_position" ? d.position
          : attrs[k].name == "a_normal"                           ? d.normal
          : attrs[k].name == "a_uv"                               ? d.uv
          : attrs[k].name == "a_tangent"                          ? d.tangent
                                                                  : d.lightmap;
      GLuint b = 0;
      g.GenBuffers(1, &b);
      g.BindBuffer(GL_ARRAY_BUFFER, b);
      g.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(a.size() * 4), a.data(), GL_STATIC_DRAW);
      g.VertexAttribPointer(static_cast<GLuint>(k), static_cast<GLint>(a.size() / (d.position.size() / 3)), GL_FLOAT,
                            GL_FALSE, 0, nullptr);
      g.EnableVertexAttribArray(static_cast<GLuint>(k));
    }
    GLuint ib = 0;
    g.GenBuffers(1, &ib);
    g.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ib);
    g.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(d.indices.size() * 4), d.indices.data(),
                 GL_STATIC_DRAW);
    g.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.indices.size()), GL_UNSIGNED_INT, nullptr);
    r.delete_program(p);
  }
  f->rgba.resize(static_cast<size_t>(f->w) * f->h * 4);
  g.ReadPixels(0, 0, f->w, f->h, GL_RGBA, GL_FLOAT, f->rgba.data());
  const GLenum e = g.GetError();
  for (GLuint t : objects) r.delete_texture(t);
  g.DeleteFramebuffers(1, &fbo);
  g.DeleteRenderbuffers(1, &depth);
  g.DeleteTextures(1, &color);
  g.DeleteVertexArrays(1, &vao);
  if (e != GL_NO_ERROR) {
    *err = "GL error " + std::to_string(e);
    return false;
  }
  return true;
}

// Runs the bare program; returns its exit status and its stdout.
int run_bare(const std::string &bare, const std::string &b, const std::string &d, const char *api, std::string *out) {
  const std::string cmd = "'" + bare + "' --bundle '" + b + "' --dump '" + d + "' --api " + api + " 2>&1";
  FILE *p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  char buf[512];
  out->clear();
  while (fgets(buf, sizeof buf, p)) *out += buf;
  const int st = pclose(p);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace

int main(int, char **argv) {
  const std::string bare = (std::filesystem::path(argv[0]).parent_path() / "bare_gl_render").string();
  char tmpl[] = "/tmp/test_bundle.XXXXXX";
  if (!mkdtemp(tmpl)) {
    printf("FAIL setup: mkdtemp\n");
    return 1;
  }
  const std::string tmp = tmpl;
  std::vector<ShaderDecl> decls;
  std::string err;
  if (!load_shader_decls(&decls, &err)) {
    printf("FAIL setup: %s\n", err.c_str());
    return 1;
  }
  std::vector<Variant> vars(2);
  bool ok = find_variant(decls, "model_lighting", "ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=0,NUM_LIGHTS=2",
                         &vars[0], &err) &&
      find_variant(decls, "model_lighting",
                   "sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,"
                   "ENVMAP=1,LIGHT_WARP=1",
                   &vars[1], &err);
  for (const auto &d : decls)
    if (d.name == "world_lighting") vars.push_back(enumerate_variants(d, {Tier::SM3}, &err).back());
  check(ok && vars.size() == 3, "setup: three variants", err);
  if (!ok || vars.size() != 3) return 1;
  const struct {
    Api api;
    Target target;
  } kRuns[] = {{Api::GLES2, Target::ESSL100}, {Api::GLES3, Target::ESSL300}, {Api::GL33, Target::GLSL330}};
  for (const auto &run : kRuns) {
    const std::string api = api_name(run.api);
    const std::string b = tmp + "/bundle_" + api, d = tmp + "/dump_" + api;
    std::vector<BundleEntry> entries;
    for (const auto &v : vars) entries.push_back({&v, {"test"}});
    err.clear();
    const bool wrote = write_bundle(entries, run.target, b, "test_bundle", &err);
    check(wrote, api + ": write_bundle", err);
    auto ctx = GlContext::create(Backend::EGL, run.api, &err);
    DumpFrame f;
    f.w = 96;
    f.h = 64;
    f.clear[0] = 0.1f;
    f.clear[3] = 1.f;
    for (size_t i = 0; i < 2 * vars.size(); ++i) {
      DumpDraw dd;
      dd.shader = vars[i / 2].shader->name;
      dd.variant = vars[i / 2].name();
      sphere(-1.2f + 0.5f * static_cast<float>(i), 0.3f * static_cast<float>(i % 2), &dd);
      f.draws.push_back(dd);
    }
    const bool rendered = ctx && render(*ctx, vars, &f, &err) && write_draw_dump(d, f, &err);
    check(rendered, api + ": render and write the draw dump", err);
    if (!wrote || !rendered) continue;
    long covered = 0;
    for (size_t i = 0; i < f.rgba.size(); i += 4) covered += f.rgba[i] != f.clear[0];
    check(covered > f.w * f.h / 4, api + ": the spheres cover the frame", std::to_string(covered) + " pixels");
    std::string out;
    int st = run_bare(bare, b, d, api.c_str(), &out);
    check(st == 0 && out.find(", 0 channels differ") != std::string::npos, api + ": bare GL replay is bit-identical",
          "status " + std::to_string(st) + ": " + out);
    // Negative controls: the comparison must be able to fail.
    DumpFrame bad = f;
    for (auto &u : bad.draws[2].uniforms)
      if (u.name == "u_ambient_cube") u.values[0] *= 2.f;
    st = -1;
    if (write_draw_dump(d + "_uniform", bad, &err)) st = run_bare(bare, b, d + "_uniform", api.c_str(), &out);
    check(st == 1 && out.find(" 0 channels differ") == std::string::npos, api + ": a corrupted uniform is caught",
          "status " + std::to_string(st) + ": " + out);
    bad = f;
    bad.draws[1].variant = bad.draws[2].variant;
    bad.draws[1].uniforms = bad.draws[2].uniforms;
    bad.draws[1].textures = bad.draws[2].textures;
    st = -1;
    if (write_draw_dump(d + "_swapped", bad, &err)) st = run_bare(bare, b, d + "_swapped", api.c_str(), &out);
    check(st == 1, api + ": a swapped variant is caught", "status " + std::to_string(st) + ": " + out);
  }
  std::error_code ec;
  std::filesystem::remove_all(tmp, ec);
  return g_failed ? 1 : 0;
}

// tiershade bundle: the draw dump (see draw_dump.h and docs/bundles.md).
#include "bundle/draw_dump.h"

#include <algorithm>

#include <cstdio>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>

#include "io/atomic_dir.h"
#include "gl/type_names.h"
#include "gl/program_info.h"

using json = nlohmann::ordered_json;

bool dump_capture_uniforms(const GlFns &gl, GLuint program, std::vector<DumpUniform> *out, std::string *err) {
  std::vector<ProgramVar> vars;
  if (!program_uniforms(gl, program, &vars, err)) return false;
  out->clear();
  for (const auto &v : vars) {
    if (gl_type_is_sampler(v.type)) continue;
    DumpUniform u;
    u.name = v.name;
    u.type = gl_type_glsl_name(v.type);
    u.array_size = v.is_array ? v.array_size : 0;
    const int comps = gl_type_components(v.type);
    const int n = v.is_array ? v.array_size : 1;
    for (int i = 0; i < n; ++i) {
      const std::string elem = v.is_array ? v.name + "[" + std::to_string(i) + "]" : v.name;
      const GLint loc = gl.GetUniformLocation(program, elem.c_str());
      if (loc < 0) {
        *err = "uniform " + elem + " is active but has no location";
        return false;
      }
      if (gl_type_is_float(v.type)) {
        float buf[16] = {0};
        gl.GetUniformfv(program, loc, buf);
        u.values.insert(u.values.end(), buf, buf + comps);
      } else {
        GLint buf[16] = {0};
        gl.GetUniformiv(program, loc, buf);
        for (int k = 0; k < comps; ++k) u.values.push_back(static_cast<float>(buf[k]));
      }
    }
    out->push_back(u);
  }
  const GLenum e = gl.GetError();
  if (e != GL_NO_ERROR) {
    *err = "GL error " + std::to_string(e) + " while reading the uniforms";
    return false;
  }
  return true;
}

namespace {

uint32_t bits_of(float f) {
  uint32_t b;
  memcpy(&b, &f, 4);
  return b;
}

json float_bits(const float *v, size_t n) {
  json a = json::array();
  for (size_t i = 0; i < n; ++i) a.push_back(bits_of(v[i]));
  return a;
}

const char *kind_name(TexKind k) { return k == TexKind::Cube ? "cube" : k == TexKind::Tex3D ? "3d" : "2d"; }

size_t texel_count(const TextureDesc &t) {
  const size_t w = static_cast<size_t>(t.w), h = static_cast<size_t>(t.h), d = static_cast<size_t>(t.d);
  return t.kind == TexKind::Cube ? w * w * 6 : t.kind == TexKind::Tex3D ? w * h * d : w * h;
}

bool check_draw(const DumpDraw &d, size_t i, std::string *err) {
  const std::string where = "draw " + std::to_string(i) + " (" + d.shader + " " + d.variant + "): ";
  const size_t n = d.position.size() / 3;
  if (d.position.size() % 3 || d.normal.size() != 3 * n || d.uv.size() != 2 * n ||
      !(d.tangent.empty() || d.tangent.size() == 4 * n) || !(d.lightmap.empty() || d.lightmap.size() == 4 * n)) {
    *err = where + "vertex arrays of different lengths";
    return false;
  }
  if (d.indices.size() % 3) {
    *err = where + "index count is not a multiple of 3";
    return false;
  }
  for (uint32_t k : d.indices)
    if (k >= n) {
      *err = where + "index " + std::to_string(k) + " out of range (" + std::to_string(n) + " vertices)";
      return false;
    }
  for (const auto &tp : d.textures) {
    if (!tp) {
      *err = where + "a texture is missing";
      return false;
    }
    const TextureDesc &t = *tp;
    if (t.w <= 0 || t.h <= 0 || t.d <= 0 || (t.kind == TexKind::Cube && t.w != t.h) ||
        t.rgba.size() != texel_count(t) * 4) {
      *err = where + "texture " + t.sampler + " has a size that does not match its texels";
      return false;
    }
    for (size_t k = 0; k < t.mips.size(); ++k) {
      const int l = static_cast<int>(k) + 1;
      if (t.kind != TexKind::Tex2D || l >= 31 ||
          t.mips[k].size() != static_cast<size_t>(std::max(1, t.w >> l)) * std::max(1, t.h >> l) * 4) {
        *err = where + "texture " + t.sampler + ": mip level " + std::to_string(l) + " does not match its size";
        return false;
      }
    }
  }
  for (const auto &u : d.uniforms) {
    const size_t per = u.values.size() / static_cast<size_t>(u.array_size > 0 ? u.array_size : 1);
    if (u.values.empty() || per * static_cast<size_t>(u.array_size > 0 ? u.array_size : 1) != u.values.size()) {
      *err = where + "uniform " + u.name + " has " + std::to_string(u.values.size()) + " values";
      return false;
    }
  }
  return true;
}

// FNV-1a 64 over a level's header (kind, size) and its texels.
uint64_t content_hash(TexKind kind, int w, int h, int d, const std::vector<float> &texels) {
  uint64_t x = 1469598103934665603ull;
  auto mix = [&](const void *p, size_t n) {
    const unsigned char *c = static_cast<const unsigned char *>(p);
    for (size_t i = 0; i < n; ++i) x = (x ^ c[i]) * 1099511628211ull;
  };
  const int hdr[4] = {static_cast<int>(kind), w, h, d};
  mix(hdr, sizeof hdr);
  mix(texels.data(), texels.size() * sizeof(float));
  return x;
}
uint64_t content_hash(const TextureDesc &t) { return content_hash(t.kind, t.w, t.h, t.d, t.rgba); }

}  // namespace

bool write_draw_dump(const std::string &dir, const DumpFrame &f, std::string *err) {
  if (f.w <= 0 || f.h <= 0 || f.rgba.size() != static_cast<size_t>(f.w) * f.h * 4) {
    *err = "draw dump: the frame is not " + std::to_string(f.w) + " x " + std::to_string(f.h) + " RGBA";
    return false;
  }
  if (f.depth_format != "DEPTH_COMPONENT24" && f.depth_format != "DEPTH_COMPONENT32F") {
    *err = "draw dump: unknown depth format " + f.depth_format;
    return false;
  }
  for (size_t i = 0; i < f.draws.size(); ++i)
    if (!check_draw(f.draws[i], i, err)) return false;
  DirWriter w;
  if (!w.begin(dir, "draws.json", "draw dump", err)) return false;
  std::map<uint64_t, std::string> tex_files;  // content hash -> file
  std::map<const TextureDesc *, std::string> tex_of;  // each shared texture hashed once
  json draws = json::array();
  for (size_t i = 0; i < f.draws.size(); ++i) {
    const DumpDraw &d = f.draws[i];
    char stem[32];
    snprintf(stem, sizeof stem, "draw_%03zu", i);
    const std::string s = stem;
    json j;
    j["shader"] = d.shader;
    j["variant"] = d.variant;
    j["vertices"] = d.position.size() / 3;
    j["indices"] = d.indices.size();
    auto put = [&](const char *key, const void *data, size_t bytes, const char *ext) {
      const std::string name = s + "." + key + ext;
      j[std::string(key) + "_file"] = name;
      return w.write(name, data, bytes, err);
    };
    if (!put("position", d.position.data(), d.position.size() * 4, ".f32") ||
        !put("normal", d.normal.data(), d.normal.size() * 4, ".f32") ||
        !put("uv", d.uv.data(), d.uv.size() * 4, ".f32") ||
        (!d.tangent.empty() && !put("tangent", d.tangent.data(), d.tangent.size() * 4, ".f32")) ||
        (!d.lightmap.empty() && !put("lightmap", d.lightmap.data(), d.lightmap.size() * 4, ".f32")) ||
        !put("index", d.indices.data(), d.indices.size() * 4, ".u32"))
      return false;
    if (d.tangent.empty()) j["tangent_file"] = nullptr;
    if (d.lightmap.empty()) j["lightmap_file"] = nullptr;
    json ju = json::array();
    for (const auto &u : d.uniforms)
      ju.push_back({{"name", u.name},
                    {"type", u.type},
                    {"array_size", u.array_size},
                    {"values", u.values},
                    {"bits", float_bits(u.values.data(), u.values.size())}});
    j["uniforms"] = ju;
    json jt = json::array();
    for (const auto &tp : d.textures) {
      const TextureDesc &t = *tp;
      auto known = tex_of.find(&t);
      if (known == tex_of.end()) {
        const uint64_t h = content_hash(t);
        auto it = tex_files.find(h);
        if (it == tex_files.end()) {
          char name[48];
          snprintf(name, sizeof name, "tex_%016llx.f32", static_cast<unsigned long long>(h));
          if (!w.write(name, t.rgba.data(), t.rgba.size() * 4, err)) return false;
          it = tex_files.emplace(h, name).first;
        }
        known = tex_of.emplace(&t, it->second).first;
      }
      // The mip chain's levels 1..n (docs/rendering.md "Mipmaps"), each a file like level 0.
      json levels = json::array();
      for (size_t k = 0; k < t.mips.size(); ++k) {
        const int l = static_cast<int>(k) + 1, lw = std::max(1, t.w >> l), lh = std::max(1, t.h >> l);
        const uint64_t h = content_hash(t.kind, lw, lh, 1, t.mips[k]);
        auto it = tex_files.find(h);
        if (it == tex_files.end()) {
          char name[48];
          snprintf(name, sizeof name, "tex_%016llx.f32", static_cast<unsigned long long>(h));
          if (!w.write(name, t.mips[k].data(), t.mips[k].size() * 4, err)) return false;
          it = tex_files.emplace(h, name).first;
        }
        levels.push_back(it->second);
      }
      jt.push_back({{"sampler", t.sampler},
                    {"kind", kind_name(t.kind)},
                    {"w", t.w},
                    {"h", t.h},
                    {"d", t.d},
                    {"linear", t.linear},
                    {"repeat", t.repeat},
                    {"file", known->second},
                    {"mip_filter", t.mips.empty() ? "none" : t.mip_filter == 1 ? "nearest" : "linear"},
                    {"levels", levels}});
    }
    j["textures"] = jt;
    draws.push_back(j);
  }
  if (!w.write("frame.f32", f.rgba.data(), f.rgba.size() * 4, err)) return false;
  json m;
  m["tiershade_draw_dump"] = 1;
  m["width"] = f.w;
  m["height"] = f.h;
  m["clear"] = {f.clear[0], f.clear[1], f.clear[2], f.clear[3]};
  m["clear_bits"] = float_bits(f.clear, 4);
  m["depth_format"] = f.depth_format;
  m["frame_file"] = "frame.f32";
  if (f.camera.present) {
    const DumpCamera &c = f.camera;
    json jc = {{"projection", c.orthographic ? "orthographic" : "perspective"},
               {"eye", {c.eye[0], c.eye[1], c.eye[2]}},
               {"forward", {c.forward[0], c.forward[1], c.forward[2]}},
               {"up", {c.up[0], c.up[1], c.up[2]}},
               {"znear", c.znear},
               {"zfar", c.zfar}};
    if (c.orthographic) {
      jc["xmag"] = c.xmag;
      jc["ymag"] = c.ymag;
    } else {
      jc["yfov"] = c.yfov;
    }
    m["camera"] = jc;
  }
  m["draws"] = draws;
  if (!w.write("draws.json", m.dump(1) + "\n", err)) return false;
  return w.commit(err);
}

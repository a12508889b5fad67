// tiershade glue: load_scene (glue/scene/scene.h): a glTF 2.0 file (.gltf or .glb) read with
// tinygltf, checked (JSON syntax and finite numbers, external files, accessors, indices), and
// flattened to world-space triangles, cameras and lights. Materials: scene_gltf_source.cpp;
// lights and tiershade extras: scene_gltf_extras.cpp. Format: docs/scenes.md.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "scene/gltf_util.h"

namespace scene_gltf {
namespace {

using tinygltf::Model;

// ---------------------------------------------------------------- file & JSON checks ---

bool read_file(const std::string &path, std::vector<unsigned char> *out, Err &e) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return e.fail("", "cannot open the file");
  out->assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  if (f.bad()) return e.fail("", "read error");
  return true;
}

uint32_t le32(const unsigned char *p) { return p[0] | p[1] << 8 | p[2] << 16 | static_cast<uint32_t>(p[3]) << 24; }

// The JSON chunk of a .glb (header and chunk bounds checked).
bool glb_json(const std::vector<unsigned char> &b, std::string *json, Err &e) {
  if (b.size() < 20) return e.fail("GLB header", "file is " + std::to_string(b.size()) + " bytes, too short");
  if (memcmp(b.data(), "glTF", 4) != 0) return e.fail("GLB header", "bad magic (expected \"glTF\")");
  if (le32(&b[4]) != 2) return e.fail("GLB header", "version " + std::to_string(le32(&b[4])) + ", expected 2");
  if (le32(&b[8]) > b.size()) return e.fail("GLB header", "length field exceeds the file size");
  const uint32_t len = le32(&b[12]);
  if (le32(&b[16]) != 0x4E4F534Au) return e.fail("GLB chunk 0", "the first chunk is not JSON");
  if (len > b.size() - 20) return e.fail("GLB chunk 0", "chunk length exceeds the file");
  json->assign(reinterpret_cast<const char *>(&b[20]), len);
  return true;
}

// JSON number tokens outside strings that overflow a double (nlohmann reports them without
// a position).
bool check_number_tokens(const std::string &s, Err &e) {
  int line = 1, col = 1;
  bool in_str = false;
  for (size_t i = 0; i < s.size(); ++i, ++col) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      col = 0;
      continue;
    }
    if (in_str) {
      if (c == '\\') ++i, ++col;
      else if (c == '"') in_str = false;
      continue;
    }
    if (c == '"') {
      in_str = true;
      continue;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      size_t j = i;
      while (j < s.size() && strchr("+-.eE0123456789", s[j])) ++j;
      const std::string tok = s.substr(i, j - i);
      const double x = strtod(tok.c_str(), nullptr);
      if (!std::isfinite(x))
        return e.fail("line " + std::to_string(line) + ", column " + std::to_string(col),
                      "number " + tok + " is not finite");
      col += static_cast<int>(j - i) - 1;
      i = j - 1;
    }
  }
  return true;
}

std::string url_decode(const std::string &s) {
  std::string o;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && isxdigit(static_cast<unsigned char>(s[i + 1])) &&
        isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      o += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      o += s[i];
    }
  }
  return o;
}

// Syntax, then the external buffers and images the document names (tinygltf's own messages
// do not say which one is missing).
bool precheck_json(const std::string &text, const std::string &dir, Err &e) {
  if (!check_number_tokens(text, e)) return false;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception &ex) {
    std::string w = ex.what();
    const size_t p = w.find("] ");
    if (w.rfind("[json.exception", 0) == 0 && p != std::string::npos) w = w.substr(p + 2);
    return e.fail("JSON", w);
  }
  if (!j.is_object()) return e.fail("JSON", "the root is not an object");
  for (const char *kind : {"buffers", "images"}) {
    auto it = j.find(kind);
    if (it == j.end() || !it->is_array()) continue;
    for (size_t i = 0; i < it->size(); ++i) {
      const auto &o = (*it)[i];
      const std::string place = std::string(kind) + "[" + std::to_string(i) + "]";
      if (!o.is_object() || !o.contains("uri") || !o["uri"].is_string()) continue;
      const std::string uri = o["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      const std::string file = join_path(dir, url_decode(uri));
      long long size = 0;
      if (!file_exists(file, &size)) return e.fail(place, "file not found: " + file);
      if (kind[0] == 'b' && o.contains("byteLength") && o["byteLength"].is_number()) {
        const double want = o["byteLength"].get<double>();
        if (static_cast<double>(size) != want)
          return e.fail(place, "file " + file + " has " + std::to_string(size) + " bytes, byteLength is " +
                                   std::to_string(static_cast<long long>(want)));
      }
    }
  }
  return true;
}

std::string trim_tinygltf(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (char &c : s)
    if (c == '\n') c = ';';
  return s;
}

// ------------------------------------------------------------------------- images ---

bool convert_images(const Model &m, const std::string &path, const std::string &dir, Scene *s, Err &e) {
  for (size_t i = 0; i < m.images.size(); ++i) {
    const tinygltf::Image &im = m.images[i];
    const std::string place = named("images[" + std::to_string(i) + "]", im.name);
    SceneImage out;
    out.path = im.uri.empty() || im.uri.rfind("data:", 0) == 0 ? path + "#images[" + std::to_string(i) + "]"
                                                               : join_path(dir, url_decode(im.uri));
    const int bytes = im.bits == 16 ? 2 : 1;
    if (im.image.empty() || im.width < 1 || im.height < 1 || (im.bits != 8 && im.bits != 16) ||
        im.component < 1 || im.component > 4)
      return e.fail(place, "no decodable PNG/JPEG pixels (" + out.path + ")");
    const size_t w = static_cast<size_t>(im.width), h = static_cast<size_t>(im.height);
    const size_t nc = static_cast<size_t>(im.component);
    if (im.image.size() < w * h * nc * bytes) return e.fail(place, "pixel data shorter than its size");
    out.w = im.width;
    out.h = im.height;
    out.rgba.assign(w * h * 4, 1.f);
    const float scale = bytes == 2 ? 1.f / 65535.f : 1.f / 255.f;
    for (size_t y = 0; y < h; ++y)
      for (size_t x = 0; x < w; ++x)
        for (size_t c = 0; c < nc; ++c) {
          const size_t k = ((h - 1 - y) * w + x) * nc + c;  // file row h-1-y is our row y
          const unsigned code = bytes == 2 ? (im.image[2 * k] | im.image[2 * k + 1] << 8) : im.image[k];
          const float v = static_cast<float>(code) * scale;
          float *px = &out.rgba[(y * w + x) * 4];
          if (nc <= 2) {  // grey (+ alpha)
            if (c == 0) px[0] = px[1] = px[2] = v;
            else px[3] = v;
          } else {
            px[c] = v;
          }
        }
    s->images.push_back(std::move(out));
  }
  return true;
}

// ---------------------------------------------------------------------- accessors ---

const char *type_name(int t) {
  switch (t) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
  }
  return "unknown";
}

const char *comp_name(int c) {
  switch (c) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
  }
  return "unknown";
}

int comp_size(int c) {
  switch (c) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
  }
  return 0;
}

int type_count(int t) {
  switch (t) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
  }
  return 0;
}

// What a use of an accessor accepts: one type; component types; normalized integers.
struct AccessorUse {
  int type;
  std::initializer_list<int> comps;
  bool normalized_ints;  // integer components must be normalized (TEXCOORD); else none allowed
};

// Reads accessor `a` as doubles (normalized integers decoded), every bound checked.
bool read_accessor(const Model &m, int a, const std::string &place, const AccessorUse &use,
                   std::vector<double> *out, size_t *count, Err &e) {
  const std::string an = "accessor " + std::to_string(a);
  if (a < 0 || static_cast<size_t>(a) >= m.accessors.size())
    return e.fail(place, an + " does not exist (" + std::to_string(m.accessors.size()) + " accessors)");
  const tinygltf::Accessor &acc = m.accessors[a];
  if (acc.type != use.type)
    return e.fail(place, an + " has type " + type_name(acc.type) + ", expected " + type_name(use.type));
  bool comp_ok = false;
  std::string want;
  for (int c : use.comps) {
    comp_ok = comp_ok || c == acc.componentType;
    want += std::string(want.empty() ? "" : " or ") + comp_name(c);
  }
  if (!comp_ok)
    return e.fail(place, an + " has componentType " + std::to_string(acc.componentType) + " (" +
                             comp_name(acc.componentType) + "), expected " + want);
  const bool is_float = acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  if (!is_float && use.normalized_ints && !acc.normalized)
    return e.fail(place, an + " has integer components that are not normalized");
  if (acc.normalized && (is_float || !use.normalized_ints))
    return e.fail(place, an + " is normalized, which is not allowed here");
  if (acc.sparse.isSparse) return e.fail(place, an + " is sparse (not supported)");
  const size_t n = acc.count, nc = static_cast<size_t>(type_count(acc.type));
  const size_t cs = static_cast<size_t>(comp_size(acc.componentType)), elem = cs * nc;
  if (n > (1u << 26)) return e.fail(place, an + " has " + std::to_string(n) + " elements (too many)");
  *count = n;
  out->assign(n * nc, 0.0);
  if (acc.bufferView < 0) return true;  // all zeros (glTF)
  const std::string vn = "bufferViews[" + std::to_string(acc.bufferView) + "]";
  if (static_cast<size_t>(acc.bufferView) >= m.bufferViews.size())
    return e.fail(place, an + " names " + vn + ", which does not exist");
  const tinygltf::BufferView &bv = m.bufferViews[acc.bufferView];
  if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= m.buffers.size())
    return e.fail(vn, "buffer " + std::to_string(bv.buffer) + " does not exist");
  const std::vector<unsigned char> &buf = m.buffers[bv.buffer].data;
  if (bv.byteOffset > buf.size() || bv.byteLength > buf.size() - bv.byteOffset)
    return e.fail(vn, "byteOffset " + std::to_string(bv.byteOffset) + " + byteLength " +
                          std::to_string(bv.byteLength) + " exceeds buffers[" + std::to_string(bv.buffer) + "] (" +
                          std::to_string(buf.size()) + " bytes)");
  size_t stride = elem;
  if (bv.byteStride != 0) {
    if (bv.byteStride < elem || bv.byteStride > 252 || bv.byteStride % 4 != 0)
      return e.fail(vn, "byteStride " + std::to_string(bv.byteStride) + " is invalid for " + an + " (element " +
                            std::to_string(elem) + " bytes; 4..252, a multiple of 4)");
    stride = bv.byteStride;
  }
  if (n == 0) return true;
  const size_t need = acc.byteOffset + (n - 1) * stride + elem;
  if (acc.byteOffset > bv.byteLength || need > bv.byteLength)
    return e.fail(place, an + " (byteOffset " + std::to_string(acc.byteOffset) + ", " + std::to_string(n) +
                             " x " + std::to_string(stride) + " bytes) needs " + std::to_string(need) + " bytes, " +
                             vn + " has " + std::to_string(bv.byteLength));
  const unsigned char *base = buf.data() + bv.byteOffset + acc.byteOffset;
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < nc; ++c) {
      const unsigned char *p = base + i * stride + c * cs;
      double v = 0;
      switch (acc.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = p[0]; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: v = p[0] | p[1] << 8; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: v = le32(p); break;
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
          uint32_t u = le32(p);
          float f;
          memcpy(&f, &u, 4);
          if (!std::isfinite(f))
            return e.fail(place, an + " element " + std::to_string(i) + " is not finite");
          v = f;
          break;
        }
      }
      if (acc.normalized) v /= acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 255.0 : 65535.0;
      (*out)[i * nc + c] = v;
    }
  return true;
}

// ------------------------------------------------------------------- transforms ---

typedef double Mat4[16];  // column-major

void mat_mul(const Mat4 a, const Mat4 b, Mat4 r) {
  Mat4 t;
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + rr] * b[c * 4 + k];
      t[c * 4 + rr] = s;
    }
  memcpy(r, t, sizeof(Mat4));
}

bool local_matrix(const tinygltf::Node &n, const std::string &place, Mat4 out, Err &e) {
  if (!n.matrix.empty()) {
    if (n.matrix.size() != 16) return e.fail(place + ".matrix", "expected 16 numbers");
    for (int i = 0; i < 16; ++i) {
      if (!std::isfinite(n.matrix[i])) return e.fail(place + ".matrix", "not finite");
      out[i] = n.matrix[i];
    }
    return true;
  }
  double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, sc[3] = {1, 1, 1};
  if (!n.translation.empty() && n.translation.size() != 3) return e.fail(place + ".translation", "expected 3 numbers");
  if (!n.rotation.empty() && n.rotation.size() != 4) return e.fail(place + ".rotation", "expected 4 numbers");
  if (!n.scale.empty() && n.scale.size() != 3) return e.fail(place + ".scale", "expected 3 numbers");
  for (size_t i = 0; i < n.translation.size(); ++i) t[i] = n.translation[i];
  for (size_t i = 0; i < n.rotation.size(); ++i) q[i] = n.rotation[i];
  for (size_t i = 0; i < n.scale.size(); ++i) sc[i] = n.scale[i];
  double ql = 0;
  for (int i = 0; i < 4; ++i) ql += q[i] * q[i];
  for (double v : {t[0], t[1], t[2], sc[0], sc[1], sc[2], ql})
    if (!std::isfinite(v)) return e.fail(place, "translation/rotation/scale not finite");
  if (ql < 1e-12) return e.fail(place + ".rotation", "zero-length quaternion");
  ql = std::sqrt(ql);
  const double x = q[0] / ql, y = q[1] / ql, z = q[2] / ql, w = q[3] / ql;
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                       2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                       2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
  for (int c = 0; c < 3; ++c) {
    for (int rr = 0; rr < 3; ++rr) out[c * 4 + rr] = r[c * 3 + rr] * sc[c];
    out[c * 4 + 3] = 0;
  }
  out[12] = t[0], out[13] = t[1], out[14] = t[2], out[15] = 1;
  return true;
}

void xform_point(const Mat4 m, const double p[3], double o[3]) {
  for (int r = 0; r < 3; ++r) o[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}
void xform_dir(const double m3[9], const double v[3], double o[3]) {  // m3 column-major 3x3
  for (int r = 0; r < 3; ++r) o[r] = m3[r] * v[0] + m3[3 + r] * v[1] + m3[6 + r] * v[2];
}
void normalize3(double v[3]) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (l > 1e-30)
    for (int i = 0; i < 3; ++i) v[i] /= l;
}

// ---------------------------------------------------------------------- meshes ---

struct Walk {
  const Model &m;
  Scene *s;
  Err &e;
  std::vector<int> seen;  // per node: visited
};

bool convert_primitive(Walk &w, int mesh, int pi, const Mat4 world, int instance, const std::string &node_name,
                       double bmin[3], double bmax[3]) {
  const tinygltf::Primitive &p = w.m.meshes[mesh].primitives[pi];
  const std::string place = "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(pi) + "]";
  if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES)
    return w.e.fail(place, "mode " + std::to_string(p.mode) + " is not TRIANGLES (4): only triangles are supported");
  auto attr = [&](const char *name) {
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
  };
  const int F = TINYGLTF_COMPONENT_TYPE_FLOAT, UB = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
            US = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, UI = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  if (attr("POSITION") < 0) return w.e.fail(place + ".attributes", "no POSITION");
  std::vector<double> pos, nrm, uv, tan, idx;
  size_t nv = 0, n2 = 0;
  if (!read_accessor(w.m, attr("POSITION"), place + ".attributes.POSITION", {TINYGLTF_TYPE_VEC3, {F}, false}, &pos,
                     &nv, w.e))
    return false;
  if (nv == 0) return w.e.fail(place + ".attributes.POSITION", "no vertices");
  struct Opt {
    const char *name;
    AccessorUse use;
    std::vector<double> *out;
  } opts[] = {{"NORMAL", {TINYGLTF_TYPE_VEC3, {F}, false}, &nrm},
              {"TEXCOORD_0", {TINYGLTF_TYPE_VEC2, {F, UB, US}, true}, &uv},
              {"TANGENT", {TINYGLTF_TYPE_VEC4, {F}, false}, &tan}};
  for (const Opt &o : opts) {
    if (attr(o.name) < 0) continue;
    const std::string ap = place + ".attributes." + o.name;
    if (!read_accessor(w.m, attr(o.name), ap, o.use, o.out, &n2, w.e)) return false;
    if (n2 != nv)
      return w.e.fail(ap, "accessor " + std::to_string(attr(o.name)) + " has " + std::to_string(n2) +
                              " elements, POSITION has " + std::to_string(nv));
  }
  std::vector<uint32_t> tri;
  if (p.indices >= 0) {
    size_t ni = 0;
    if (!read_accessor(w.m, p.indices, place + ".indices", {TINYGLTF_TYPE_SCALAR, {UB, US, UI}, false}, &idx, &ni,
                       w.e))
      return false;
    if (ni % 3 != 0) return w.e.fail(place + ".indices", std::to_string(ni) + " indices is not a multiple of 3");
    tri.resize(ni);
    for (size_t i = 0; i < ni; ++i) {
      if (idx[i] >= static_cast<double>(nv))
        return w.e.fail(place + ".indices", "index " + std::to_string(static_cast<long long>(idx[i])) +
                                                " at position " + std::to_string(i) + " is out of range (" +
                                                std::to_string(nv) + " vertices)");
      tri[i] = static_cast<uint32_t>(idx[i]);
    }
  } else {
    if (nv % 3 != 0) return w.e.fail(place, "non-indexed with " + std::to_string(nv) + " vertices (not a multiple of 3)");
    tri.resize(nv);
    for (size_t i = 0; i < nv; ++i) tri[i] = static_cast<uint32_t>(i);
  }
  int material = p.material;
  if (material >= static_cast<int>(w.m.materials.size()))
    return w.e.fail(place + ".material", "material " + std::to_string(material) + " does not exist");

  // Linear part, its inverse transpose (cofactors / det) and the handedness.
  double m3[9], it[9];
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m3[c * 3 + r] = world[c * 4 + r];
  auto M = [&](int r, int c) { return m3[c * 3 + r]; };
  const double det = M(0, 0) * (M(1, 1) * M(2, 2) - M(1, 2) * M(2, 1)) -
                     M(0, 1) * (M(1, 0) * M(2, 2) - M(1, 2) * M(2, 0)) +
                     M(0, 2) * (M(1, 0) * M(2, 1) - M(1, 1) * M(2, 0));
  if (!(std::fabs(det) > 1e-18)) return w.e.fail(place + " (node " + quoted(node_name) + ")", "the node transform is singular");
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {  // inverse transpose = cofactor matrix / det
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      it[c * 3 + r] = (M(r1, c1) * M(r2, c2) - M(r1, c2) * M(r2, c1)) / det;
    }
  if (det < 0)  // a mirroring transform flips the winding: keep the front faces in front
    for (size_t t = 0; t + 2 < tri.size(); t += 3) std::swap(tri[t + 1], tri[t + 2]);

  ScenePrimitive out;
  out.material = material;
  out.instance = instance;
  out.where = place + " (node " + quoted(node_name) + ")";
  const bool flat = nrm.empty();
  // Flat normals need one vertex per triangle corner.
  std::vector<uint32_t> src;
  if (flat) {
    src = tri;
    for (size_t i = 0; i < tri.size(); ++i) tri[i] = static_cast<uint32_t>(i);
  } else {
    src.resize(nv);
    for (size_t i = 0; i < nv; ++i) src[i] = static_cast<uint32_t>(i);
  }
  const size_t n = src.size();
  out.position.resize(n * 3);
  out.normal.resize(n * 3);
  out.uv.assign(n * 2, 0.f);
  if (!tan.empty()) out.tangent.resize(n * 4);
  for (size_t i = 0; i < n; ++i) {
    const size_t v = src[i];
    double q[3];
    xform_point(world, &pos[v * 3], q);
    for (int k = 0; k < 3; ++k) {
      out.position[i * 3 + k] = static_cast<float>(q[k]);
      bmin[k] = std::min(bmin[k], q[k]);
      bmax[k] = std::max(bmax[k], q[k]);
    }
    if (!flat) {
      xform_dir(it, &nrm[v * 3], q);
      normalize3(q);
      for (int k = 0; k < 3; ++k) out.normal[i * 3 + k] = static_cast<float>(q[k]);
    }
    if (!uv.empty()) out.uv[i * 2] = static_cast<float>(uv[v * 2]), out.uv[i * 2 + 1] = static_cast<float>(uv[v * 2 + 1]);
    if (!tan.empty()) {
      xform_dir(m3, &tan[v * 4], q);
      normalize3(q);
      for (int k = 0; k < 3; ++k) out.tangent[i * 4 + k] = static_cast<float>(q[k]);
      // The bitangent is w * cross(N, T); under a mirror cross() turns round, so w does too.
      out.tangent[i * 4 + 3] = static_cast<float>(det < 0 ? -tan[v * 4 + 3] : tan[v * 4 + 3]);
    }
  }
  if (flat)
    for (size_t t = 0; t + 2 < n; t += 3) {
      double a[3], b[3], c[3];
      for (int k = 0; k < 3; ++k) {
        a[k] = static_cast<double>(out.position[(t + 1) * 3 + k]) - out.position[t * 3 + k];
        b[k] = static_cast<double>(out.position[(t + 2) * 3 + k]) - out.position[t * 3 + k];
      }
      c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2], c[2] = a[0] * b[1] - a[1] * b[0];
      normalize3(c);
      for (size_t j = t; j < t + 3; ++j)
        for (int k = 0; k < 3; ++k) out.normal[j * 3 + k] = static_cast<float>(c[k]);
    }
  out.indices = std::move(tri);
  w.s->primitives.push_back(std::move(out));
  return true;
}

bool convert_camera(Walk &w, int cam, const Mat4 world, const std::string &node_name) {
  const std::string place = "cameras[" + std::to_string(cam) + "]";
  if (cam < 0 || static_cast<size_t>(cam) >= w.m.cameras.size()) return w.e.fail(place, "does not exist");
  const tinygltf::Camera &c = w.m.cameras[cam];
  SceneCamera sc;
  if (c.type == "orthographic") {
    if (!read_orthographic(c, named(place, c.name), &sc, w.e)) return false;
  } else if (c.type != "perspective") {
    return w.e.fail(named(place, c.name), "type " + quoted(c.type) + ": not perspective or orthographic");
  } else {
    const tinygltf::PerspectiveCamera &p = c.perspective;
    if (!(p.yfov > 0 && p.yfov < 3.14159)) return w.e.fail(named(place, c.name) + ".perspective.yfov", "must be in (0, pi)");
    if (!(p.znear > 0 && std::isfinite(p.znear))) return w.e.fail(named(place, c.name) + ".perspective.znear", "must be > 0");
    if (!(p.zfar == 0 || (p.zfar > p.znear && std::isfinite(p.zfar))))
      return w.e.fail(named(place, c.name) + ".perspective.zfar", "must be > znear (or absent)");
    if (!(p.aspectRatio >= 0 && std::isfinite(p.aspectRatio)))
      return w.e.fail(named(place, c.name) + ".perspective.aspectRatio", "must be > 0 (or absent)");
    sc.yfov = p.yfov;
    sc.znear = p.znear;
    sc.zfar = p.zfar;
    sc.aspect = p.aspectRatio;
  }
  sc.name = !c.name.empty() ? c.name : !node_name.empty() ? node_name : place;
  const double o[3] = {0, 0, 0}, fz[3] = {0, 0, -1}, uy[3] = {0, 1, 0};
  double m3[9];
  for (int cc = 0; cc < 3; ++cc)
    for (int r = 0; r < 3; ++r) m3[cc * 3 + r] = world[cc * 4 + r];
  xform_point(world, o, sc.eye);
  xform_dir(m3, fz, sc.forward);
  xform_dir(m3, uy, sc.up);
  normalize3(sc.forward);
  const double d = sc.up[0] * sc.forward[0] + sc.up[1] * sc.forward[1] + sc.up[2] * sc.forward[2];
  for (int k = 0; k < 3; ++k) sc.up[k] -= d * sc.forward[k];
  normalize3(sc.up);
  w.s->cameras.push_back(sc);
  return true;
}

bool walk_node(Walk &w, int ni, const Mat4 parent, int depth) {
  const std::string place = "nodes[" + std::to_string(ni) + "]";
  if (ni < 0 || static_cast<size_t>(ni) >= w.m.nodes.size()) return w.e.fail(place, "does not exist");
  if (w.seen[ni]) return w.e.fail(place, "appears twice in the node hierarchy (a cycle or a shared child)");
  if (depth > 256) return w.e.fail(place, "node hierarchy deeper than 256");
  w.seen[ni] = 1;
  const tinygltf::Node &n = w.m.nodes[ni];
  const std::string nplace = named(place, n.name);
  Mat4 local, world;
  if (!local_matrix(n, nplace, local, w.e)) return false;
  mat_mul(parent, local, world);
  const std::string nname = n.name.empty() ? place : n.name;
  if (n.camera >= 0 && !convert_camera(w, n.camera, world, n.name)) return false;
  auto ext = n.extensions.find("KHR_lights_punctual");
  if (ext != n.extensions.end()) {
    int li = -1;
    const std::string lp = nplace + ".extensions.KHR_lights_punctual";
    if (!check_keys(ext->second, lp, {"light"}, w.e) ||
        !read_int(ext->second.Get("light"), lp + ".light", 0, static_cast<int>(w.m.lights.size()) - 1, &li, w.e) ||
        !convert_light(w.m, li, world, nplace, w.s, w.e))
      return false;
  }
  if (n.mesh >= 0) {
    if (static_cast<size_t>(n.mesh) >= w.m.meshes.size())
      return w.e.fail(nplace + ".mesh", "mesh " + std::to_string(n.mesh) + " does not exist");
    SceneInstance inst;
    inst.name = nname;
    memcpy(inst.world, world, sizeof(Mat4));
    const int id = static_cast<int>(w.s->instances.size());
    double bmin[3] = {1e300, 1e300, 1e300}, bmax[3] = {-1e300, -1e300, -1e300};
    const auto &prims = w.m.meshes[n.mesh].primitives;
    for (size_t pi = 0; pi < prims.size(); ++pi)
      if (!convert_primitive(w, n.mesh, static_cast<int>(pi), world, id, nname, bmin, bmax)) return false;
    for (int k = 0; k < 3; ++k) inst.center[k] = prims.empty() ? world[12 + k] : 0.5 * (bmin[k] + bmax[k]);
    w.s->instances.push_back(inst);
  }
  for (int c : n.children)
    if (!walk_node(w, c, world, depth + 1)) return false;
  return true;
}

bool convert_nodes(const Model &m, Scene *s, Err &e) {
  Walk w{m, s, e, std::vector<int>(m.nodes.size(), 0)};
  std::vector<int> roots;
  if (!m.scenes.empty()) {
    int si = m.defaultScene >= 0 ? m.defaultScene : 0;
    if (static_cast<size_t>(si) >= m.scenes.size()) return e.fail("scene", "scene " + std::to_string(si) + " does not exist");
    roots = m.scenes[si].nodes;
  } else {  // no scenes: every node that is nobody's child
    std::vector<int> child(m.nodes.size(), 0);
    for (const auto &n : m.nodes)
      for (int c : n.children)
        if (c >= 0 && static_cast<size_t>(c) < child.size()) child[c] = 1;
    for (size_t i = 0; i < m.nodes.size(); ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  const Mat4 id = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  for (int r : roots)
    if (!walk_node(w, r, id, 0)) return false;
  return true;
}

bool load(const std::string &path, Scene *s, Err &e) {
  std::vector<unsigned char> bytes;
  if (!read_file(path, &bytes, e)) return false;
  const std::string dir = dir_of(path);
  const bool glb = (path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0) ||
                   (bytes.size() >= 4 && memcmp(bytes.data(), "glTF", 4) == 0);
  std::string json;
  if (glb) {
    if (!glb_json(bytes, &json, e)) return false;
  } else {
    json.assign(bytes.begin(), bytes.end());
  }
  if (!precheck_json(json, dir, e)) return false;
  if (bytes.size() > 0xFFFFFFFFu) return e.fail("", "file too large");
  Model m;
  tinygltf::TinyGLTF loader;
  std::string terr, twarn;
  const bool ok = glb ? loader.LoadBinaryFromMemory(&m, &terr, &twarn, bytes.data(),
                                                    static_cast<unsigned>(bytes.size()), dir)
                      : loader.LoadASCIIFromString(&m, &terr, &twarn, json.data(),
                                                   static_cast<unsigned>(json.size()), dir);
  if (!ok) return e.fail("glTF", trim_tinygltf(terr.empty() ? "tinygltf could not load the file" : terr));
  s->path = path;
  if (!convert_images(m, path, dir, s, e) || !convert_materials(m, s, e) || !convert_nodes(m, s, e)) return false;
  for (ScenePrimitive &p : s->primitives)
    if (p.material < 0) {  // glTF's default material: a plain VertexLitGeneric one
      if (s->materials.empty() || s->materials.back().where != "default material") {
        SceneMaterial d;
        d.name = "default";
        d.where = "default material";
        s->materials.push_back(d);
      }
      p.material = static_cast<int>(s->materials.size()) - 1;
    }
  if (s->primitives.empty()) return e.fail("scene", "no triangles (a scene needs at least one mesh primitive)");
  if (s->cameras.empty()) return e.fail("scene", "no camera (a scene needs a node with a camera)");
  return convert_tiershade_extras(m, dir, s, e);
}

}  // namespace
}  // namespace scene_gltf

bool load_scene(const std::string &path, Scene *out, std::string *err) {
  scene_gltf::Err e;
  e.file = path;
  Scene s;
  bool ok = false;
  try {
    ok = scene_gltf::load(path, &s, e);
  } catch (const std::exception &ex) {
    e.fail("", std::string("unexpected error: ") + ex.what());
    ok = false;
  }
  if (!ok) {
    if (err) *err = e.msg.empty() ? path + ": could not load the scene" : e.msg;
    return false;
  }
  *out = std::move(s);
  return true;
}

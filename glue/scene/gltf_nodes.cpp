// tiershade scene: the glTF loader's geometry (glue/scene/gltf_load.cpp reads the file): accessors,
// node transforms (GLM, double), and meshes, cameras and lights flattened to world space.
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_util.h"

namespace scene_gltf {
namespace {

using tinygltf::Model;

// ---------------------------------------------------------------------- accessors ---

// Accessor types and component types: the name errors give, and the components per element
// or bytes per component this loader reads (0: a code no attribute accepts).
struct GltfCode {
  int code;
  const char *name;
  int n;
};
const GltfCode kTypes[] = {{TINYGLTF_TYPE_SCALAR, "SCALAR", 1}, {TINYGLTF_TYPE_VEC2, "VEC2", 2},
                           {TINYGLTF_TYPE_VEC3, "VEC3", 3},     {TINYGLTF_TYPE_VEC4, "VEC4", 4},
                           {TINYGLTF_TYPE_MAT2, "MAT2", 0},     {TINYGLTF_TYPE_MAT3, "MAT3", 0},
                           {TINYGLTF_TYPE_MAT4, "MAT4", 0}};
const GltfCode kComponents[] = {{TINYGLTF_COMPONENT_TYPE_BYTE, "BYTE", 0},
                                {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, "UNSIGNED_BYTE", 1},
                                {TINYGLTF_COMPONENT_TYPE_SHORT, "SHORT", 0},
                                {TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "UNSIGNED_SHORT", 2},
                                {TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, "UNSIGNED_INT", 4},
                                {TINYGLTF_COMPONENT_TYPE_FLOAT, "FLOAT", 4}};
// The row of `code`; a row named "unknown" with n 0 when the table has none.
template <size_t N>
const GltfCode &code_row(const GltfCode (&table)[N], int code) {
  static const GltfCode kUnknown = {-1, "unknown", 0};
  for (const GltfCode &r : table)
    if (r.code == code) return r;
  return kUnknown;
}
const char *type_name(int t) { return code_row(kTypes, t).name; }
int type_count(int t) { return code_row(kTypes, t).n; }
const char *comp_name(int c) { return code_row(kComponents, c).name; }
int comp_size(int c) { return code_row(kComponents, c).n; }

// What a use of an accessor accepts: one type; component types; normalized integers.
struct AccessorUse {
  int type;
  std::initializer_list<int> comps;
  bool normalized_ints;  // integer components must be normalized (TEXCOORD); else none allowed
};

// Reads accessor `a` as doubles (normalized integers decoded), every bound checked.
bool read_accessor(const Model &m, int a, const std::string &place, const AccessorUse &use, std::vector<double> *out,
                   size_t *count, Err &e) {
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
    return e.fail(place,
                  an + " has componentType " + std::to_string(acc.componentType) + " (" + comp_name(acc.componentType) +
                      "), expected " + want);
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
    return e.fail(vn,
                  "byteOffset " + std::to_string(bv.byteOffset) + " + byteLength " + std::to_string(bv.byteLength) +
                      " exceeds buffers[" + std::to_string(bv.buffer) + "] (" + std::to_string(buf.size()) + " bytes)");
  size_t stride = elem;
  if (bv.byteStride != 0) {
    if (bv.byteStride < elem || bv.byteStride > 252 || bv.byteStride % 4 != 0)
      return e.fail(vn,
                    "byteStride " + std::to_string(bv.byteStride) + " is invalid for " + an + " (element " +
                        std::to_string(elem) + " bytes; 4..252, a multiple of 4)");
    stride = bv.byteStride;
  }
  if (n == 0) return true;
  const size_t need = acc.byteOffset + (n - 1) * stride + elem;
  if (acc.byteOffset > bv.byteLength || need > bv.byteLength)
    return e.fail(place,
                  an + " (byteOffset " + std::to_string(acc.byteOffset) + ", " + std::to_string(n) + " x " +
                      std::to_string(stride) + " bytes) needs " + std::to_string(need) + " bytes, " + vn + " has " +
                      std::to_string(bv.byteLength));
  const unsigned char *base = buf.data() + bv.byteOffset + acc.byteOffset;
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < nc; ++c) {
      const unsigned char *p = base + i * stride + c * cs;
      double v = 0;
      switch (acc.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          v = p[0];
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
          v = p[0] | p[1] << 8;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
          v = le32(p);
          break;
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
          uint32_t u = le32(p);
          float f;
          memcpy(&f, &u, 4);
          if (!std::isfinite(f)) return e.fail(place, an + " element " + std::to_string(i) + " is not finite");
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

// v / |v|, or v itself when shorter than 1e-30 (a degenerate normal stays zero).
glm::dvec3 unit_or_zero(const glm::dvec3 &v) {
  const double l = glm::length(v);
  return l > 1e-30 ? v / l : v;
}

// Corner i of a float position array, in double.
glm::dvec3 corner(const std::vector<float> &p, size_t i) { return glm::dvec3(p[i * 3], p[i * 3 + 1], p[i * 3 + 2]); }

// A node's local matrix: its `matrix`, or T * R * S (glTF 2.0, 3.5.2), every number checked.
bool local_matrix(const tinygltf::Node &n, const std::string &place, glm::dmat4 *out, Err &e) {
  if (!n.matrix.empty()) {
    if (n.matrix.size() != 16) return e.fail(place + ".matrix", "expected 16 numbers");
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(n.matrix[i])) return e.fail(place + ".matrix", "not finite");
    *out = glm::make_mat4(n.matrix.data());  // column-major, as glTF stores it
    return true;
  }
  glm::dvec3 t(0.0), sc(1.0);
  glm::dquat q(1.0, 0.0, 0.0, 0.0);  // (w, x, y, z); glTF stores x, y, z, w
  if (!n.translation.empty() && n.translation.size() != 3) return e.fail(place + ".translation", "expected 3 numbers");
  if (!n.rotation.empty() && n.rotation.size() != 4) return e.fail(place + ".rotation", "expected 4 numbers");
  if (!n.scale.empty() && n.scale.size() != 3) return e.fail(place + ".scale", "expected 3 numbers");
  if (!n.translation.empty()) t = glm::make_vec3(n.translation.data());
  if (!n.rotation.empty()) q = glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
  if (!n.scale.empty()) sc = glm::make_vec3(n.scale.data());
  const double ql = glm::dot(q, q);
  for (double v : {t[0], t[1], t[2], sc[0], sc[1], sc[2], ql})
    if (!std::isfinite(v)) return e.fail(place, "translation/rotation/scale not finite");
  if (ql < 1e-12) return e.fail(place + ".rotation", "zero-length quaternion");
  *out = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(glm::normalize(q)) * glm::scale(glm::dmat4(1.0), sc);
  return true;
}

// ---------------------------------------------------------------------- meshes ---

struct Walk {
  const Model &m;
  Scene *s;
  Err &e;
  std::vector<int> seen;  // per node: visited
  std::vector<int> uses;  // per mesh: the nodes of the scene that instance it
  std::map<std::pair<int, int>, std::shared_ptr<const SceneGeometry>> shared;  // (mesh, primitive)
};

// A primitive's accessors as read (doubles), before any transform.
struct RawPrimitive {
  std::vector<double> pos, nrm, uv, uv1, tan;
  std::vector<uint32_t> tri;
  size_t nv = 0;
};

// The arrays of `raw` through `world` (double, rounded to float): positions; normals by the
// inverse transpose, renormalised (flat face normals from the rounded positions when the mesh has
// none); tangents by the linear part, renormalised, w flipped by a mirror (which also flips the
// winding); every position into the box bmin..bmax.
void fill_arrays(const RawPrimitive &raw, const glm::dmat4 &world, SceneGeometry *out, double bmin[3], double bmax[3]) {
  const glm::dmat3 m3(world);
  const double det = glm::determinant(m3);
  const glm::dmat3 it = glm::inverseTranspose(m3);
  std::vector<uint32_t> tri = raw.tri;
  if (det < 0)  // a mirroring transform flips the winding: keep the front faces in front
    for (size_t t = 0; t + 2 < tri.size(); t += 3) std::swap(tri[t + 1], tri[t + 2]);
  const std::vector<double> &pos = raw.pos, &nrm = raw.nrm, &uv = raw.uv, &uv1 = raw.uv1, &tan = raw.tan;
  const bool flat = nrm.empty();
  // Flat normals need one vertex per triangle corner.
  std::vector<uint32_t> src;
  if (flat) {
    src = tri;
    for (size_t i = 0; i < tri.size(); ++i) tri[i] = static_cast<uint32_t>(i);
  } else {
    src.resize(raw.nv);
    for (size_t i = 0; i < raw.nv; ++i) src[i] = static_cast<uint32_t>(i);
  }
  const size_t n = src.size();
  out->position.resize(n * 3);
  out->normal.resize(n * 3);
  out->uv.assign(n * 2, 0.f);
  if (!tan.empty()) out->tangent.resize(n * 4);
  if (!uv1.empty()) out->uv1.resize(n * 2);
  for (size_t i = 0; i < n; ++i) {
    const size_t v = src[i];
    glm::dvec3 q = glm::dvec3(world * glm::dvec4(pos[v * 3], pos[v * 3 + 1], pos[v * 3 + 2], 1.0));
    for (int k = 0; k < 3; ++k) {
      out->position[i * 3 + k] = static_cast<float>(q[k]);
      bmin[k] = std::min(bmin[k], q[k]);
      bmax[k] = std::max(bmax[k], q[k]);
    }
    if (!flat) {
      q = unit_or_zero(it * glm::dvec3(nrm[v * 3], nrm[v * 3 + 1], nrm[v * 3 + 2]));
      for (int k = 0; k < 3; ++k) out->normal[i * 3 + k] = static_cast<float>(q[k]);
    }
    if (!uv.empty())
      out->uv[i * 2] = static_cast<float>(uv[v * 2]), out->uv[i * 2 + 1] = static_cast<float>(uv[v * 2 + 1]);
    if (!uv1.empty())
      out->uv1[i * 2] = static_cast<float>(uv1[v * 2]), out->uv1[i * 2 + 1] = static_cast<float>(uv1[v * 2 + 1]);
    if (!tan.empty()) {
      q = unit_or_zero(m3 * glm::dvec3(tan[v * 4], tan[v * 4 + 1], tan[v * 4 + 2]));
      for (int k = 0; k < 3; ++k) out->tangent[i * 4 + k] = static_cast<float>(q[k]);
      // The bitangent is w * cross(N, T); under a mirror cross() turns round, so w does too.
      out->tangent[i * 4 + 3] = static_cast<float>(det < 0 ? -tan[v * 4 + 3] : tan[v * 4 + 3]);
    }
  }
  if (flat)
    for (size_t t = 0; t + 2 < n; t += 3) {
      const glm::dvec3 p0 = corner(out->position, t), a = corner(out->position, t + 1) - p0,
                       b = corner(out->position, t + 2) - p0;
      const glm::dvec3 c = unit_or_zero(glm::cross(a, b));
      for (size_t j = t; j < t + 3; ++j)
        for (int k = 0; k < 3; ++k) out->normal[j * 3 + k] = static_cast<float>(c[k]);
    }
  out->indices = std::move(tri);
}

// A rigid transform (rotation and translation: orthonormal columns within 1e-9, no mirror, the
// affine bottom row): the shaders' u_model carries it as it is (model_lighting.vs transforms
// normals and tangents by u_model, which is right for these alone).
bool rigid(const glm::dmat4 &w) {
  if (w[0][3] != 0 || w[1][3] != 0 || w[2][3] != 0 || w[3][3] != 1) return false;
  const glm::dmat3 m3(w);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(glm::dot(m3[i], m3[j]) - (i == j ? 1.0 : 0.0)) > 1e-9) return false;
  return glm::determinant(m3) > 0;
}

bool convert_primitive(Walk &w, int mesh, int pi, const glm::dmat4 &world, int instance, const std::string &node_name,
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
  RawPrimitive raw;
  std::vector<double> idx;
  size_t nv = 0, n2 = 0;
  if (!read_accessor(w.m, attr("POSITION"), place + ".attributes.POSITION", {TINYGLTF_TYPE_VEC3, {F}, false}, &raw.pos,
                     &nv, w.e))
    return false;
  if (nv == 0) return w.e.fail(place + ".attributes.POSITION", "no vertices");
  raw.nv = nv;
  struct Opt {
    const char *name;
    AccessorUse use;
    std::vector<double> *out;
  } opts[] = {{"NORMAL", {TINYGLTF_TYPE_VEC3, {F}, false}, &raw.nrm},
              {"TEXCOORD_0", {TINYGLTF_TYPE_VEC2, {F, UB, US}, true}, &raw.uv},
              {"TEXCOORD_1", {TINYGLTF_TYPE_VEC2, {F, UB, US}, true}, &raw.uv1},  // lightmap UVs (glue/bake/charts.h)
              {"TANGENT", {TINYGLTF_TYPE_VEC4, {F}, false}, &raw.tan}};
  for (const Opt &o : opts) {
    if (attr(o.name) < 0) continue;
    const std::string ap = place + ".attributes." + o.name;
    if (!read_accessor(w.m, attr(o.name), ap, o.use, o.out, &n2, w.e)) return false;
    if (n2 != nv)
      return w.e.fail(ap,
                      "accessor " + std::to_string(attr(o.name)) + " has " + std::to_string(n2) +
                          " elements, POSITION has " + std::to_string(nv));
  }
  std::vector<uint32_t> &tri = raw.tri;
  if (p.indices >= 0) {
    size_t ni = 0;
    if (!read_accessor(w.m, p.indices, place + ".indices", {TINYGLTF_TYPE_SCALAR, {UB, US, UI}, false}, &idx, &ni, w.e))
      return false;
    if (ni % 3 != 0) return w.e.fail(place + ".indices", std::to_string(ni) + " indices is not a multiple of 3");
    tri.resize(ni);
    for (size_t i = 0; i < ni; ++i) {
      if (idx[i] >= static_cast<double>(nv))
        return w.e.fail(place + ".indices",
                        "index " + std::to_string(static_cast<long long>(idx[i])) + " at position " +
                            std::to_string(i) + " is out of range (" + std::to_string(nv) + " vertices)");
      tri[i] = static_cast<uint32_t>(idx[i]);
    }
  } else {
    if (nv % 3 != 0)
      return w.e.fail(place, "non-indexed with " + std::to_string(nv) + " vertices (not a multiple of 3)");
    tri.resize(nv);
    for (size_t i = 0; i < nv; ++i) tri[i] = static_cast<uint32_t>(i);
  }
  int material = p.material;
  if (material >= static_cast<int>(w.m.materials.size()))
    return w.e.fail(place + ".material", "material " + std::to_string(material) + " does not exist");

  const double det = glm::determinant(glm::dmat3(world));
  if (!(std::fabs(det) > 1e-18))
    return w.e.fail(place + " (node " + quoted(node_name) + ")", "the node transform is singular");

  ScenePrimitive out;
  out.material = material;
  out.instance = instance;
  out.where = place + " (node " + quoted(node_name) + ")";
  // Shared: a mesh several nodes of the scene instance, drawn with a Model material (the glTF
  // default material is one) under a rigid transform; world materials stay in world space (the
  // bake's faces and their lightmap coordinates are per face).
  const bool model_material =
      material < 0 || w.s->materials.at(static_cast<size_t>(material)).shader == SceneShader::Model;
  if (w.uses.at(static_cast<size_t>(mesh)) > 1 && model_material && rigid(world)) {
    std::shared_ptr<const SceneGeometry> &g = w.shared[{mesh, pi}];
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    if (!g) {
      auto obj = std::make_shared<SceneGeometry>();
      fill_arrays(raw, glm::dmat4(1.0), obj.get(), lo, hi);  // object space: the identity is exact
      g = obj;
    }
    out.shared = g;
    const double *wm = glm::value_ptr(world);
    for (int i = 0; i < 16; ++i) out.model[i] = static_cast<float>(wm[i]);
    for (size_t v = 0; v < nv; ++v) {  // the instance's box, as the flattened positions give it
      const glm::dvec3 q = glm::dvec3(world * glm::dvec4(raw.pos[v * 3], raw.pos[v * 3 + 1], raw.pos[v * 3 + 2], 1.0));
      for (int k = 0; k < 3; ++k) bmin[k] = std::min(bmin[k], q[k]), bmax[k] = std::max(bmax[k], q[k]);
    }
  } else {
    fill_arrays(raw, world, &out, bmin, bmax);
  }
  w.s->primitives.push_back(std::move(out));
  return true;
}

bool convert_camera(Walk &w, int cam, const glm::dmat4 &world, const std::string &node_name) {
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
    if (!(p.yfov > 0 && p.yfov < glm::pi<double>()))
      return w.e.fail(named(place, c.name) + ".perspective.yfov", "must be in (0, pi)");
    if (!(p.znear > 0 && std::isfinite(p.znear)))
      return w.e.fail(named(place, c.name) + ".perspective.znear", "must be > 0");
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
  // The camera looks down its node's -Z with +Y up (glTF 2.0, 3.10.1), up made orthogonal.
  const glm::dmat3 m3(world);
  const glm::dvec3 eye(world[3]), fwd = unit_or_zero(m3 * glm::dvec3(0, 0, -1));
  glm::dvec3 up = m3 * glm::dvec3(0, 1, 0);
  up = unit_or_zero(up - glm::dot(up, fwd) * fwd);
  for (int k = 0; k < 3; ++k) sc.eye[k] = eye[k], sc.forward[k] = fwd[k], sc.up[k] = up[k];
  w.s->cameras.push_back(sc);
  return true;
}

// A node's extras.tiershade: "reach" [[x,y,z], [x,y,z]], the world-space box its centre can be in
// (docs/scenes.md). Other keys are refused, naming the place.
bool read_node_reach(const tinygltf::Node &n, const std::string &nplace, SceneInstance *inst, Err &e) {
  if (!n.extras.IsObject() || !n.extras.Has("tiershade")) return true;
  const std::string place = nplace + ".extras.tiershade";
  const tinygltf::Value &t = n.extras.Get("tiershade");
  if (!check_keys(t, place, {"reach"}, e)) return false;
  if (!t.Has("reach")) return true;
  const tinygltf::Value &b = t.Get("reach");
  if (!b.IsArray() || b.ArrayLen() != 2) return e.fail(place + ".reach", "expected [[x,y,z], [x,y,z]]");
  if (!read_vec(b.Get(0), place + ".reach[0]", 3, -1e6, 1e6, inst->reach_lo, e) ||
      !read_vec(b.Get(1), place + ".reach[1]", 3, -1e6, 1e6, inst->reach_hi, e))
    return false;
  for (int k = 0; k < 3; ++k)
    if (!(inst->reach_hi[k] >= inst->reach_lo[k]))
      return e.fail(place + ".reach", "the high corner is below the low one on an axis");
  inst->has_reach = true;
  return true;
}

bool walk_node(Walk &w, int ni, const glm::dmat4 &parent, int depth) {
  const std::string place = "nodes[" + std::to_string(ni) + "]";
  if (ni < 0 || static_cast<size_t>(ni) >= w.m.nodes.size()) return w.e.fail(place, "does not exist");
  if (w.seen[ni]) return w.e.fail(place, "appears twice in the node hierarchy (a cycle or a shared child)");
  if (depth > 256) return w.e.fail(place, "node hierarchy deeper than 256");
  w.seen[ni] = 1;
  const tinygltf::Node &n = w.m.nodes[ni];
  const std::string nplace = named(place, n.name);
  glm::dmat4 local;
  if (!local_matrix(n, nplace, &local, w.e)) return false;
  const glm::dmat4 world = parent * local;
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
    memcpy(inst.world, glm::value_ptr(world), sizeof inst.world);
    const int id = static_cast<int>(w.s->instances.size());
    double bmin[3] = {1e300, 1e300, 1e300}, bmax[3] = {-1e300, -1e300, -1e300};
    const auto &prims = w.m.meshes[n.mesh].primitives;
    for (size_t pi = 0; pi < prims.size(); ++pi)
      if (!convert_primitive(w, n.mesh, static_cast<int>(pi), world, id, nname, bmin, bmax)) return false;
    for (int k = 0; k < 3; ++k) inst.center[k] = prims.empty() ? world[3][k] : 0.5 * (bmin[k] + bmax[k]);
    if (!read_node_reach(n, nplace, &inst, w.e)) return false;
    w.s->instances.push_back(inst);
  }
  for (int c : n.children)
    if (!walk_node(w, c, world, depth + 1)) return false;
  return true;
}

// Per mesh, the nodes under the roots that instance it (each node once; the walk reports bad
// hierarchies).
void count_uses(Walk &w, const std::vector<int> &roots) {
  std::vector<int> seen(w.m.nodes.size(), 0), stack(roots);
  while (!stack.empty()) {
    const int ni = stack.back();
    stack.pop_back();
    if (ni < 0 || static_cast<size_t>(ni) >= w.m.nodes.size() || seen[static_cast<size_t>(ni)]) continue;
    seen[static_cast<size_t>(ni)] = 1;
    const tinygltf::Node &n = w.m.nodes[static_cast<size_t>(ni)];
    if (n.mesh >= 0 && static_cast<size_t>(n.mesh) < w.uses.size()) ++w.uses[static_cast<size_t>(n.mesh)];
    for (int c : n.children) stack.push_back(c);
  }
}

}  // namespace

bool convert_nodes(const Model &m, Scene *s, Err &e) {
  Walk w{m, s, e, std::vector<int>(m.nodes.size(), 0), std::vector<int>(m.meshes.size(), 0), {}};
  std::vector<int> roots;
  if (!m.scenes.empty()) {
    int si = m.defaultScene >= 0 ? m.defaultScene : 0;
    if (static_cast<size_t>(si) >= m.scenes.size())
      return e.fail("scene", "scene " + std::to_string(si) + " does not exist");
    roots = m.scenes[si].nodes;
  } else {  // no scenes: every node that is nobody's child
    std::vector<int> child(m.nodes.size(), 0);
    for (const auto &n : m.nodes)
      for (int c : n.children)
        if (c >= 0 && static_cast<size_t>(c) < child.size()) child[c] = 1;
    for (size_t i = 0; i < m.nodes.size(); ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  count_uses(w, roots);
  for (int r : roots)
    if (!walk_node(w, r, glm::dmat4(1.0), 0)) return false;
  return true;
}

}  // namespace scene_gltf

// tiershade scene: internal helpers of the glTF scene loader (glue/scene/gltf_load*.cpp): the error
// sink that prefixes the scene file, and typed reads of tinygltf::Value extras with places.
// Not a public interface: glue/scene/scene.h is.
#pragma once
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>

#include <glm/glm.hpp>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace scene_gltf {

// Limits of the loader (docs/reliability.md): the .gltf/.glb file, JSON nesting (tinygltf
// converts values recursively), elements of one accessor (each read as doubles).
constexpr long long kMaxSceneFileBytes = 1LL << 30;
constexpr int kMaxJsonDepth = 128;
constexpr size_t kMaxAccessorElements = size_t(1) << 24;

// Collects the first error as "<file>: <place>: <reason>"; every fail() returns false.
struct Err {
  std::string file;
  std::string msg;
  bool fail(const std::string &place, const std::string &reason) {
    if (msg.empty()) msg = file + ": " + (place.empty() ? "" : place + ": ") + reason;
    return false;
  }
};

// "base" or "base (\"name\")".
inline std::string named(const std::string &base, const std::string &name) {
  return name.empty() ? base : base + " (\"" + name + "\")";
}

inline std::string quoted(const std::string &s) { return "\"" + s + "\""; }

// A little-endian 32-bit word (GLB headers, accessor data).
inline uint32_t le32(const unsigned char *p) {
  return p[0] | p[1] << 8 | p[2] << 16 | static_cast<uint32_t>(p[3]) << 24;
}

// The JSON type of a value, for messages ("a string", "an array" ...).
std::string value_kind(const tinygltf::Value &v);

// Every key of the object `v` must be one of `allowed`; `v` must be an object.
bool check_keys(const tinygltf::Value &v, const std::string &place, std::initializer_list<const char *> allowed,
                Err &e);

// Typed reads: fail with the place and the expected type/range.
bool read_number(const tinygltf::Value &v, const std::string &place, double lo, double hi, double *out, Err &e);
bool read_int(const tinygltf::Value &v, const std::string &place, int lo, int hi, int *out, Err &e);
bool read_bool(const tinygltf::Value &v, const std::string &place, bool *out, Err &e);  // true/false or 0/1
bool read_string(const tinygltf::Value &v, const std::string &place, std::string *out, Err &e);
bool read_vec(const tinygltf::Value &v, const std::string &place, int n, double lo, double hi, double *out, Err &e);

// Path helpers: directory of a file ("" or ending in '/'), join (absolute stays), existence.
std::string dir_of(const std::string &path);
std::string join_path(const std::string &dir, const std::string &rel);
bool file_exists(const std::string &path, long long *size = nullptr);
// Why file_exists(path) is false: "file not found: <path>" or "<path>: not a regular file (a FIFO)".
std::string missing_file(const std::string &path);
// True when path ends with suffix (e.g. ".exr") and has a name before it.
bool ends_with(const std::string &path, const char *suffix);

// Part 2 (glue/scene/gltf_source_material.cpp): glTF materials with their Source keys; images are
// already in s->images with the glTF image indices.
bool convert_materials(const tinygltf::Model &m, Scene *s, Err &e);

// Part 3 (glue/scene/gltf_extras.cpp): a KHR_lights_punctual light placed by a node's world
// matrix, and the root extras.tiershade settings (cameras are already in s).
bool convert_light(const tinygltf::Model &m, int light, const glm::dmat4 &world, const std::string &place, Scene *s,
                   Err &e);
bool convert_tiershade_extras(const tinygltf::Model &m, const std::string &scene_dir, Scene *s, Err &e);

// Part 4 (glue/scene/gltf_nodes.cpp): the node hierarchy of the default scene flattened to
// world space: mesh primitives (accessors read and checked), cameras and lights.
bool convert_nodes(const tinygltf::Model &m, Scene *s, Err &e);
// glue/scene/camera_ortho.cpp: an orthographic camera's xmag, ymag, znear, zfar into *sc.
bool read_orthographic(const tinygltf::Camera &c, const std::string &place, SceneCamera *sc, Err &e);

}  // namespace scene_gltf

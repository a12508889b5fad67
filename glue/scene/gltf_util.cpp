// tiershade scene: helpers of the glTF scene loader: typed reads of extras values with
// their places in messages, key checks, and small path helpers (glue/scene/gltf_util.h).
#include "scene/gltf_util.h"

#include <sys/stat.h>

#include <cstdio>
#include <cstring>

namespace scene_gltf {

std::string value_kind(const tinygltf::Value &v) {
  if (v.IsBool()) return "a boolean";
  if (v.IsNumber()) return "a number";
  if (v.IsString()) return "a string";
  if (v.IsArray()) return "an array";
  if (v.IsObject()) return "an object";
  return "null";
}

static std::string num(double x) {
  char b[64];
  snprintf(b, sizeof b, "%g", x);
  return b;
}

bool check_keys(const tinygltf::Value &v, const std::string &place, std::initializer_list<const char *> allowed,
                Err &e) {
  if (!v.IsObject()) return e.fail(place, "expected an object, got " + value_kind(v));
  for (const std::string &k : v.Keys()) {
    bool ok = false;
    for (const char *a : allowed) ok = ok || k == a;
    if (!ok) return e.fail(place, "unknown key " + quoted(k));
  }
  return true;
}

bool read_number(const tinygltf::Value &v, const std::string &place, double lo, double hi, double *out, Err &e) {
  if (!v.IsNumber()) return e.fail(place, "expected a number, got " + value_kind(v));
  const double x = v.GetNumberAsDouble();
  if (!std::isfinite(x)) return e.fail(place, "the number is not finite");
  if (x < lo || x > hi) return e.fail(place, num(x) + " is outside [" + num(lo) + ", " + num(hi) + "]");
  *out = x;
  return true;
}

bool read_int(const tinygltf::Value &v, const std::string &place, int lo, int hi, int *out, Err &e) {
  if (!v.IsNumber()) return e.fail(place, "expected an integer, got " + value_kind(v));
  const double x = v.GetNumberAsDouble();
  if (!std::isfinite(x) || x != std::floor(x)) return e.fail(place, "expected an integer, got " + num(x));
  if (x < lo || x > hi) return e.fail(place, num(x) + " is outside [" + num(lo) + ", " + num(hi) + "]");
  *out = static_cast<int>(x);
  return true;
}

bool read_bool(const tinygltf::Value &v, const std::string &place, bool *out, Err &e) {
  if (v.IsBool()) {
    *out = v.Get<bool>();
    return true;
  }
  if (v.IsNumber() && (v.GetNumberAsDouble() == 0 || v.GetNumberAsDouble() == 1)) {
    *out = v.GetNumberAsDouble() == 1;
    return true;
  }
  return e.fail(place,
                "expected true/false or 0/1, got " + (v.IsNumber() ? num(v.GetNumberAsDouble()) : value_kind(v)));
}

bool read_string(const tinygltf::Value &v, const std::string &place, std::string *out, Err &e) {
  if (!v.IsString()) return e.fail(place, "expected a string, got " + value_kind(v));
  *out = v.Get<std::string>();
  return true;
}

bool read_vec(const tinygltf::Value &v, const std::string &place, int n, double lo, double hi, double *out, Err &e) {
  if (!v.IsArray() || v.ArrayLen() != static_cast<size_t>(n))
    return e.fail(place,
                  "expected an array of " + std::to_string(n) + " numbers, got " +
                      (v.IsArray() ? "an array of " + std::to_string(v.ArrayLen()) : value_kind(v)));
  for (int i = 0; i < n; ++i)
    if (!read_number(v.Get(i), place + "[" + std::to_string(i) + "]", lo, hi, &out[i], e)) return false;
  return true;
}

std::string dir_of(const std::string &path) {
  const size_t p = path.find_last_of('/');
  return p == std::string::npos ? std::string() : path.substr(0, p + 1);
}

std::string join_path(const std::string &dir, const std::string &rel) {
  if (!rel.empty() && rel[0] == '/') return rel;
  return dir + rel;
}

bool ends_with(const std::string &path, const char *suffix) {
  const size_t n = strlen(suffix);
  return path.size() > n && path.compare(path.size() - n, n, suffix) == 0;
}

bool file_exists(const std::string &path, long long *size) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  if (size) *size = static_cast<long long>(st.st_size);
  return true;
}

std::string missing_file(const std::string &path) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return "file not found: " + path;
  return path + ": not a regular file (" + (S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISDIR(st.st_mode) ? "a directory" : "a device or special file") + ")";
}

}  // namespace scene_gltf

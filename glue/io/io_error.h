// tiershade io: the shape of the image readers' and writers' error messages,
// "<function>: '<path>': <reason>" (io/exr.h, io/png.h, io/radiance_hdr.h).
#pragma once
#include <string>

inline std::string io_fail(const char *fn, const std::string &path, const std::string &reason) {
  return std::string(fn) + ": '" + path + "': " + reason;
}

// *err = io_fail(...) when err is not null; returns false, for `return io_error(...)`.
inline bool io_error(std::string *err, const char *fn, const std::string &path, const std::string &reason) {
  if (err) *err = io_fail(fn, path, reason);
  return false;
}

// tiershade io: atomic file writes (io/atomic_file.h).
#include "io/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace {
std::string reason(const char *what, int e) { return std::string(what) + " (" + std::strerror(e ? e : EIO) + ")"; }
}  // namespace

std::string temp_path_for(const std::string &path) {
  return path + ".tmp." + std::to_string(static_cast<long>(getpid()));
}

bool write_and_close(FILE *fp, const void *data, size_t n, std::string *why, bool sync) {
  int e = 0;
  bool ok = n == 0 || std::fwrite(data, 1, n, fp) == n;
  if (!ok) e = errno;
  if (ok && (std::fflush(fp) != 0 || std::ferror(fp))) {
    ok = false;
    e = errno;
  }
  if (ok && sync && ::fsync(fileno(fp)) != 0) {
    ok = false;
    e = errno;
  }
  if (std::fclose(fp) != 0 && ok) {
    ok = false;
    e = errno;
  }
  if (!ok) *why = reason("write failed", e);
  return ok;
}

AtomicFile::AtomicFile(const std::string &path) : path_(path), tmp_(temp_path_for(path)) {}

AtomicFile::~AtomicFile() {
  if (fp_) std::fclose(fp_);
  if (created_ && !committed_) ::unlink(tmp_.c_str());
}

bool AtomicFile::open(std::string *why) {
  fp_ = std::fopen(tmp_.c_str(), "wb");
  if (!fp_) {
    *why = reason("cannot write", errno);
    return false;
  }
  created_ = true;
  return true;
}

bool AtomicFile::commit(std::string *why) {
  FILE *fp = fp_;
  fp_ = nullptr;
  if (!fp) {
    *why = "write failed (the file was not opened)";
    return false;
  }
  if (!write_and_close(fp, nullptr, 0, why)) return false;
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    *why = reason("cannot replace", errno);
    return false;
  }
  committed_ = true;
  return true;
}

bool write_file_atomic(const std::string &path, const void *data, size_t n, std::string *err) {
  AtomicFile f(path);
  std::string why;
  bool ok = f.open(&why);
  if (ok && n != 0 && std::fwrite(data, 1, n, f.fp()) != n) {
    why = reason("write failed", errno);
    ok = false;
  }
  if (ok) ok = f.commit(&why);
  if (!ok) *err = path + ": " + why;
  return ok;
}

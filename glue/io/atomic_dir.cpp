// tiershade io: atomic output directories (io/atomic_dir.h).
#include "io/atomic_dir.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io/atomic_file.h"

namespace fs = std::filesystem;

bool DirWriter::begin(const std::string &dir, const std::string &marker, const std::string &what, std::string *err) {
  std::error_code ec;
  dir_ = dir;
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
  if (dir_.empty()) {
    *err = "empty output directory name";
    return false;
  }
  const fs::file_status st = fs::symlink_status(dir_, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) {
      *err = dir_ + ": exists and is not a directory; refusing to replace it with a " + what;
      return false;
    }
    if (!fs::is_regular_file(fs::path(dir_) / marker, ec) && !fs::is_empty(dir_, ec)) {
      *err = dir_ + ": exists and is not a previous " + what + " (no " + marker + "); refusing to replace it";
      return false;
    }
  }
  tmp_ = temp_path_for(dir_);
  fs::remove_all(tmp_, ec);
  if (!fs::create_directory(tmp_, ec)) {
    *err = dir_ + ": cannot create the temporary " + tmp_ + ": " + (ec ? ec.message() : std::string("already exists"));
    tmp_.clear();
    return false;
  }
  return true;
}

bool DirWriter::mkdir(const std::string &rel, std::string *err) {
  std::error_code ec;
  fs::create_directories(path(rel), ec);
  if (ec) {
    *err = "cannot create " + dir_ + "/" + rel + ": " + ec.message();
    return false;
  }
  return true;
}

bool DirWriter::write(const std::string &rel, const void *data, size_t bytes, std::string *err) {
  const std::string p = path(rel);
  FILE *f = fopen(p.c_str(), "wb");
  std::string why;
  if (!f) {
    *err = "cannot write " + dir_ + "/" + rel + ": " + strerror(errno);
    return false;
  }
  if (!write_and_close(f, data, bytes, &why, /*sync=*/false)) {  // synced together in commit()
    *err = "cannot write " + dir_ + "/" + rel + ": " + why;
    return false;
  }
  return true;
}

bool DirWriter::commit(std::string *err) {
  std::error_code ec;
  {  // every file's data on disk before the rename makes them visible: one syncfs for the
     // directory's file system instead of an fsync per file (a draw dump of a large scene has
     // thousands of files; each fsync cost milliseconds)
    const int fd = ::open(tmp_.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0 || ::syncfs(fd) != 0) {
      *err = "cannot write " + dir_ + ": " + strerror(errno);
      if (fd >= 0) ::close(fd);
      return false;
    }
    ::close(fd);
  }
  const std::string old = dir_ + ".old." + std::to_string(static_cast<long>(getpid()));
  const bool had = fs::exists(fs::symlink_status(dir_, ec));
  if (had && std::rename(dir_.c_str(), old.c_str()) != 0) {
    *err = "cannot move the previous " + dir_ + " aside: " + strerror(errno);
    return false;
  }
  if (std::rename(tmp_.c_str(), dir_.c_str()) != 0) {
    *err = "cannot rename " + tmp_ + " to " + dir_ + ": " + strerror(errno);
    if (had) std::rename(old.c_str(), dir_.c_str());
    return false;
  }
  committed_ = true;
  if (had) fs::remove_all(old, ec);
  return true;
}

DirWriter::~DirWriter() {
  if (!committed_ && !tmp_.empty()) {
    std::error_code ec;
    fs::remove_all(tmp_, ec);
  }
}

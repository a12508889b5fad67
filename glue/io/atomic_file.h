// tiershade io: writing a file atomically. The bytes go to "<path>.tmp.<pid>", which is
// flushed, fsync'ed and closed (each step checked) and only then renamed over <path>; on any
// failure the temporary is removed and <path> is untouched. io/atomic_dir.h does the same for
// a directory with these helpers.
#pragma once
#include <cstddef>
#include <cstdio>
#include <string>
#include "base/noncopyable.h"

// "<path>.tmp.<pid>": the temporary name of a file or directory being written.
std::string temp_path_for(const std::string &path);

// Writes n bytes to fp, then fflush, fsync (unless sync is false) and fclose, each checked; fp is closed in every
// case. On failure *why = "write failed (<reason>)".
// sync = false leaves the flush to disk to the caller (DirWriter syncs its directory's files at once).
bool write_and_close(FILE *fp, const void *data, size_t n, std::string *why, bool sync = true);

// A file written under its temporary name and renamed into place by commit(). The destructor
// removes the temporary unless commit() succeeded, so every early return cleans up. Reasons
// (*why) name no file; callers put the path in front:
//   "cannot write (<reason>)"   the temporary cannot be created
//   "write failed (<reason>)"   a write, the flush, fsync or close failed
//   "cannot replace (<reason>)" the rename failed
class AtomicFile : NonCopyable {
 public:
  explicit AtomicFile(const std::string &path);
  ~AtomicFile();

  bool open(std::string *why);
  FILE *fp() const { return fp_; }  // valid between open() and commit()
  const std::string &tmp_path() const { return tmp_; }
  // Flushes, syncs and closes the temporary, then renames it over the path.
  bool commit(std::string *why);

 private:
  std::string path_, tmp_;
  FILE *fp_ = nullptr;
  bool created_ = false, committed_ = false;
};

// The whole of `bytes` written to `path` through an AtomicFile; *err = "<path>: <reason>".
bool write_file_atomic(const std::string &path, const void *data, size_t n, std::string *err);
inline bool write_file_atomic(const std::string &path, const std::string &bytes, std::string *err) {
  return write_file_atomic(path, bytes.data(), bytes.size(), err);
}

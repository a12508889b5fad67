// tiershade io: writing an output directory atomically. Files go into DIR.tmp.<pid>, which
// is renamed over DIR at the end; an existing DIR is only replaced when it holds `marker`
// (a file this kind of output always writes) or is empty, so a user's other directory is never lost.
#pragma once
#include <string>

class DirWriter {
 public:
  // Checks DIR (absent, empty, or a directory holding `marker`) and creates a fresh DIR.tmp.<pid>.
  // what: "bundle", "draw dump" (for messages).
  bool begin(const std::string &dir, const std::string &marker, const std::string &what, std::string *err);
  const std::string &tmp() const { return tmp_; }
  std::string path(const std::string &rel) const { return tmp_ + "/" + rel; }
  bool mkdir(const std::string &rel, std::string *err);
  // Writes a file (binary) under the temporary directory; errors name the final path.
  bool write(const std::string &rel, const void *data, size_t bytes, std::string *err);
  bool write(const std::string &rel, const std::string &text, std::string *err) {
    return write(rel, text.data(), text.size(), err);
  }
  // Renames the temporary directory over DIR (the old one is removed afterwards).
  bool commit(std::string *err);
  ~DirWriter();  // removes the temporary directory unless committed

 private:
  std::string dir_, tmp_;
  bool committed_ = false;
};

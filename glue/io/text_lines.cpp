// tiershade io: plain-text input files line by line (see text_lines.h).
#include "io/text_lines.h"

#include <sys/stat.h>

bool TextLines::open(const std::string &path, const std::string &what, std::string *err) {
  path_ = path;
  what_ = what;
  lineno_ = 0;
  struct stat st;
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
    *err = "cannot read " + what + " file '" + path + "' (not a readable regular file)";
    return false;
  }
  in_.open(path);
  if (!in_) {
    *err = "cannot read " + what + " file '" + path + "'";
    return false;
  }
  return true;
}

bool TextLines::next(std::string *line) {
  if (!std::getline(in_, *line)) return false;
  ++lineno_;
  const size_t hash = line->find('#');
  if (hash != std::string::npos) line->resize(hash);
  return true;
}

bool TextLines::finish(std::string *err) const {
  if (!in_.bad()) return true;
  *err = "cannot read " + what_ + " file '" + path_ + "' (read error after line " + std::to_string(lineno_) + ")";
  return false;
}

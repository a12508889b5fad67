// tiershade io: a plain-text input file read line by line with '#' comments removed (the lights
// file, probe --input); its errors name the file and, through where(), the line.
#pragma once
#include <fstream>
#include <string>

class TextLines {
 public:
  // Opens `path`; false with *err = "cannot read <what> file 'PATH'" (+ " (not a readable regular
  // file)") when it cannot be read.
  bool open(const std::string &path, const std::string &what, std::string *err);
  // The next line, its '#' comment removed; false at the end of the file or on a read error.
  bool next(std::string *line);
  // "PATH:N" for the line next() returned last (lines count from 1).
  std::string where() const { return path_ + ":" + std::to_string(lineno_); }
  // After the last next(): false with *err = "cannot read <what> file 'PATH' (read error after
  // line N)" if reading stopped on an error rather than at the end.
  bool finish(std::string *err) const;

 private:
  std::ifstream in_;
  std::string path_, what_;
  int lineno_ = 0;
};

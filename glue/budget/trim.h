// tiershade budget: trim(), the one string helper shared by the source preparation
// (glsl_to_spirv.cpp) and the NIR text counter (nir_count.cpp). Internal to glue/budget/.
#pragma once

#include <string>

namespace budget {

// s without leading and trailing blanks (space, tab, CR, LF).
inline std::string trim(const std::string &s) {
  size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return std::string();
  size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

}  // namespace budget

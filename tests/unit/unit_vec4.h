// tiershade tests: ts_vec4f results compared to the bit (0 ULP) and shown exactly (hex floats)
// in a FAIL line.
#pragma once
#include <cstdio>
#include <cstring>
#include <string>

#include "math/ts_math.h"

inline bool same_bits(const ts_vec4f &a, const ts_vec4f &b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline std::string show(const ts_vec4f &c) {
  char b[160];
  snprintf(b, sizeof b, "(%a, %a, %a, %a)", c.x, c.y, c.z, c.w);
  return b;
}

// tiershade tests: the PASS/FAIL lines the unit tests print (one line per check; a detail's newlines become
// '|'), and their counts for the closing "N passed, N failed" line (tests/run_tests.sh reads
// both). Header-only: each test is one translation unit.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace unit_check {
inline int g_failed = 0, g_passed = 0;

inline void check(bool ok, const std::string &name, const std::string &detail = "") {
  if (ok) {
    ++g_passed;
    printf("PASS %s\n", name.c_str());
  } else {
    ++g_failed;
    std::string d = detail;
    for (char &c : d)
      if (c == '\n') c = '|';
    printf("FAIL %s: %s\n", name.c_str(), d.c_str());
  }
  fflush(stdout);
}

// The closing line "N passed, N failed" and the exit status (1 when any check failed).
inline int finish() {
  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed ? 1 : 0;
}

// A float's bits and back, for checks that compare values to the bit (0 ULP).
inline uint32_t bits_of(float f) {
  uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}
inline float float_of_bits(uint32_t b) {
  float f;
  std::memcpy(&f, &b, 4);
  return f;
}
}  // namespace unit_check

using unit_check::bits_of;
using unit_check::check;
using unit_check::finish;
using unit_check::float_of_bits;
using unit_check::g_failed;
using unit_check::g_passed;

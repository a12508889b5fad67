// tiershade tests: the PASS/FAIL lines the unit tests print (one line per check; a detail's newlines become
// '|'), and their counts for the closing "N passed, N failed" line (tests/run_tests.sh reads
// both). Header-only: each test is one translation unit.
#pragma once
#include <cstdio>
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
}  // namespace unit_check

using unit_check::check;
using unit_check::g_failed;
using unit_check::g_passed;

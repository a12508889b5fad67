// tiershade bench: what the sections share to write their tables: milliseconds since a time
// point and numbers with one or two decimals.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace bench {

using Clock = std::chrono::steady_clock;
inline double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}
inline std::string fixed(double v, int decimals) {
  char b[32];
  snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}
inline std::string f1(double v) { return fixed(v, 1); }
inline std::string f2(double v) { return fixed(v, 2); }

}  // namespace bench

// tiershade base: the median the benchmarks and timings report.
#pragma once
#include <algorithm>
#include <vector>

// The middle value of v after sorting; for an even count the upper of the two middle values
// (so a median is always one of the measurements). 0 for an empty vector.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// tiershade scene: checks and clamps of values before upload (see finite_check.h).
#include "scene/finite_check.h"

#include <cmath>

namespace {
std::string special_name(float f) { return std::isnan(f) ? "NaN" : (f > 0 ? "Inf" : "-Inf"); }
}  // namespace

bool clamp_texels_to_fp16(float *v, size_t n, const std::string &where, size_t *clamped, std::string *err) {
  size_t c = 0;
  for (size_t i = 0; i < n; ++i) {
    if (std::isnan(v[i])) {
      if (err) *err = where + ": value " + std::to_string(i) + " is NaN (refused: no value can stand for it)";
      return false;
    }
    if (v[i] > kFp16Max || v[i] < -kFp16Max) {
      v[i] = v[i] > 0 ? kFp16Max : -kFp16Max;
      ++c;
    }
  }
  if (clamped) *clamped = c;
  return true;
}

bool check_finite(const float *v, size_t n, const std::string &where, std::string *err) {
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) {
      if (err) *err = where + ": value " + std::to_string(i) + " is " + special_name(v[i]) + " (must be finite)";
      return false;
    }
  return true;
}

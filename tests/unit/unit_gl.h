// tiershade tests: the GL context of a unit test's checks on one backend/API. A context that
// cannot be created is a FAIL line naming the checks it stops, never a skip.
#pragma once
#include <memory>
#include <string>

#include "gl/context.h"
#include "unit_check.h"

// "egl/gles3": a backend/API pair as check names spell it.
inline std::string config_name(Backend b, Api api) { return std::string(backend_name(b)) + "/" + api_name(api); }

// The context, or nullptr after a FAIL line "<check_name>: <why>".
inline std::unique_ptr<GlContext> open_context(Backend b, Api api, const std::string &check_name) {
  std::string err;
  std::unique_ptr<GlContext> ctx = GlContext::create(b, api, &err);
  if (!ctx) check(false, check_name, err);
  return ctx;
}

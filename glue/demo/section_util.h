// tiershade demo: what the demo sections share: one GL context per configured backend and API,
// and a section's closing verdict.
#pragma once
#include <functional>
#include <string>

#include "families/family.h"
#include "gl/context.h"
#include "gl/float_target.h"

// The label of a backend and API in file names and tables: "osmesa_gl33", "egl_gles2", ...
std::string config_tag(const BackendApi &cfg);

// Calls body(cfg, tag, renderer) for each backend and API of opt.configs, in order, each with a
// context and renderer of its own (released after the call). Stops at the first body that returns
// false, its *err kept; a context that cannot be created fails with *err = "<tag>: <reason>".
using GlConfigBody = std::function<bool(const BackendApi &cfg, const std::string &tag, GlRenderer &r)>;
bool for_each_gl_config(const DemoOptions &opt, const GlConfigBody &body, std::string *err);

// A section's result: true when nothing failed, else false with *err = "<failures> <what>"
// (e.g. "2 GL frames differ from the C fallback").
bool demo_section_result(int failures, const std::string &what, std::string *err);

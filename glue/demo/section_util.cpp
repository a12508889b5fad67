// tiershade demo: what the demo sections share (section_util.h).
#include "demo/section_util.h"

std::string config_tag(const BackendApi &cfg) {
  return std::string(backend_name(cfg.backend)) + "_" + api_name(cfg.api);
}

bool for_each_gl_config(const DemoOptions &opt, const GlConfigBody &body, std::string *err) {
  for (const BackendApi &cfg : opt.configs) {
    const std::string tag = config_tag(cfg);
    auto ctx = GlContext::create(cfg.backend, cfg.api, err);
    if (!ctx) {
      *err = tag + ": " + *err;
      return false;
    }
    GlRenderer r(*ctx);
    if (!body(cfg, tag, r)) return false;
  }
  return true;
}

bool demo_section_result(int failures, const std::string &what, std::string *err) {
  if (!failures) return true;
  *err = std::to_string(failures) + " " + what;
  return false;
}

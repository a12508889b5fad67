// tiershade bundle: what a browser must offer for a variant (issue 14, docs/bundles.md
// "Extensions"): the WebGL extensions it needs on a target, derived from what its assembled
// source contains once preprocessed (sampler3D, dFdx, ...), the samplers and outputs it
// uses (its declared interface, glue/budget/interface.h) and the state the bundle's draws are
// replayed in (RGBA32F textures and colour target, 32-bit indices). essl100 is WebGL 1,
// essl300 WebGL 2; glsl330 is desktop GL 3.3 core, where nothing is listed.
#pragma once
#include <string>
#include <vector>

#include "budget/interface.h"
#include "shaderlib/assembler.h"
#include "shaderlib/variants.h"

struct ExtensionNeed {
  std::string name;  // the WebGL name, e.g. "OES_texture_float"
  std::vector<std::string> alternatives;  // any one of these instead (empty: none)
  std::string why;
};

// Extensions of the WebGL version `target` is for that no browser exposes (WebGL 1:
// OES_texture_3D). A variant needing one is not offered on that target.
bool extension_unavailable(Target target, const std::string &name);

// The extensions `v` needs on `target`. iface: the program's declared interface, or nullptr
// to look at the source only (what decides whether the target offers the variant).
bool variant_extensions(const Variant &v, Target target, const ProgramInterface *iface, std::vector<ExtensionNeed> *out,
                        std::string *err);

// Whether `target` offers `v`: false with the reason in *why_not when it needs an extension no
// browser exposes (color_correction's 3D-LUT variants on essl100). *err: assembly failures.
bool target_offers(const Variant &v, Target target, bool *offered, std::string *why_not, std::string *err);

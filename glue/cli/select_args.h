// tiershade cli: --shader/--tier/--variant and --backend/--api selections shared by subcommands.
#pragma once
#include <memory>
#include <vector>

#include "cli/args.h"
#include "gl/context.h"
#include "shaderlib/variants.h"

// Selection (a variant set with its declarations) is shaderlib/variants.h's.

// Fills sel from --shader S (default all), --tier T (repeatable, default all), --variant V.
void select_variants(const Args &a, Selection *sel);
// --backend osmesa|egl|all (default all), --api gl33|gles2|gles3|all (default all supported).
std::vector<BackendApi> select_configs(const Args &a);

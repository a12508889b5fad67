// tiershade main: command-line front end. `tiershade --help` lists the subcommands.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#include "cli/args.h"
#include "math/ts_math.h"

static const char kUsage[] =
    "tiershade: Source-engine shading (SIGGRAPH 2006) as tiered GLSL with a bit-exact C reference\n"
    "\n"
    "usage: tiershade <command> [options]   (tiershade <command> --help for each)\n"
    "\n"
    "commands:\n"
    "  variants   list the shader variants (tier x static x dynamic combos, minus skips)\n"
    "  assemble   print the assembled GLSL of one variant for a target (essl100, essl300, glsl330)\n"
    "  budget     count instruction slots per variant and check the tier budgets\n"
    "  conform    per-pixel conformance: llvmpipe (OSMesa, EGL) against the C reference\n"
    "  probe      evaluate one pixel of a variant in GL and in C, side by side\n"
    "  fold       fold lights beyond a tier's limit into the ambient cube, and check what it conserves\n"
    "  demo       render the lit sphere grid in each tier, on both backends and in C, to out/\n"
    "  bench      measure accuracy against time and write docs/accuracy_cost.md\n"
    "  lut        colour-correction LUTs: inspect, bake from OpenColorIO, convert .cube <-> Source .raw\n"
    "  render     render a glTF scene with only the variants it needs (GL or the C fallback)\n"
    "  bake       bake a scene's lightmaps into a bake directory (page + manifest) for extras.tiershade.lightmaps.bake\n"
    "  light      what the bake says at a point: the face, the luxel, the irradiance and the four lightmap values\n"
    "  ambient    fit an ambient cube (six colours) to a lat-long light probe\n"
    "  check-bundle  check bundles' manifests against what headless Chromium reports active\n"
    "  web        the WebGL 2 demo page of a scene, from its bundle and its draw dump\n";

int cmd_ambient(int argc, char **argv);  // glue/cli/cmd_ambient.cpp

int main(int argc, char **argv) {
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
    fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  signal(SIGXFSZ, SIG_IGN);  // a file-size limit (RLIMIT_FSIZE) fails the write with EFBIG, reported, not a kill
  ts_math_init();  // FTZ|DAZ and the fused-mad choice, as llvmpipe computes
  const std::string cmd = argv[1];
  struct {
    const char *name;
    int (*fn)(int, char **);
  } const table[] = {{"variants", cmd_variants}, {"assemble", cmd_assemble}, {"budget", cmd_budget},
                     {"conform", cmd_conform},   {"probe", cmd_probe},       {"fold", cmd_fold},
                     {"demo", cmd_demo},         {"bench", cmd_bench},       {"lut", cmd_lut},
                     {"render", cmd_render},     {"bake", cmd_bake},
                     {"light", cmd_light},
                     {"ambient", cmd_ambient},   {"check-bundle", cmd_check_bundle}, {"web", cmd_web}};
  for (const auto &c : table)
    if (cmd == c.name) return c.fn(argc - 2, argv + 2);
  fprintf(stderr, "tiershade: unknown command '%s'\n\n%s", cmd.c_str(), kUsage);
  return 2;
}

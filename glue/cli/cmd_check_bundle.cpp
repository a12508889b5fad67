// tiershade cli: `check-bundle` subcommand: bundles' manifests against a browser's reflection
// (glue/browser/bundle_check.h; docs/bundles.md, "Checked in a browser").
#include <cstdio>

#include "browser/bundle_check.h"
#include "cli/args.h"

namespace {
const char kHelp[] = R"(usage: tiershade check-bundle DIR... [--timeout S] [--verbose]
Links every program of the bundles DIR... (written by `tiershade variants ... -o DIR`; essl100 in
WebGL 1, essl300 in WebGL 2, glsl330 bundles are skipped) on one page in headless Chromium and checks
what getActiveAttrib / getActiveUniform report against each manifest: every active entry is in the
declared interface (name, type, at most the declared array size), and every declared entry that
may_trim does not list is active at its declared size. Also prints in how many programs Chromium's
active set differs from Mesa's (the declared interface minus may_trim; --verbose: which entries).
Exit 0 when every program passes, 1 when one fails (each failure on its own line), 2 on bad
arguments or an unreadable bundle. --timeout: the browser is killed after S seconds (default 300).)";
}  // namespace

int cmd_check_bundle(int argc, char **argv) {
  Args a("check-bundle", argc, argv, {"--help", "--verbose"}, {"--timeout"});
  if (a.help(kHelp)) return 0;
  if (a.positional().empty()) a.fail("expected one or more bundle directories (tiershade check-bundle DIR...)");
  const int timeout = a.get_int("--timeout", 300, 1, 3600);
  BundleCheckOutcome o;
  std::string err;
  if (!check_bundles_in_chromium(a.positional(), timeout, &o, &err)) {
    fprintf(stderr, "tiershade check-bundle: %s\n", err.c_str());
    return err.find("manifest.json") != std::string::npos || err.find(": cannot open") != std::string::npos ? 2 : 1;
  }
  for (int v = 1; v <= 2; ++v)
    if (!o.renderer[v].empty()) printf("WebGL %d: %s\n", v, o.renderer[v].c_str());
  printf("%d bundles (%d glsl330 skipped), %d programs, %d distinct, %d active entries\n", o.bundles, o.skipped_bundles,
         o.programs, o.distinct, o.active_entries);
  printf("Mesa's reflection differs from Chromium's in %d of %d distinct programs\n", o.differ_from_mesa, o.distinct);
  if (a.flag("--verbose"))
    for (const auto &d : o.mesa_differences) printf("  differs: %s\n", d.c_str());
  printf("declared interface: %d active entries outside it, %d required entries inactive, %d trimmed entries under "
         "may_trim\n",
         o.outside_declared, o.required_inactive, o.trimmed_by_browser);
  for (const auto &p : o.problems) printf("FAIL %s\n", p.c_str());
  printf("%s\n", o.problems.empty() ? "ok: every manifest agrees with Chromium's reflection"
                                    : (std::to_string(o.problems.size()) + " problems").c_str());
  return o.problems.empty() ? 0 : 1;
}

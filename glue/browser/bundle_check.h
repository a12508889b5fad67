// tiershade browser: a bundle's manifests against a browser's reflection (issue 14; docs/bundles.md,
// "Checked in a browser"). Every program of the given bundles (essl100: WebGL 1, essl300: WebGL 2)
// is linked on one page, glue/browser/webgl_reflect.{html,js}, in headless Chromium (ANGLE on
// SwiftShader), and what getActiveAttrib / getActiveUniform report is checked against the
// manifest: every active entry is in the declared interface with its type and at most its declared
// size; every declared entry the manifest does not list under may_trim is active at its declared
// size. Also counted: the programs where Chromium's active set differs from Mesa's (the declared
// interface minus may_trim, the sizes may_trim gives), which is what manifests said before issue 14.
#pragma once
#include <string>
#include <vector>

struct BundleCheckOutcome {
  std::string renderer[3];  // [1], [2]: what the WebGL 1 / 2 contexts reported (empty if unused)
  int bundles = 0, skipped_bundles = 0;  // read; not for a browser (glsl330)
  int programs = 0, distinct = 0;  // programs checked (one per manifest variant); distinct sources
  int active_entries = 0;  // active attributes and uniforms reported, summed over the distinct programs
  int outside_declared = 0;  // active entries not in the declared interface (name, type, size)
  int required_inactive = 0;  // declared entries not under may_trim that were not active (at full size)
  int trimmed_by_browser = 0;  // declared entries the browser trimmed that may_trim lists (allowed)
  int differ_from_mesa = 0;  // distinct programs whose active set differs from Mesa's reflection
  std::vector<std::string> problems;  // one line each: bundle, variant, entry, what is wrong
  std::vector<std::string> mesa_differences;  // one line per distinct program that differs from Mesa
};

// False with *err when a bundle cannot be read (the file and place named) or the browser or the
// page fails; a check that fails is a problem in out->problems, not an error.
bool check_bundles_in_chromium(const std::vector<std::string> &dirs, int timeout_s, BundleCheckOutcome *out,
                               std::string *err);

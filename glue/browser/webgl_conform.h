// tiershade browser: per-pixel conformance in a browser (issue 14, docs/conformance.md "In a
// browser"). The same variants and input grids as `tiershade conform`, drawn by the WebGL page
// glue/browser/webgl_conform.{html,js} in headless Chromium (ANGLE on SwiftShader), read back as
// RGBA32F and checked against the GLSL ES error bounds of the twins' interval instances
// (conform/bounds.h). Not against the 0-ULP C twin: that claim holds on llvmpipe only.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "conform/bounds.h"

struct WebglConformOptions {
  int webgl = 2;                 // 1: WebGL 1 (essl100), 2: WebGL 2 (essl300)
  int programs_per_page = 48;    // programs per browser run (each run starts Chromium once)
  int timeout_s = 600;           // per page: a hung browser is killed and the run fails
};

struct WebglConformOutcome {
  std::string renderer;  // what the page reported: the WebGL version and the unmasked renderer
  std::vector<BoundsResult> results;  // one per offered variant and input set, in the given order
  std::vector<std::string> not_offered;  // variants the target does not offer, with the reason
};

// `inputs[family][i]` is the grid of `sets[i]` for that family (as cmd_conform makes them).
// False with *err when the browser cannot run at all (none installed, the page failed); a variant
// that fails to compile is a failed result, not an error.
bool webgl_conform(const std::vector<Variant> &variants, const std::map<std::string, std::vector<FamilyInputs>> &inputs,
                   const std::vector<InputSet> &sets, const WebglConformOptions &opt, WebglConformOutcome *out,
                   std::string *err);

// The conformance page a user opens in their own browser (docs/conformance.md "On your device"):
// writes DIR/index.html, webgl_conform.js and job.js (atomically: DIR.tmp.<pid>, then renamed; an
// existing DIR is replaced only if it holds job.js). The job carries every offered variant's program,
// grids and, per pixel, the intervals; the page draws, checks and shows per variant inside / outside
// / width with the worst pixel's inputs. *programs_written: the variants in it.
bool webgl_conform_write_page(const std::vector<Variant> &variants,
                              const std::map<std::string, std::vector<FamilyInputs>> &inputs,
                              const std::vector<InputSet> &sets, int webgl, const std::string &dir,
                              std::vector<std::string> *not_offered, size_t *programs_written, std::string *err);

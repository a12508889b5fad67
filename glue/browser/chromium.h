// tiershade browser: headless Chromium as a second GL implementation (WebGL through ANGLE on
// SwiftShader: ../shared/docs/platform_notes.md section 6 gives the command line that works).
#pragma once
#include <string>
#include <utility>
#include <vector>

// The browser to run: $TIERSHADE_CHROMIUM when set, else `chromium` or `chromium-browser` on PATH
// (Debian's `chromium`, installed by `make deps`). False with *err saying what was looked for.
bool find_chromium(std::string *path, std::string *err);

// Opens file://`html` in headless Chromium (SwiftShader, no sandbox, a fresh profile under
// `scratch_dir`) and returns the page's DOM once its scripts have run (--dump-dom). The browser and
// every process it starts are killed after `timeout_s` seconds (a hang is an error, never a wait).
// False with *err (the exit status or the timeout, and the end of Chromium's stderr).
bool chromium_dump_dom(const std::string &html, const std::string &scratch_dir, int timeout_s, std::string *dom,
                       std::string *err);

// Writes `files` (name, content) into a fresh scratch directory under $TMPDIR (removed afterwards),
// opens `html` (one of them) with chromium_dump_dom and returns the text of the page's
// <pre id="out">, its HTML escapes undone: how tiershade's pages (glue/browser/*.html) report.
// False with *err when the browser fails or the page wrote no <pre id="out">.
bool chromium_run_page(const std::vector<std::pair<std::string, std::string>> &files, const std::string &html,
                       int timeout_s, std::string *text, std::string *err);

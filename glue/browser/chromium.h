// tiershade browser: headless Chromium as a second GL implementation (WebGL through ANGLE on
// SwiftShader: ../shared/docs/platform_notes.md section 6 gives the command line that works).
#pragma once
#include <string>

// The browser to run: $TIERSHADE_CHROMIUM when set, else `chromium` or `chromium-browser` on PATH
// (Debian's `chromium`, installed by `make deps`). False with *err saying what was looked for.
bool find_chromium(std::string *path, std::string *err);

// Opens file://`html` in headless Chromium (SwiftShader, no sandbox, a fresh profile under
// `scratch_dir`) and returns the page's DOM once its scripts have run (--dump-dom). The browser and
// every process it starts are killed after `timeout_s` seconds (a hang is an error, never a wait).
// False with *err (the exit status or the timeout, and the end of Chromium's stderr).
bool chromium_dump_dom(const std::string &html, const std::string &scratch_dir, int timeout_s, std::string *dom,
                       std::string *err);

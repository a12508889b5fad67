// tiershade budget: capture of the NIR that Mesa prints under ST_DEBUG=nir, for the
// `tiershade budget --nir` cross-check (docs/budget_model.md, "Cross-check against
// Mesa's NIR").
//
// Mesa (22.3 here) prints "NIR before handing off to driver:" followed by the final,
// scalarised NIR of every stage to stderr.  On llvmpipe (OSMesa and EGL alike) this
// happens inside glLinkProgram, which precompiles the default variant; a later draw
// with default state prints nothing more.  Mesa reads ST_DEBUG once per process, when
// the first driver screen is created, so nir_capture_setup_env() must run before the
// first GL context of the process exists.
//
// Capture is done at the file-descriptor level: fd 2 is dup()ed, a private temp file
// (mkstemp inside a mkdtemp directory under $TMPDIR, default /tmp) is dup2()ed onto
// it while the program is built, then fd 2 is restored and the file read and removed.
// While fd 2 is redirected tiershade itself writes nothing to stderr (errors are
// collected in strings); whatever else lands in the file (Mesa warnings, GL messages)
// is written back to the real stderr afterwards.  A fatal signal (SIGSEGV, SIGABRT,
// ...), SIGINT/SIGTERM/SIGHUP/SIGPIPE or a sanitizer report during the window restores
// fd 2 first, copies the tail of the captured text to it and removes the temp files,
// then lets the signal take its previous course.  Not thread-safe: one capture at a time.
#pragma once
#include <functional>
#include <string>

#include "gl/float_target.h"
#include "shaderlib/variants.h"

// Sets ST_DEBUG=nir (overwriting) and, unless the caller chose otherwise,
// MESA_SHADER_CACHE_DISABLE=true, so every link compiles from scratch and the dump
// does not depend on the state of ~/.cache/mesa_shader_cache.  Call before the first
// GlContext::create of the process.
void nir_capture_setup_env();

// Runs fn() with fd 2 redirected to a private temp file; *captured receives every byte
// written to fd 2 meanwhile.  fn must not print to stderr itself.  Returns false (with
// *err) only if the redirection could not be set up or undone; fn has then not run, or
// ran with output uncaptured.
bool capture_fd2(const std::function<void()> &fn, std::string *captured, std::string *err);

// Splits captured stderr into the NIR dump sections ("NIR before handing off to
// driver:" up to the closing "}" of the shader's last function) and everything else.
void nir_split_stderr(const std::string &captured, std::string *nir, std::string *other);

struct NirCounts {
  int alu = 0;  // scalar NIR ALU ops of the fragment stage (budget_count_nir_text)
  int tex = 0;  // NIR texture ops of the fragment stage
  std::string printed_at;  // "link" or "draw": when Mesa printed the fragment NIR
  size_t dump_bytes = 0;  // size of the NIR dump (all stages)
};

// Builds v's production program (build_production_program for `api`, the API of r's
// context; `budget --nir` uses OSMesa GL 3.3) on r with fd 2
// captured and counts the fragment section of Mesa's dump.  If the link printed no
// fragment NIR (a driver that compiles at first draw), it draws once into a 1x1 target,
// also captured.  Non-NIR text Mesa printed meanwhile goes to stderr afterwards.
// ST_DEBUG=nir must have been in effect when the context's screen was created.
bool nir_count_production(GlRenderer &r, Api api, const Variant &v, NirCounts *out, std::string *err);

// tiershade fuzz: what every libFuzzer harness (tests/fuzz/fuzz_*.cpp) shares: the input bytes as
// a file of a given name in this process's temporary directory (the readers take paths), and the
// process-wide setup (the memory limit the CLI defaults to). docs/reliability.md lists the harnesses.
#pragma once
#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "io/memory_limit.h"

namespace fuzz {

// This process's directory for input files (made once, removed at exit).
inline const std::string &dir() {
  static const std::string d = [] {
    char t[] = "/tmp/tiershade_fuzz.XXXXXX";
    const char *p = mkdtemp(t);
    if (!p) abort();
    std::string s = p;
    static std::string keep = s;
    atexit([] { std::string cmd = "rm -rf '" + keep + "'"; if (std::system(cmd.c_str()) != 0) {} });
    // Half the CLI's default: run_fuzz.sh's -rss_limit_mb=1024 (libFuzzer's malloc limit too) must
    // stay above what a reader may take inside the limit, and a decoder's own buffers exceed the
    // image it checked a little (OpenEXR's chunk buffers, libpng's rows and inflate state; before
    // libpng, stb's inflate buffer made a 1040 MiB realloc: tests/fuzz/regressions/png/).
    set_memory_limit_mib(kDefaultMemoryLimitMiB / 2);
    return s;
  }();
  return d;
}

// Writes bytes to dir()/name and returns the path.
inline std::string write_file(const std::string &name, const uint8_t *data, size_t size) {
  const std::string path = dir() + "/" + name;
  FILE *f = std::fopen(path.c_str(), "wb");
  if (!f) abort();
  if (size && std::fwrite(data, 1, size, f) != size) abort();
  if (std::fclose(f) != 0) abort();
  return path;
}

inline std::string write_text(const std::string &name, const std::string &text) {
  return write_file(name, reinterpret_cast<const uint8_t *>(text.data()), text.size());
}

}  // namespace fuzz

// tiershade cli: --max-memory and the render's memory estimate (cli/memory_estimate.h).
// The per-pixel and per-texel figures are peak resident sizes measured with /usr/bin/time -v on
// the shipped scenes at 640x360 and 2560x1440 (docs/reliability.md): the C fallback about
// 40 bytes a pixel, GL the same plus ~150 MiB for llvmpipe, --check ~160 bytes a pixel. They are
// rounded up (64 and 192), so a render the estimate admits stays under the limit.
#include "cli/memory_estimate.h"

#include <cstdio>

#include "io/memory_limit.h"

namespace {

// Resident memory now (VmRSS), bytes; 0 if unknown.
double resident_bytes() {
  FILE *f = fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  double kib = 0;
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "VmRSS: %lf kB", &kib) == 1) break;
  fclose(f);
  return kib * 1024.0;
}

}  // namespace

void apply_max_memory(const Args &a) {
  set_memory_limit_mib(a.get_int("--max-memory", static_cast<int>(kDefaultMemoryLimitMiB), 64, 1048576));
}

bool render_fits_memory(const Scene &s, int w, int h, bool gl, bool check, std::string *why, int msaa) {
  struct Part {
    std::string what;
    double bytes;
  };
  std::vector<Part> parts;
  parts.push_back({"the frame of " + std::to_string(w) + " x " + std::to_string(h) + (check ? " with --check" : ""),
                   static_cast<double>(w) * h * (check ? 192.0 : 64.0)});
  if (msaa > 1) {
    // GL: RGBA8 and 32-bit depth per sample in llvmpipe; the C fallback (glue/scene/msaa.cpp):
    // triangle, depth, robustness and layer bytes per sample, and up to one shaded layer per
    // sample (visibility 16 and RGBA32F 16 bytes a pixel); --check runs both.
    const double c_bytes = msaa * (10.0 + 32.0), gl_bytes = msaa * 8.0 + 4.0;
    parts.push_back({"the " + std::to_string(msaa) + "-sample frame",
                     static_cast<double>(w) * h * (gl ? gl_bytes + (check ? c_bytes : 0) : c_bytes)});
  }
  double probes = 0;
  for (const SceneProbe &p : s.probes) probes += 2.0 * 6 * p.size * p.size * 16;  // the cube, and its GL copy
  if (!s.probes.empty()) parts.push_back({std::to_string(s.probes.size()) + " probe cubes", probes});
  const bool world = s.lightmaps.image.empty();  // a page baked at load: ~4 float RGBA arrays a texel
  parts.push_back({"the lightmap page of " + std::to_string(s.lightmaps.page_w) + " x " +
                       std::to_string(s.lightmaps.page_h) + (world ? " (baked at load)" : ""),
                   static_cast<double>(s.lightmaps.page_w) * s.lightmaps.page_h * (world ? 64.0 : 32.0)});
  if (gl) parts.push_back({"llvmpipe", 160.0 * 1048576});
  double total = resident_bytes();
  const Part *biggest = &parts[0];
  for (const Part &p : parts) {
    total += p.bytes;
    if (p.bytes > biggest->bytes) biggest = &p;
  }
  return memory_fits(total, "the render or bake (mostly " + biggest->what + ")", why);
}

// tiershade demo: the scene file names (scene_files.h), found from the binary, not the current
// directory: the repository is the nearest of the executable's parent directories (up to three:
// build/tiershade, build/san/tiershade, build/tests/test_x) that holds scenes/sphere_grid.gltf.
// Run from that repository's root, the names stay relative ("scenes/..."), as docs quote them.
#include "demo/scene_files.h"

#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <deque>
#include <string>

namespace {

bool is_file(const std::string &p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// The repository holding the executable ("" if none), or "." when it is the current directory.
const std::string &repo_root() {
  static const std::string root = [] {
    char exe[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) return std::string();
    std::string dir(exe, static_cast<size_t>(n));
    for (int up = 0; up < 4; ++up) {
      const size_t slash = dir.find_last_of('/');
      if (slash == std::string::npos || slash == 0) break;
      dir.resize(slash);
      if (!is_file(dir + "/scenes/sphere_grid.gltf")) continue;
      char here[PATH_MAX], there[PATH_MAX];
      if (realpath(".", here) && realpath(dir.c_str(), there) && std::string(here) == there) return std::string(".");
      return dir;
    }
    return std::string();
  }();
  return root;
}

const char *in_repo(const char *rel) {
  static std::deque<std::string> names;  // stable addresses for the const char * names
  const std::string &root = repo_root();
  if (root.empty() || root == ".") return rel;
  names.push_back(root + "/" + rel);
  return names.back().c_str();
}

}  // namespace

const char *repo_file(const char *rel) { return in_repo(rel); }

const char *const kSphereGridGltf = in_repo("scenes/sphere_grid.gltf");
const char *const kSphereGridLights = in_repo("scenes/sphere_grid.lights");
const char *const kPhongSphereGltf = in_repo("scenes/phong_sphere.gltf");
const char *const kProbeChartGltf = in_repo("scenes/probe_chart.gltf");
const char *const kHdrDaylightGltf = in_repo("scenes/hdr_daylight.gltf");
const char *const kHdrDarkRoomGltf = in_repo("scenes/hdr_dark_room.gltf");
const char *const kWorldLightingGltf = in_repo("scenes/world_lighting.gltf");

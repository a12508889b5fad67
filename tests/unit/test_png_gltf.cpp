// tiershade tests: the glTF texture decoder (io/png.h decode_png_rgba, libpng) against what the scene
// loader used before it, stb_image (stbi_load(_16)_from_memory with 4 channels, as tinygltf's own
// image loader calls it), byte for byte, on every shipped texture and PNG seed; and the zip-bomb
// PNG fuzz_png found (tests/fuzz/regressions/png/) refused by the libpng path.
//
// Usage: test_png_gltf (from the repository root, as tests/run_tests.sh runs it)
//   Prints "PASS name" or "FAIL name: details" per check (tests/unit/unit_check.h); exit 1 on a failure.
#include <stb_image.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/png.h"
#include "unit_check.h"

using unit_check::check;
namespace fs = std::filesystem;

namespace {
std::vector<unsigned char> slurp(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}
}  // namespace

int main() {
  std::vector<std::string> files;
  for (const char *dir : {"scenes/textures", "tests/fuzz/corpus/png"})
    if (fs::is_directory(dir))
      for (const auto &e : fs::directory_iterator(dir))
        if (e.path().extension() == ".png") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  check(files.size() >= 20, "png_gltf_found_textures", std::to_string(files.size()) + " PNG files under scenes/textures and tests/fuzz/corpus/png");
  for (const std::string &f : files) {
    const std::vector<unsigned char> b = slurp(f);
    std::vector<unsigned char> got;
    int w = 0, h = 0, bits = 0;
    std::string why;
    const bool ok = decode_png_rgba(b.data(), b.size(), &got, &w, &h, &bits, &why);
    int sw = 0, sh = 0, sc = 0, sbits = 8;
    unsigned char *s = nullptr;
    if (stbi_is_16_bit_from_memory(b.data(), static_cast<int>(b.size()))) {
      s = reinterpret_cast<unsigned char *>(stbi_load_16_from_memory(b.data(), static_cast<int>(b.size()), &sw, &sh, &sc, 4));
      sbits = 16;
    }
    if (!s) {
      s = stbi_load_from_memory(b.data(), static_cast<int>(b.size()), &sw, &sh, &sc, 4);
      sbits = 8;
    }
    std::string detail;
    bool same = false;
    if (!ok || !s) {
      detail = !ok ? "libpng: " + why : "stb_image cannot read it";
    } else if (w != sw || h != sh || bits != sbits) {
      detail = "libpng " + std::to_string(w) + "x" + std::to_string(h) + "/" + std::to_string(bits) + " bits, stb " +
          std::to_string(sw) + "x" + std::to_string(sh) + "/" + std::to_string(sbits);
    } else {
      const size_t n = static_cast<size_t>(w) * h * 4 * (bits / 8);
      size_t diff = 0;
      for (size_t i = 0; i < n && i < got.size(); ++i) diff += got[i] != s[i];
      same = got.size() == n && diff == 0;
      detail = std::to_string(diff) + " of " + std::to_string(n) + " bytes differ";
    }
    stbi_image_free(s);
    check(same, "png_gltf_equals_stb " + fs::path(f).filename().string(), detail);
  }
  {
    const std::string f = "tests/fuzz/regressions/png/png_zip_bomb-2c5666476c9d";
    const std::vector<unsigned char> b = slurp(f);
    std::vector<unsigned char> got;
    int w = 0, h = 0, bits = 0;
    std::string why;
    const bool ok = decode_png_rgba(b.data(), b.size(), &got, &w, &h, &bits, &why);
    check(!b.empty() && !ok && !why.empty() && got.size() <= 4 * 4 * 8, "png_gltf_zip_bomb_refused",
          b.empty() ? "cannot read " + f : ok ? "decoded" : "reason: " + why);
  }
  return unit_check::finish();
}

// tiershade tests: mutated scenes never crash (run under AddressSanitizer and UndefinedBehaviorSanitizer by
// `make test`): the shipped glTF scenes, with their numbers, strings and lines changed by a
// fixed-seed generator (a number becomes -1, 0, 1e9, 4294967296, 0.5, NaN-free extremes, a
// string, null, an array...; a string becomes another; a line is dropped, doubled or swapped;
// world_lighting also as a scene that reads its baked lightmap page from a file;
// or words of the binary buffer become NaN, Inf, huge values or indices past the end),
// go through load_scene; a scene that loads goes on through the variant selection, the draw
// preparation (lightmap bake, probes) and a 16 x 9 frame of the C fallback.
// Checks: every failure is a message naming the scene file ("<file>: <place>: <reason>"),
// later stages fail with a message too, and a frame that renders holds no NaN or Inf in its
// lit pass. The counts of each outcome are printed as INFO lines.
// Prints "PASS name" / "FAIL name: detail"; ends with "N passed, N failed".
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "families/family.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "scene/frame.h"
#include "scene/prepare.h"
#include "base/image.h"
#include "io/exr.h"
#include "unit_check.h"

namespace {

std::string read_text(const std::string &path) {
  std::string s;
  FILE *f = fopen(path.c_str(), "rb");
  if (!f) return s;
  char buf[65536];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  fclose(f);
  return s;
}

bool write_text(const std::string &path, const std::string &s) {
  FILE *f = fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = fwrite(s.data(), 1, s.size(), f) == s.size();
  return fclose(f) == 0 && ok;
}

// Token spans outside JSON strings (numbers) and string literals (with their quotes).
struct Tokens {
  std::vector<std::pair<size_t, size_t>> numbers, strings;
};
Tokens scan(const std::string &s) {
  Tokens t;
  for (size_t i = 0; i < s.size();) {
    if (s[i] == '"') {
      size_t j = i + 1;
      while (j < s.size() && s[j] != '"') j += s[j] == '\\' ? 2 : 1;
      t.strings.push_back({i, std::min(j + 1, s.size())});
      i = j + 1;
    } else if (s[i] == '-' || (s[i] >= '0' && s[i] <= '9')) {
      size_t j = i + 1;
      while (j < s.size() &&
             (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' || s[j] == 'e' || s[j] == 'E' ||
              s[j] == '+' || s[j] == '-'))
        ++j;
      t.numbers.push_back({i, j});
      i = j;
    } else {
      ++i;
    }
  }
  return t;
}

std::vector<std::string> split_lines(const std::string &s) {
  std::vector<std::string> v;
  size_t a = 0;
  while (a <= s.size()) {
    const size_t b = s.find('\n', a);
    v.push_back(s.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    a = b + 1;
  }
  return v;
}

std::string join_lines(const std::vector<std::string> &v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += v[i] + (i + 1 < v.size() ? "\n" : "");
  return s;
}

std::string mutate(const std::string &src, Rng &r) {
  static const char *const kNumbers[] = {"-1",    "0",    "1",    "2",     "3",          "7",          "-0.0",  "0.5",
                                         "1e9",   "-1e9", "1e38", "1e-38", "4294967296", "2147483648", "65536", "255",
                                         "\"x\"", "null", "[]",   "{}",    "true",       "[1,2]",      "1e308"};
  static const char *const kStrings[] = {"\"\"",
                                         "\"x\"",
                                         "\"VertexLitGeneric\"",
                                         "\"LightmappedGeneric\"",
                                         "\"textures/none.png\"",
                                         "\"../../../../etc/passwd\"",
                                         "\"spot\"",
                                         "\"directional\"",
                                         "\"float\"",
                                         "\"integer\"",
                                         "\"rgbe\"",
                                         "\"ldr\"",
                                         "3",
                                         "null",
                                         "\"VEC3\"",
                                         "\"SCALAR\"",
                                         "\"MAT4\""};
  std::string s = src;
  const Tokens t = scan(s);
  const uint32_t kind = r.next() % 10;
  if (kind < 5 && !t.numbers.empty()) {
    const auto &sp = t.numbers[r.next() % t.numbers.size()];
    return s.replace(sp.first, sp.second - sp.first, kNumbers[r.next() % (sizeof kNumbers / sizeof *kNumbers)]);
  }
  if (kind < 7 && !t.strings.empty()) {
    const auto &sp = t.strings[r.next() % t.strings.size()];
    return s.replace(sp.first, sp.second - sp.first, kStrings[r.next() % (sizeof kStrings / sizeof *kStrings)]);
  }
  std::vector<std::string> lines = split_lines(s);
  if (lines.size() < 3) return s;
  const size_t a = r.next() % lines.size(), b = r.next() % lines.size();
  if (kind == 7)
    lines.erase(lines.begin() + static_cast<long>(a));
  else if (kind == 8)
    lines.insert(lines.begin() + static_cast<long>(a), lines[a]);
  else
    std::swap(lines[a], lines[b]);
  return join_lines(lines);
}

// The buffer with 1..4 of its 4-byte words replaced (NaN, Inf, huge, negative, an index past
// the end, ...): geometry and index data as a broken exporter might write them.
std::string mutate_buffer(std::string b, Rng &r) {
  static const uint32_t kWords[] = {0x7fc00000u, 0x7f800000u, 0xff800000u, 0x7f7fffffu, 0x00000001u, 0x80000000u,
                                    0xffffffffu, 0x0000ffffu, 0x3f800000u, 0xbf800000u, 0x00000000u};
  const int n = 1 + static_cast<int>(r.next() % 4);
  for (int i = 0; i < n && b.size() >= 4; ++i) {
    const size_t at = (r.next() % (b.size() / 4)) * 4;
    const uint32_t w = kWords[r.next() % (sizeof kWords / sizeof *kWords)];
    if (r.next() % 2) {
      b[at] = static_cast<char>(w & 0xff), b[at + 1] = static_cast<char>(w >> 8 & 0xff);
      b[at + 2] = static_cast<char>(w >> 16 & 0xff), b[at + 3] = static_cast<char>(w >> 24);
    } else {  // a 16-bit index or component
      b[at] = static_cast<char>(w & 0xff), b[at + 1] = static_cast<char>(w >> 8 & 0xff);
    }
  }
  return b;
}

struct Outcome {
  int load_fail = 0, select_fail = 0, prepare_fail = 0, rendered = 0;
  int lit_nonfinite = 0;  // rendered, with a NaN or Inf in the lit frame
  std::string prepare_example;  // the first message of a preparation failure
  std::string nonfinite_example;
};

// One mutated scene through load, selection, preparation and a tiny C frame.
void run_one(const std::string &path, Outcome *o, std::string *first_bad) {
  Scene s;
  std::string err;
  if (!load_scene(path, &s, &err)) {
    ++o->load_fail;
    if (err.rfind(path + ": ", 0) != 0 && first_bad->empty()) *first_bad = "load: " + err;
    return;
  }
  SceneSelection sel;
  if (!select_scene_variants(s, Tier::SM3, "", &sel, &err)) {
    ++o->select_fail;
    if (err.empty() && first_bad->empty()) *first_bad = "selection failed without a message";
    return;
  }
  SceneRenderConfig cfg;
  cfg.backend = Backend::CPU;
  cfg.w = 16;
  cfg.h = 9;
  cfg.threads = 1;
  cfg.exposure_frames = 30;
  SceneRenderResult res;
  if (!render_scene(s, sel, cfg, &res, &err)) {
    ++o->prepare_fail;
    if (o->prepare_example.empty()) o->prepare_example = err;
    if (err.empty() && first_bad->empty()) *first_bad = "render failed without a message";
    return;
  }
  ++o->rendered;
  for (float v : res.lit.rgba)
    if (!std::isfinite(v)) {
      if (o->lit_nonfinite++ == 0) o->nonfinite_example = path;
      break;
    }
  if (res.display.size() != static_cast<size_t>(16 * 9 * 4) && first_bad->empty())
    *first_bad = path + ": display frame of " + std::to_string(res.display.size()) + " values";
}

// page_file: the scene names it in extras.tiershade.lightmaps.image (a page written by the
// baker, so that the mutants also reach the page reader and its checks).
void fuzz_scene(const std::string &dir, const char *name, int count, uint32_t seed, const char *page_file = nullptr) {
  const std::string here = "scenes/";
  std::string text = read_text(here + name);
  if (text.empty()) {
    check(false, std::string("read ") + name);
    return;
  }
  std::string label = name;
  if (page_file) {
    const std::string key = "\"lightmaps\": {";
    const size_t p = text.find(key);
    if (p == std::string::npos) {
      check(false, std::string(name) + ": no lightmaps object to name a page in");
      return;
    }
    text.insert(p + key.size(), std::string("\"image\": \"") + page_file + "\", ");
    label += " (lightmap page from " + std::string(page_file) + ")";
  }
  // The probes name ../../shared/data/probes/ relative to scenes/: point them at it from here.
  char cwd[4096];
  if (!getcwd(cwd, sizeof cwd)) cwd[0] = 0;
  const std::string from = "\"../../shared/", to = std::string("\"") + cwd + "/../shared/";
  for (size_t p = text.find(from); p != std::string::npos; p = text.find(from, p + to.size()))
    text.replace(p, from.size(), to);
  const std::string bin_name = std::string(name).substr(0, std::string(name).size() - 5) + ".bin";
  const std::string bin = read_text(here + bin_name);
  Rng r(seed);
  Outcome o;
  std::string bad;
  for (int i = 0; i < count; ++i) {
    const std::string path = dir + "/" + std::to_string(i) + "_" + name;
    std::string m, bin_path;
    if (r.next() % 5 == 0 && !bin.empty()) {  // the buffer mutated, the JSON intact
      bin_path = dir + "/" + std::to_string(i) + "_" + bin_name;
      m = text;
      const std::string uri = "\"" + bin_name + "\"";
      const size_t p = m.find(uri);
      if (p != std::string::npos) m.replace(p, uri.size(), "\"" + std::to_string(i) + "_" + bin_name + "\"");
      if (!write_text(bin_path, mutate_buffer(bin, r))) {
        check(false, "write " + bin_path);
        return;
      }
    } else {
      m = mutate(text, r);
      if (r.next() % 4 == 0) m = mutate(m, r);  // now and then two mutations
    }
    if (!write_text(path, m)) {
      check(false, "write " + path);
      return;
    }
    run_one(path, &o, &bad);
    unlink(path.c_str());
    if (!bin_path.empty()) unlink(bin_path.c_str());
  }
  printf(
      "INFO %s: %d mutants: %d refused at load, %d by the selection, %d at preparation, %d rendered "
      "(%d with a non-finite lit value)\n",
      label.c_str(), count, o.load_fail, o.select_fail, o.prepare_fail, o.rendered, o.lit_nonfinite);
  if (!o.prepare_example.empty()) printf("INFO   e.g. %s\n", o.prepare_example.c_str());
  check(bad.empty(),
        label + ": " + std::to_string(count) + " mutants load or fail with a message naming the file, none crashes",
        bad);
  check(o.lit_nonfinite == 0, label + ": no NaN or Inf in the lit frame of a mutant that renders",
        std::to_string(o.lit_nonfinite) + " frames, first " + o.nonfinite_example);
  check(o.rendered > 0 && o.load_fail > 0, label + ": the mutants reach both outcomes (the test exercises both)",
        std::to_string(o.rendered) + " rendered, " + std::to_string(o.load_fail) + " refused");
}

}  // namespace

// test_scene_fuzz [COUNT [SEED]]: more mutants, other seeds, for a longer search by hand.
int main(int argc, char **argv) {
  ts_math_init();
  const int count = argc > 1 ? std::max(1, atoi(argv[1])) : 120;
  const uint32_t seed = argc > 2 ? static_cast<uint32_t>(strtoul(argv[2], nullptr, 10)) : 0;
  char tmpl[] = "/tmp/test_scene_fuzz.XXXXXX";
  if (!mkdtemp(tmpl)) {
    check(false, "mkdtemp");
    printf("%d passed, %d failed\n", g_passed, g_failed);
    return 1;
  }
  const std::string dir = tmpl;
  // The mutants sit beside links to the scenes' buffers and textures.
  char cwd[4096];
  if (!getcwd(cwd, sizeof cwd)) cwd[0] = 0;
  for (const char *f : {"model_lighting.bin", "world_lighting.bin", "hdr_atrium.bin", "textures", "luts"}) {
    const std::string target = std::string(cwd) + "/scenes/" + f, link = dir + "/" + f;
    if (symlink(target.c_str(), link.c_str()) != 0) check(false, "symlink " + link);
  }
  fuzz_scene(dir, "world_lighting.gltf", count, seed * 3 + 1);
  fuzz_scene(dir, "model_lighting.gltf", count, seed * 3 + 2);
  fuzz_scene(dir, "hdr_atrium.gltf", count, seed * 3 + 3);
  // world_lighting reading its baked page (tiershade bake's output, written here).
  {
    Scene s;
    SceneSelection sel;
    PreparedScene ps;
    std::string err;
    ImageF page;
    if (load_scene("scenes/world_lighting.gltf", &s, &err) && select_scene_variants(s, Tier::SM3, "", &sel, &err) &&
        prepare_scene(s, sel, 16, 16, Api::GL33, 1.f, &ps, &err)) {
      page.w = ps.lightmap_w;
      page.h = ps.lightmap_h;
      page.rgba = ps.lightmap_page;
      if (write_exr(dir + "/page.exr", page, &err))
        fuzz_scene(dir, "world_lighting.gltf", count / 2, seed * 3 + 4, "page.exr");
      else
        check(false, "write the baked page", err);
    } else {
      check(false, "bake world_lighting's page", err);
    }
  }
  const std::string rm = "rm -rf '" + dir + "'";
  if (system(rm.c_str()) != 0) check(false, "remove " + dir);
  return finish();
}

// tiershade browser: the WebGL 2 demo page of a scene and its headless check (see webgl_scene.h).
#include "browser/webgl_scene.h"

#include <stdlib.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/base64.h"
#include "browser/chromium.h"
#include "io/atomic_dir.h"
#include "shaderlib/assembler.h"

using json = nlohmann::json;

namespace {

bool read_bytes(const std::string &path, std::string *out, std::string *err) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *err = path + ": cannot open";
    return false;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  *out = ss.str();
  return true;
}

bool read_json(const std::string &path, json *out, std::string *err) {
  std::string text;
  if (!read_bytes(path, &text, err)) return false;
  try {
    *out = json::parse(text);
  } catch (const std::exception &e) {
    *err = path + ": not JSON (" + e.what() + ")";
    return false;
  }
  return true;
}

// A data file of the dump as base64, checked to hold exactly `bytes` bytes.
bool data_b64(const std::string &path, size_t bytes, std::string *out, std::string *err) {
  std::string raw;
  if (!read_bytes(path, &raw, err)) return false;
  if (raw.size() != bytes) {
    *err = path + ": " + std::to_string(raw.size()) + " bytes, expected " + std::to_string(bytes);
    return false;
  }
  *out = base64_encode(raw.data(), raw.size());
  return true;
}


// The attributes the dump stores, their files and floats per vertex (docs/bundles.md).
struct AttrFile {
  const char *name, *key;
  int size;
};
const AttrFile kAttrs[] = {{"a_position", "position_file", 3}, {"a_normal", "normal_file", 3}, {"a_uv", "uv_file", 2},
                           {"a_tangent", "tangent_file", 4},   {"a_lightmap", "lightmap_file", 4}};

}  // namespace

bool webgl_scene_write_page(const std::string &bundle_dir, const std::string &dump_dir, const std::string &dir,
                            WebScenePage *info, std::string *err) {
  json man, dump;
  const std::string mpath = bundle_dir + "/manifest.json", dpath = dump_dir + "/draws.json";
  if (!read_json(mpath, &man, err) || !read_json(dpath, &dump, err)) return false;
  std::string html, js;
  if (!shader_library_read("glue/browser/webgl_scene.html", &html) ||
      !shader_library_read("glue/browser/webgl_scene.js", &js)) {
    *err = "the demo page (glue/browser/webgl_scene.html, .js) is not in this binary";
    return false;
  }
  json scene;
  std::string where = mpath;
  try {
    if (man.at("target").get<std::string>() != "essl300") {
      *err = mpath + ": target " + man.at("target").get<std::string>() +
             ": the demo page is WebGL 2 (write the bundle with --target essl300)";
      return false;
    }
    where = dpath;
    if (!dump.contains("camera")) {
      *err = dpath + ": no camera (a dump of an older tiershade render: render the scene again with --dump-draws)";
      return false;
    }
    info->w = dump.at("width").get<int>();
    info->h = dump.at("height").get<int>();
    scene["width"] = info->w;
    scene["height"] = info->h;
    scene["clear"] = dump.at("clear");
    scene["camera"] = dump.at("camera");
    scene["programs"] = json::array();
    scene["textures"] = json::array();
    scene["draws"] = json::array();
    std::map<std::string, int> program_of, texture_of;
    const json &vars = man.at("variants");
    const json &draws = dump.at("draws");
    for (size_t i = 0; i < draws.size(); ++i) {
      const json &d = draws[i];
      where = dpath + ": draws[" + std::to_string(i) + "]";
      const std::string shader = d.at("shader").get<std::string>(), variant = d.at("variant").get<std::string>();
      const std::string key = shader + "|" + variant;
      const json *v = nullptr;
      for (const json &x : vars)
        if (x.at("shader").get<std::string>() == shader && x.at("name").get<std::string>() == variant) v = &x;
      if (!v) {
        *err = where + ": " + shader + " " + variant + " is not in the bundle " + mpath;
        return false;
      }
      if (!program_of.count(key)) {
        json p;
        p["shader"] = shader;
        p["variant"] = variant;
        std::string vs, fs;
        if (!read_bytes(bundle_dir + "/" + v->at("vertex").get<std::string>(), &vs, err) ||
            !read_bytes(bundle_dir + "/" + v->at("fragment").get<std::string>(), &fs, err))
          return false;
        p["vs"] = vs;
        p["fs"] = fs;
        p["attributes"] = json::array();
        for (const json &a : v->at("attributes")) p["attributes"].push_back(a.at("name"));
        p["samplers"] = json::array();
        for (const json &s : v->at("samplers")) p["samplers"].push_back(s.at("name"));
        // What the draw writes: linear (OUTPUT_MODE 0, or a family without display encoding) or
        // display-encoded (OUTPUT_MODE 1 gamma 2.2, 2 sRGB): the page's display pass encodes the first.
        const json &defs = v->at("defines");
        p["linear_output"] = !defs.contains("OUTPUT_MODE") || defs.at("OUTPUT_MODE").get<int>() == 0;
        program_of[key] = static_cast<int>(scene["programs"].size());
        scene["programs"].push_back(p);
      }
      const int prog = program_of[key];
      const size_t nv = d.at("vertices").get<size_t>(), ni = d.at("indices").get<size_t>();
      json jd;
      jd["program"] = prog;
      jd["count"] = ni;
      jd["arrays"] = json::object();
      for (const json &an : scene["programs"][prog]["attributes"]) {
        const std::string name = an.get<std::string>();
        const AttrFile *af = nullptr;
        for (const auto &x : kAttrs)
          if (name == x.name) af = &x;
        if (!af || d.at(af->key).is_null()) {
          *err = where + ": the program reads " + name + " but the dump has no array for it";
          return false;
        }
        std::string b64;
        if (!data_b64(dump_dir + "/" + d.at(af->key).get<std::string>(), nv * af->size * 4, &b64, err)) return false;
        jd["arrays"][name] = {{"size", af->size}, {"data", b64}};
      }
      std::string ib64;
      if (!data_b64(dump_dir + "/" + d.at("index_file").get<std::string>(), ni * 4, &ib64, err)) return false;
      jd["index"] = ib64;
      jd["uniforms"] = json::array();
      for (const json &u : d.at("uniforms")) {
        // The float32 bits, exactly as the shader saw them (NaN-safe): the page sets them as they are.
        std::vector<uint32_t> bits = u.at("bits").get<std::vector<uint32_t>>();
        jd["uniforms"].push_back({{"name", u.at("name")},
                                  {"type", u.at("type")},
                                  {"array_size", u.at("array_size")},
                                  {"data", base64_encode(bits.data(), bits.size() * 4)}});
      }
      jd["textures"] = json::array();
      for (const json &t : d.at("textures")) {
        const std::string file = t.at("file").get<std::string>(), kind = t.at("kind").get<std::string>();
        if (kind == "3d") {
          *err = where + ": texture " + t.at("sampler").get<std::string>() + ": 3D textures are not replayed by the page";
          return false;
        }
        // A texture is its level 0 and its mip chain (docs/rendering.md "Mipmaps"): one page entry each.
        const json no_levels = json::array();
        const json &levels = t.contains("levels") ? t.at("levels") : no_levels;
        std::string key = file;
        for (const json &l : levels) key += "|" + l.get<std::string>();
        if (!texture_of.count(key)) {
          const size_t w = t.at("w").get<size_t>(), h = t.at("h").get<size_t>();
          const size_t texels = kind == "cube" ? w * w * 6 : w * h;
          std::string b64;
          if (!data_b64(dump_dir + "/" + file, texels * 16, &b64, err)) return false;
          json lv = json::array();
          for (size_t k = 0; k < levels.size(); ++k) {
            const size_t lw = std::max<size_t>(1, w >> (k + 1)), lh = std::max<size_t>(1, h >> (k + 1));
            std::string lb64;
            if (k >= 30 || !data_b64(dump_dir + "/" + levels[k].get<std::string>(), lw * lh * 16, &lb64, err)) {
              if (err->empty()) *err = where + ": texture " + t.at("sampler").get<std::string>() + ": too many levels";
              return false;
            }
            lv.push_back(lb64);
          }
          texture_of[key] = static_cast<int>(scene["textures"].size());
          scene["textures"].push_back({{"kind", kind}, {"w", w}, {"h", h}, {"data", b64}, {"levels", lv}});
        }
        jd["textures"].push_back({{"sampler", t.at("sampler")},
                                  {"texture", texture_of[key]},
                                  {"linear", t.at("linear")},
                                  {"repeat", t.at("repeat")},
                                  {"mip_filter", t.contains("mip_filter") ? t.at("mip_filter") : json("none")}});
      }
      scene["draws"].push_back(jd);
    }
    info->programs = program_of.size();
    info->draws = draws.size();
    info->textures = texture_of.size();
  } catch (const std::exception &e) {
    *err = where + ": " + e.what();
    return false;
  }
  const std::string scene_js = "var TS_SCENE = " + scene.dump() + ";\n";
  info->bytes = scene_js.size();
  DirWriter w;
  return w.begin(dir, "scene.js", "demo page", err) && w.write("index.html", html, err) &&
         w.write("webgl_scene.js", js, err) && w.write("scene.js", scene_js, err) && w.commit(err);
}


bool webgl_scene_check(const std::string &dir, const std::string &dump_dir, int timeout_s,
                       const WebSceneTolerance &tol, WebSceneCheck *out, std::string *err) {
  std::string html, js, scene_js;
  if (!read_bytes(dir + "/index.html", &html, err) || !read_bytes(dir + "/webgl_scene.js", &js, err) ||
      !read_bytes(dir + "/scene.js", &scene_js, err))
    return false;
  json dump;
  if (!read_json(dump_dir + "/draws.json", &dump, err)) return false;
  int w = 0, h = 0;
  std::string frame_file;
  try {
    w = dump.at("width").get<int>();
    h = dump.at("height").get<int>();
    frame_file = dump.at("frame_file").get<std::string>();
  } catch (const std::exception &e) {
    *err = dump_dir + "/draws.json: " + e.what();
    return false;
  }
  std::string frame;
  const size_t n = static_cast<size_t>(w) * h * 4;
  if (!read_bytes(dump_dir + "/" + frame_file, &frame, err)) return false;
  if (frame.size() != n * 4) {
    *err = dump_dir + "/" + frame_file + ": " + std::to_string(frame.size()) + " bytes for a " + std::to_string(w) + "x" +
           std::to_string(h) + " RGBA32F frame";
    return false;
  }
  std::string text;
  if (!chromium_run_page({{"index.html", html}, {"webgl_scene.js", js}, {"scene.js", scene_js}}, "index.html?check",
                         timeout_s, &text, err))
    return false;
  std::vector<uint8_t> px;
  bool done = false;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line == "DONE") {
      done = true;
    } else if (line.compare(0, 2, "I ") == 0) {
      out->renderer = line.substr(2);
    } else if (line.compare(0, 2, "X ") == 0) {
      *err = "the demo page failed: " + line.substr(2);
      return false;
    } else if (line.compare(0, 3, "VP ") == 0) {
      if (sscanf(line.c_str() + 3, "%d %d", &out->view_proj_differ, &out->view_proj_compared) != 2) {
        *err = "the demo page wrote a malformed line: " + line.substr(0, 80);
        return false;
      }
    } else if (line.compare(0, 2, "F ") == 0) {
      if (!base64_decode(line.substr(2), &px) || px.size() != n * 4) {
        *err = "the demo page returned " + std::to_string(px.size()) + " bytes for a " + std::to_string(w) + "x" +
               std::to_string(h) + " RGBA32F frame";
        return false;
      }
    }
  }
  if (!done || px.empty()) {
    *err = "the demo page did not run to its end (no frame or no DONE line)";
    return false;
  }
  const float *a = reinterpret_cast<const float *>(px.data());  // browser
  const float *b = reinterpret_cast<const float *>(frame.data());  // llvmpipe
  std::vector<double> diffs(static_cast<size_t>(w) * h);
  out->pixels = diffs.size();
  for (size_t p = 0; p < diffs.size(); ++p) {
    double d = 0;
    bool equal = true, within = true;
    for (int c = 0; c < 4; ++c) {
      const float x = a[p * 4 + c], y = b[p * 4 + c];
      if (memcmp(&x, &y, 4) != 0) equal = false;
      const double e = std::isnan(x) || std::isnan(y) ? (std::isnan(x) && std::isnan(y) ? 0 : INFINITY)
                                                      : std::fabs(static_cast<double>(x) - y);
      d = std::max(d, e);
      if (!(e <= tol.abs + tol.rel * std::fabs(static_cast<double>(y)))) within = false;
    }
    diffs[p] = d;
    out->equal += equal;
    out->within += within;
    if (d > out->max_diff || p == 0) {
      out->max_diff = d;
      out->worst_x = static_cast<int>(p % static_cast<size_t>(w));
      out->worst_y = static_cast<int>(p / static_cast<size_t>(w));
    }
  }
  std::vector<double> sorted = diffs;
  std::sort(sorted.begin(), sorted.end());
  out->median_diff = sorted[sorted.size() / 2];
  out->p99_diff = sorted[std::min(sorted.size() - 1, sorted.size() * 99 / 100)];
  out->pass = out->view_proj_differ == 0 && out->view_proj_compared > 0 &&
              static_cast<double>(out->pixels - out->within) <= tol.share * static_cast<double>(out->pixels);
  return true;
}

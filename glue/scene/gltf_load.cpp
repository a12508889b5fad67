// tiershade scene: load_scene (glue/scene/scene.h): a glTF 2.0 file (.gltf or .glb) read with
// tinygltf, checked (JSON syntax and finite numbers, external files, accessors, indices), and
// flattened to world-space triangles, cameras and lights. Accessors, meshes and node transforms:
// gltf_nodes.cpp; materials: gltf_source_material.cpp; lights and tiershade extras: gltf_extras.cpp.
// Format: docs/scenes.md.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stb_image.h>

#include "base/image.h"
#include "io/memory_limit.h"
#include "io/png.h"
#include "scene/gltf_util.h"

namespace scene_gltf {
namespace {

using tinygltf::Model;

// ---------------------------------------------------------------- file & JSON checks ---

bool read_file(const std::string &path, std::vector<unsigned char> *out, Err &e) {
  std::string why;
  long long size = 0;
  if (!regular_file_within(path, kMaxSceneFileBytes, &size, &why) ||
      !memory_fits(2.0 * static_cast<double>(size), "the scene file", &why))
    return e.fail("", why);
  std::ifstream f(path, std::ios::binary);
  if (!f) return e.fail("", "cannot open the file");
  out->assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  if (f.bad()) return e.fail("", "read error");
  if (static_cast<long long>(out->size()) > kMaxSceneFileBytes) return e.fail("", "the file grew while it was read");
  return true;
}

// The JSON chunk of a .glb (header and chunk bounds checked).
bool glb_json(const std::vector<unsigned char> &b, std::string *json, Err &e) {
  if (b.size() < 20) return e.fail("GLB header", "file is " + std::to_string(b.size()) + " bytes, too short");
  if (memcmp(b.data(), "glTF", 4) != 0) return e.fail("GLB header", "bad magic (expected \"glTF\")");
  if (le32(&b[4]) != 2) return e.fail("GLB header", "version " + std::to_string(le32(&b[4])) + ", expected 2");
  if (le32(&b[8]) > b.size()) return e.fail("GLB header", "length field exceeds the file size");
  const uint32_t len = le32(&b[12]);
  if (le32(&b[16]) != 0x4E4F534Au) return e.fail("GLB chunk 0", "the first chunk is not JSON");
  if (len > b.size() - 20) return e.fail("GLB chunk 0", "chunk length exceeds the file");
  json->assign(reinterpret_cast<const char *>(&b[20]), len);
  return true;
}

// JSON number tokens outside strings that overflow a double (nlohmann reports them without
// a position), and arrays and objects nested deeper than kMaxJsonDepth (tinygltf converts
// values recursively: 20,000 levels overflow its stack).
bool check_number_tokens(const std::string &s, Err &e) {
  int line = 1, col = 1, depth = 0;
  bool in_str = false;
  for (size_t i = 0; i < s.size(); ++i, ++col) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      col = 0;
      continue;
    }
    if (in_str) {
      if (c == '\\')
        ++i, ++col;
      else if (c == '"')
        in_str = false;
      continue;
    }
    if (c == '"') {
      in_str = true;
      continue;
    }
    if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        return e.fail("line " + std::to_string(line) + ", column " + std::to_string(col),
                      "arrays and objects nested more than " + std::to_string(kMaxJsonDepth) + " deep");
      continue;
    }
    if (c == ']' || c == '}') {
      --depth;
      continue;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      size_t j = i;
      while (j < s.size() && strchr("+-.eE0123456789", s[j])) ++j;
      const std::string tok = s.substr(i, j - i);
      const double x = strtod(tok.c_str(), nullptr);
      if (!std::isfinite(x))
        return e.fail("line " + std::to_string(line) + ", column " + std::to_string(col),
                      "number " + tok + " is not finite");
      col += static_cast<int>(j - i) - 1;
      i = j - 1;
    }
  }
  return true;
}

std::string url_decode(const std::string &s) {
  std::string o;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && isxdigit(static_cast<unsigned char>(s[i + 1])) &&
        isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      o += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      o += s[i];
    }
  }
  return o;
}

// Syntax, then the external buffers and images the document names (tinygltf's own messages
// do not say which one is missing).
bool precheck_json(const std::string &text, const std::string &dir, Err &e) {
  if (!check_number_tokens(text, e)) return false;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception &ex) {
    std::string w = ex.what();
    const size_t p = w.find("] ");
    if (w.rfind("[json.exception", 0) == 0 && p != std::string::npos) w = w.substr(p + 2);
    return e.fail("JSON", w);
  }
  if (!j.is_object()) return e.fail("JSON", "the root is not an object");
  for (const char *kind : {"buffers", "images"}) {
    auto it = j.find(kind);
    if (it == j.end() || !it->is_array()) continue;
    for (size_t i = 0; i < it->size(); ++i) {
      const auto &o = (*it)[i];
      const std::string place = std::string(kind) + "[" + std::to_string(i) + "]";
      if (!o.is_object() || !o.contains("uri") || !o["uri"].is_string()) continue;
      const std::string uri = o["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      const std::string file = join_path(dir, url_decode(uri));
      long long size = 0;
      if (!file_exists(file, &size)) return e.fail(place, missing_file(file));
      std::string why;
      if (!memory_fits(static_cast<double>(size), "the file " + file, &why)) return e.fail(place, why);
      if (kind[0] == 'b' && o.contains("byteLength") && o["byteLength"].is_number()) {
        const double want = o["byteLength"].get<double>();
        if (static_cast<double>(size) != want)
          return e.fail(place,
                        "file " + file + " has " + std::to_string(size) + " bytes, byteLength is " +
                            std::to_string(static_cast<long long>(want)));
      }
    }
  }
  return true;
}

std::string trim_tinygltf(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (char &c : s)
    if (c == '\n') c = ';';
  return s;
}

// Every accessor against its bufferView (count x stride within byteLength) and the memory
// limit, before any accessor is read: gltf_nodes.cpp allocates count x components doubles.
bool check_accessors(const Model &m, Err &e) {
  double total = 0;
  for (size_t i = 0; i < m.accessors.size(); ++i) {
    const tinygltf::Accessor &a = m.accessors[i];
    const std::string place = named("accessors[" + std::to_string(i) + "]", a.name);
    const int nc = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    const int cs = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    if (nc <= 0 || cs <= 0) continue;  // gltf_nodes.cpp names the bad type where it is used
    if (a.count > kMaxAccessorElements)
      return e.fail(place, "count " + std::to_string(a.count) + " is more than the limit of " +
                               std::to_string(kMaxAccessorElements) + " elements");
    total += 8.0 * static_cast<double>(a.count) * nc;
    std::string why;
    if (!memory_fits(total, "the accessors up to " + place, &why)) return e.fail(place, why);
    if (a.bufferView < 0 || a.count == 0 || a.sparse.isSparse) continue;
    if (static_cast<size_t>(a.bufferView) >= m.bufferViews.size())
      return e.fail(place, "bufferView " + std::to_string(a.bufferView) + " does not exist");
    const tinygltf::BufferView &bv = m.bufferViews[a.bufferView];
    const size_t elem = static_cast<size_t>(nc) * cs;
    const size_t stride = bv.byteStride >= elem ? bv.byteStride : elem;
    const double need = static_cast<double>(a.byteOffset) + static_cast<double>(a.count - 1) * stride + elem;
    // Small overruns are left to gltf_nodes.cpp, which names the use (and a wrong type first).
    if (need > static_cast<double>(bv.byteLength) && need > 1048576.0)
      return e.fail(place, "byteOffset " + std::to_string(a.byteOffset) + " + " + std::to_string(a.count) + " x " +
                               std::to_string(stride) + " bytes needs " + std::to_string(static_cast<long long>(need)) +
                               " bytes, bufferViews[" + std::to_string(a.bufferView) + "] has " +
                               std::to_string(bv.byteLength));
  }
  return true;
}

// tinygltf's image callback (SetImageLoader): PNG through libpng (io/png.h decode_png_rgba: the size
// from the header checked against the limits before any pixel is allocated, and no inflate past
// the rows, where stb_image grew its buffer without bound on a zip-bomb IDAT), JPEG through stb_image
// as before (its size from stbi_info checked first); any other format is refused. Pixels as
// tinygltf's own loader gave them: RGBA, 8 or 16 bits (little-endian). A failure names the image
// and its file (or its bufferView / data URI).
struct ImageLoad {
  std::string dir;
  std::string error;  // the first failure, "images[i] (file): reason"
};

bool load_image(tinygltf::Image *im, const int idx, std::string *err, std::string *warn, int req_w, int req_h,
                const unsigned char *bytes, int size, void *user) {
  ImageLoad &ctx = *static_cast<ImageLoad *>(user);
  const std::string src = !im->uri.empty()        ? join_path(ctx.dir, url_decode(im->uri))
      : im->bufferView >= 0                       ? "bufferView " + std::to_string(im->bufferView)
                                                  : "a data URI";
  const std::string place = named("images[" + std::to_string(idx) + "]", im->name) + " (" + src + ")";
  auto fail = [&](const std::string &why) {
    if (ctx.error.empty()) ctx.error = place + ": " + why;
    if (err) *err += ctx.error + "\n";
    return false;
  };
  const size_t n = size > 0 ? static_cast<size_t>(size) : 0;
  if (is_png(bytes, n)) {
    std::vector<unsigned char> px;
    int w = 0, h = 0, bits = 8;
    std::string why;
    if (!decode_png_rgba(bytes, n, &px, &w, &h, &bits, &why)) return fail("cannot decode the image (libpng: " + why + ")");
    if ((req_w > 0 && req_w != w) || (req_h > 0 && req_h != h)) return fail("the image is not of the size required");
    im->width = w;
    im->height = h;
    im->component = 4;
    im->bits = bits;
    im->pixel_type = bits == 16 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    im->image = std::move(px);
    return true;
  }
  int w = 0, h = 0, comp = 0;
  if (n < 3 || bytes[0] != 0xFF || bytes[1] != 0xD8 || bytes[2] != 0xFF || !stbi_info_from_memory(bytes, size, &w, &h, &comp)) {
    const char *r = n >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 ? stbi_failure_reason() : "neither PNG nor JPEG signature";
    return fail(std::string("not a PNG or JPEG image (") + (r ? r : "unknown format") + ")");
  }
  if (w < 1 || h < 1 || static_cast<long long>(w) * h > kMaxImagePixels)
    return fail(std::to_string(w) + " x " + std::to_string(h) + " pixels (at most " + std::to_string(kMaxImagePixels) +
                " pixels)");
  std::string why;
  const double px = static_cast<double>(w) * h;  // stb's 4 channels (8 bits) and the float copy
  if (!memory_fits(px * (8 + 16), "a " + std::to_string(w) + " x " + std::to_string(h) + " image", &why))
    return fail(why);
  std::string terr;
  if (!tinygltf::LoadImageData(im, idx, &terr, warn, req_w, req_h, bytes, size, nullptr)) {
    const char *r = stbi_failure_reason();
    return fail(std::string("cannot decode the image (stb_image: ") + (r ? r : "JPEG decoding failed") + ")");
  }
  return true;
}

// ------------------------------------------------------------------------- images ---

bool convert_images(const Model &m, const std::string &path, const std::string &dir, Scene *s, Err &e) {
  for (size_t i = 0; i < m.images.size(); ++i) {
    const tinygltf::Image &im = m.images[i];
    const std::string place = named("images[" + std::to_string(i) + "]", im.name);
    SceneImage out;
    out.path = im.uri.empty() || im.uri.rfind("data:", 0) == 0 ? path + "#images[" + std::to_string(i) + "]"
                                                               : join_path(dir, url_decode(im.uri));
    const int bytes = im.bits == 16 ? 2 : 1;
    if (im.image.empty() || im.width < 1 || im.height < 1 || (im.bits != 8 && im.bits != 16) || im.component < 1 ||
        im.component > 4)
      return e.fail(place, "no decodable PNG/JPEG pixels (" + out.path + ")");
    const size_t w = static_cast<size_t>(im.width), h = static_cast<size_t>(im.height);
    const size_t nc = static_cast<size_t>(im.component);
    if (im.image.size() < w * h * nc * bytes) return e.fail(place, "pixel data shorter than its size");
    out.w = im.width;
    out.h = im.height;
    out.rgba.assign(w * h * 4, 1.f);
    const float scale = bytes == 2 ? 1.f / 65535.f : 1.f / 255.f;
    for (size_t y = 0; y < h; ++y)
      for (size_t x = 0; x < w; ++x)
        for (size_t c = 0; c < nc; ++c) {
          const size_t k = ((h - 1 - y) * w + x) * nc + c;  // file row h-1-y is our row y
          const unsigned code = bytes == 2 ? (im.image[2 * k] | im.image[2 * k + 1] << 8) : im.image[k];
          const float v = static_cast<float>(code) * scale;
          float *px = &out.rgba[(y * w + x) * 4];
          if (nc <= 2) {  // grey (+ alpha)
            if (c == 0)
              px[0] = px[1] = px[2] = v;
            else
              px[3] = v;
          } else {
            px[c] = v;
          }
        }
    s->images.push_back(std::move(out));
  }
  return true;
}

bool load(const std::string &path, Scene *s, Err &e) {
  std::vector<unsigned char> bytes;
  if (!read_file(path, &bytes, e)) return false;
  const std::string dir = dir_of(path);
  const bool glb = (path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0) ||
      (bytes.size() >= 4 && memcmp(bytes.data(), "glTF", 4) == 0);
  std::string json;
  if (glb) {
    if (!glb_json(bytes, &json, e)) return false;
  } else {
    json.assign(bytes.begin(), bytes.end());
  }
  if (!precheck_json(json, dir, e)) return false;
  if (bytes.size() > 0xFFFFFFFFu) return e.fail("", "file too large");
  Model m;
  tinygltf::TinyGLTF loader;
  ImageLoad images{dir, ""};
  loader.SetImageLoader(load_image, &images);
  std::string terr, twarn;
  const bool ok = glb
      ? loader.LoadBinaryFromMemory(&m, &terr, &twarn, bytes.data(), static_cast<unsigned>(bytes.size()), dir)
      : loader.LoadASCIIFromString(&m, &terr, &twarn, json.data(), static_cast<unsigned>(json.size()), dir);
  if (!ok && !images.error.empty()) return e.fail("", images.error);
  if (!ok) return e.fail("glTF", trim_tinygltf(terr.empty() ? "tinygltf could not load the file" : terr));
  s->path = path;
  if (!check_accessors(m, e) || !convert_images(m, path, dir, s, e) || !convert_materials(m, s, e) ||
      !convert_nodes(m, s, e))
    return false;
  for (ScenePrimitive &p : s->primitives)
    if (p.material < 0) {  // glTF's default material: a plain VertexLitGeneric one
      if (s->materials.empty() || s->materials.back().where != "default material") {
        SceneMaterial d;
        d.name = "default";
        d.where = "default material";
        s->materials.push_back(d);
      }
      p.material = static_cast<int>(s->materials.size()) - 1;
    }
  if (s->primitives.empty()) return e.fail("scene", "no triangles (a scene needs at least one mesh primitive)");
  if (s->cameras.empty()) return e.fail("scene", "no camera (a scene needs a node with a camera)");
  return convert_tiershade_extras(m, dir, s, e);
}

}  // namespace
}  // namespace scene_gltf

bool load_scene(const std::string &path, Scene *out, std::string *err) {
  scene_gltf::Err e;
  e.file = path;
  Scene s;
  bool ok = false;
  try {
    ok = scene_gltf::load(path, &s, e);
  } catch (const std::exception &ex) {
    e.fail("", std::string("unexpected error: ") + ex.what());
    ok = false;
  }
  if (!ok) {
    if (err) *err = e.msg.empty() ? path + ": could not load the scene" : e.msg;
    return false;
  }
  *out = std::move(s);
  return true;
}

// tiershade fuzz: a lightmap page file (extras.tiershade.lightmaps.image, docs/scenes.md "Lightmap
// pages"): any bytes as the page (.exr or .hdr by the magic) of a fixed one-triangle scene, loaded
// with load_scene, which reads the page and checks its size and texels.
#include <cstring>

#include "fuzz_util.h"
#include "scene/scene.h"

namespace {
// One triangle, a camera and lightmap settings naming the page; its buffer is a data URI.
const char kScene[] =
    R"J({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}], "nodes": [{"mesh": 0, ")J"
    R"J(extras": {"note": [1, [2, [3]]]}}, {"camera": 0, "translation": [0.3, 0.3, 2]}], "cameras": [{"t)J"
    R"J(ype": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 10, "aspectRatio": 1.5}})J"
    R"J(], "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "ind)J"
    R"J(ices": 3, "material": 0}]}], "materials": [{"name": "m", "pbrMetallicRoughness": {"baseColorFact)J"
    R"J(or": [0.7, 0.7, 0.7, 1]}}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, ")J"
    R"J(type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}, {"bufferView": 1, "componentType": 5126, "co)J"
    R"J(unt": 3, "type": "VEC3"}, {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}, )J"
    R"J({"bufferView": 3, "componentType": 5123, "count": 3, "type": "SCALAR"}], "bufferViews": [{"buffe)J"
    R"J(r": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}, {")J"
    R"J(buffer": 0, "byteOffset": 72, "byteLength": 24}, {"buffer": 0, "byteOffset": 96, "byteLength": 6)J"
    R"J(}], "buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAA)J"
    R"J(AAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AA)J"
    R"J(ABAAIAAAA=", "byteLength": 104}], "extras": {"tiershade": {"camera": 0, "probes": [{"name": "p",)J"
    R"J( "position": [0, 0, 0], "size": 8}], "ambient": [{"position": [0, 0, 0], "cube": [[0.1, 0.1, 0.1)J"
    R"J(], [0.1, 0.1, 0.1], [0.1, 0.1, 0.1], [0.1, 0.1, 0.1], [0.1, 0.1, 0.1], [0.1, 0.1, 0.1]]}], "hdr")J"
    R"J(: {"path": "integer", "tone_map_scale": 1.0}, "lightmaps": {"luxels_per_unit": 4, "encoding": "f)J"
    R"J(loat", "image": "page.exr"}, "fog": {"color": [0.1, 0.1, 0.1], "start": 1, "end": 5}}}})J";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const uint8_t exr_magic[4] = {0x76, 0x2f, 0x31, 0x01};
  const bool exr = size >= 4 && std::memcmp(data, exr_magic, 4) == 0;
  static const std::string exr_scene = fuzz::write_text("page_exr.gltf", kScene);
  static const std::string hdr_scene = [] {
    std::string s = kScene;
    s.replace(s.find("page.exr"), 8, "page.hdr");
    return fuzz::write_text("page_hdr.gltf", s);
  }();
  fuzz::write_file(exr ? "page.exr" : "page.hdr", data, size);
  Scene s;
  std::string err;
  load_scene(exr ? exr_scene : hdr_scene, &s, &err);
  return 0;
}

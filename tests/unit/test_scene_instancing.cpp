// tiershade tests: instances of one mesh share their geometry (glue/scene/gltf_nodes.cpp,
// glue/scene/draw_geometry.cpp; docs/rendering.md, "Scenes of real size"). glTF files written here:
//   - one mesh under N and under 4N nodes: the loaded scene's geometry bytes and the prepared
//     scene's (PreparedScene::geometry_bytes) are the same for both, every draw of the mesh binds
//     the one DrawGeometry and carries its node's translation as u_model; flattened (every
//     instance in world space, as before) the prepared bytes grow 4x;
//   - a mesh under one node, and a scaled or a mirrored node: flattened to world space (the
//     shaders' u_model carries rigid transforms only);
//   - the C fallback's frame of the shared scene equals, bit for bit, that of the same scene
//     flattened (positions on a 1/8 grid and integer translations: the float transform is exact).
// Sizes are tiny (a 6-vertex mesh, 48 x 32 frames): a fraction of a second, also under ASan.
// Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "scene/cpu_renderer.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"
#include "unit_check.h"

namespace {


std::string g_dir;

std::string base64(const std::string &in) {
  static const char *t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string o;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= static_cast<unsigned char>(in[i + 2]);
    o += t[v >> 18 & 63];
    o += t[v >> 12 & 63];
    o += i + 1 < in.size() ? t[v >> 6 & 63] : '=';
    o += i + 2 < in.size() ? t[v & 63] : '=';
  }
  return o;
}

// A closed 6-vertex, 8-triangle mesh within 0.75 of its origin (positions on a 1/8 grid), 6 normals
// with no zero component, 24 uint16 indices.
std::string mesh_bin() {
  const float r = 0.75f;
  const float p[18] = {r, 0, 0, 0, r, 0, 0, 0, r, 0.25f, -r, 0.125f, 0.125f, 0.25f, -r, -r, 0.25f, 0.125f};
  const float n[18] = {0.48f, 0.6f, 0.64f, 0.6f, 0.64f, 0.48f, 0.64f, 0.48f, 0.6f,
                       0.48f, -0.6f, 0.64f, 0.6f, 0.64f, -0.48f, -0.64f, 0.48f, 0.6f};
  const uint16_t ix[24] = {0, 1, 2, 1, 5, 2, 5, 3, 2, 3, 0, 2, 1, 0, 4, 5, 1, 4, 3, 5, 4, 0, 3, 4};
  std::string b(reinterpret_cast<const char *>(p), sizeof p);
  b.append(reinterpret_cast<const char *>(n), sizeof n);
  b.append(reinterpret_cast<const char *>(ix), sizeof ix);
  return b;
}

// A scene of mesh 0 under the given nodes (JSON objects without the "mesh" key) and a camera at
// z = 14 looking down -Z.
std::string scene_json(const std::vector<std::string> &nodes) {
  std::string ns, roots;
  for (size_t i = 0; i < nodes.size(); ++i) {
    ns += "{\"mesh\":0," + nodes[i] + "},";
    roots += std::to_string(i) + ",";
  }
  ns += "{\"camera\":0,\"translation\":[0,0,14]}";
  roots += std::to_string(nodes.size());
  const std::string bin = mesh_bin();
  return "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[" + roots + "]}],\"nodes\":[" + ns +
      "],\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.5,\"zfar\":100}}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":2,\"material\":0}]}],"
      "\"materials\":[{\"name\":\"mat\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.6,0.4,1]},"
      "\"extras\":{\"source\":{\"shader\":\"VertexLitGeneric\"}}}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":6,\"type\":\"VEC3\",\"min\":[-0.75,-0.75,-0.75],"
      "\"max\":[0.75,0.75,0.75]},{\"bufferView\":1,\"componentType\":5126,\"count\":6,\"type\":\"VEC3\"},"
      "{\"bufferView\":2,\"componentType\":5123,\"count\":24,\"type\":\"SCALAR\"}],"
      "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":72},{\"buffer\":0,\"byteOffset\":72,"
      "\"byteLength\":72},{\"buffer\":0,\"byteOffset\":144,\"byteLength\":48}],"
      "\"buffers\":[{\"uri\":\"data:application/octet-stream;base64," +
      base64(bin) + "\",\"byteLength\":" + std::to_string(bin.size()) + "}]}";
}

// `count` nodes on a grid of spacing 2 (integer translations), within the camera's view.
std::vector<std::string> grid_nodes(int count) {
  std::vector<std::string> out;
  const int cols = count <= 4 ? 2 : 4;
  for (int i = 0; i < count; ++i) {
    const int x = (i % cols) * 2 - cols + 1, y = (i / cols) * 2 - 3;
    out.push_back("\"translation\":[" + std::to_string(x) + "," + std::to_string(y) + ",0]");
  }
  return out;
}

bool load_json(const std::string &name, const std::string &json, Scene *s) {
  const std::string path = g_dir + "/" + name;
  FILE *f = fopen(path.c_str(), "wb");
  if (!f) return false;
  fwrite(json.data(), 1, json.size(), f);
  fclose(f);
  std::string err;
  if (!load_scene(path, s, &err)) {
    check(false, "load " + name, err);
    return false;
  }
  // Two point lights (1/d^2): the draws are lit, each with its own choice.
  for (int k = 0; k < 2; ++k) {
    SceneLight l;
    l.name = "lamp_" + std::to_string(k);
    l.light = ts_light{};
    l.light.type = TS_LIGHT_POINT;
    l.light.color[0] = l.light.color[1] = l.light.color[2] = 30.f;
    l.light.pos[0] = k ? 3.f : -3.f;
    l.light.pos[1] = 1.f;
    l.light.pos[2] = 4.f;
    l.light.atten[2] = 1;
    s->lights.push_back(l);
  }
  return true;
}

bool prepare(const Scene &s, SceneSelection *sel, PreparedScene *p) {
  std::string err;
  if (!select_scene_variants(s, Tier::SM3, "", sel, &err) || !prepare_scene(s, *sel, 48, 32, Api::GL33, 1.f, p, &err)) {
    check(false, "prepare " + s.path, err);
    return false;
  }
  return true;
}

Scene flattened(const Scene &s) {
  Scene f = s;
  for (size_t i = 0; i < s.primitives.size(); ++i) f.primitives[i] = scene_flattened(s, s.primitives[i]);
  return f;
}

void test_shared_bytes() {
  const int n = 4;
  Scene a, b;
  if (!load_json("n.gltf", scene_json(grid_nodes(n)), &a) || !load_json("4n.gltf", scene_json(grid_nodes(4 * n)), &b))
    return;
  bool shared = a.primitives.size() == static_cast<size_t>(n) && b.primitives.size() == static_cast<size_t>(4 * n);
  for (const ScenePrimitive &p : b.primitives)
    shared = shared && p.shared && p.shared == b.primitives[0].shared && p.position.empty();
  check(shared, "instancing: the 4N nodes of one mesh share one object-space geometry");
  check(scene_geometry_bytes(a) == scene_geometry_bytes(b) && scene_geometry_bytes(a) > 0,
        "instancing: scene geometry bytes N = 4N",
        std::to_string(scene_geometry_bytes(a)) + " vs " + std::to_string(scene_geometry_bytes(b)));
  SceneSelection sa, sb, sf;
  PreparedScene pa, pb, pf;
  if (!prepare(a, &sa, &pa) || !prepare(b, &sb, &pb)) return;
  check(pa.draws.size() == static_cast<size_t>(n) && pb.draws.size() == static_cast<size_t>(4 * n) &&
            pa.geometry_bytes() == pb.geometry_bytes() && pb.geometries() == 1,
        "instancing: prepared geometry bytes N = 4N (one DrawGeometry for every draw)",
        std::to_string(pa.geometry_bytes()) + " vs " + std::to_string(pb.geometry_bytes()) + ", " +
            std::to_string(pb.geometries()) + " geometries");
  bool model_ok = true;
  for (size_t i = 0; i < pb.draws.size(); ++i) {
    const PreparedDraw &d = pb.draws[i];
    const double *w = b.instances.at(static_cast<size_t>(b.primitives[i].instance)).world;
    model_ok = model_ok && d.instanced && d.model[12] == static_cast<float>(w[12]) &&
        d.model[13] == static_cast<float>(w[13]) && d.model[0] == 1.f && d.model[15] == 1.f;
  }
  check(model_ok, "instancing: each draw's u_model is its node's translation");
  const Scene f = flattened(b);
  if (!prepare(f, &sf, &pf)) return;
  check(pf.geometry_bytes() == 4 * static_cast<size_t>(n) * pa.geometry_bytes(),
        "instancing: flattened, the prepared bytes grow with the draws (4N copies)",
        std::to_string(pf.geometry_bytes()));
  // The C fallback: the same frame, shared or flattened.
  SceneVisibility va, vf;
  ImageF ia, iff;
  scene_rasterize_cpu(pb, &va, 1);
  scene_shade_cpu(pb, va, &ia, 1);
  scene_rasterize_cpu(pf, &vf, 1);
  scene_shade_cpu(pf, vf, &iff, 1);
  long covered = 0;
  for (int d : va.draw) covered += d >= 0;
  const bool same = ia.rgba.size() == iff.rgba.size() && va.draw == vf.draw &&
      std::memcmp(ia.rgba.data(), iff.rgba.data(), ia.rgba.size() * sizeof(float)) == 0;
  check(covered > 100 && same, "instancing: C fallback frame shared = flattened, bit for bit",
        std::to_string(covered) + " pixels covered");
}

void test_flattened_cases() {
  Scene one, scaled, mirrored;
  if (!load_json("one.gltf", scene_json({"\"translation\":[0,0,0]"}), &one)) return;
  check(one.primitives.size() == 1 && !one.primitives[0].shared && one.primitives[0].position.size() == 18,
        "instancing: a mesh under one node is flattened to world space");
  std::vector<std::string> nodes = grid_nodes(4);
  nodes[1] += ",\"scale\":[2,2,2]";
  if (!load_json("scaled.gltf", scene_json(nodes), &scaled)) return;
  check(scaled.primitives.size() == 4 && scaled.primitives[0].shared && !scaled.primitives[1].shared &&
            scaled.primitives[2].shared == scaled.primitives[0].shared,
        "instancing: a scaled node is flattened, the rigid ones share");
  nodes = grid_nodes(4);
  nodes[2] += ",\"scale\":[-1,1,1]";
  if (!load_json("mirrored.gltf", scene_json(nodes), &mirrored)) return;
  check(mirrored.primitives.size() == 4 && !mirrored.primitives[2].shared && mirrored.primitives[3].shared,
        "instancing: a mirrored node is flattened");
  // World positions of a shared instance: its node's translation applied.
  const std::vector<float> wp = scene_world_positions(scaled, scaled.primitives[0]);
  const double *w = scaled.instances.at(static_cast<size_t>(scaled.primitives[0].instance)).world;
  check(wp.size() == 18 && wp[0] == static_cast<float>(0.75 + w[12]) && wp[1] == static_cast<float>(w[13]),
        "instancing: scene_world_positions applies the node transform");
}

}  // namespace

int main() {
  char tmpl[] = "/tmp/ts_instancing_XXXXXX";
  if (!mkdtemp(tmpl)) {
    printf("FAIL setup: mkdtemp\n");
    return 1;
  }
  g_dir = tmpl;
  test_shared_bytes();
  test_flattened_cases();
  for (const char *f : {"n.gltf", "4n.gltf", "one.gltf", "scaled.gltf", "mirrored.gltf"})
    unlink((g_dir + "/" + f).c_str());
  rmdir(g_dir.c_str());
  return unit_check::finish();
}

// tiershade fuzz: the bake directory (`tiershade bake SCENE -o DIR`, docs/baking.md): manifest.json
// and volume.bin as a render of a scene naming DIR reads them (read_bake_dir, read_volume_dir
// through prepare_scene), and a checkpoint (DIR.partial/pass.bin) as a resumed bake reads it
// (load_checkpoint). DIR's page.exr is the real bake's (fuzz_exr and fuzz_page fuzz EXR pages).
//
// Input: the manifest's text, then optionally "\n@@volume.bin\n" and volume.bin's bytes, then
// optionally "\n@@pass.bin\n" and a checkpoint's body (its trailing hash is appended here). A stale
// or edited bake is refused at its hashes before anything else is read, so placeholders stand for
// them and are filled here: in the manifest "@hash.geometry@" .. "@hash.settings@", "@hash.all@"
// (the scene's BakeHash), "@volume.inputs_hash@" (the scene's volume inputs), "@volume.bytes@" and
// "@volume.content_hash@" (of the volume part as given); in the checkpoint body the 8 bytes
// "@BAKEHS@" (the bake's hash). A mutation that breaks a placeholder tests the hash checks.
// Setup: the one-quad scene below (a floor, a model triangle, a point light, 2 bounces, a volume
// of a few samples) is baked once into this process's directory. TIERSHADE_FUZZ_SEEDS=DIR writes
// that bake as seed inputs (how tests/fuzz/corpus/bakedir/ was made).
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bake/bake_dir.h"
#include "bake/content_hash.h"
#include "fuzz_util.h"
#include "scene/prepare.h"
#include "scene/scene.h"
#include "scene/selection.h"

namespace {

const char kScene[] =
    R"J({"asset":{"version":"2.0"},"extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctu)J"
    R"J(al":{"lights":[{"name":"lamp","type":"point","color":[1,0.9,0.8],"intensity":4.0}]}},"scene":0,"scen)J"
    R"J(es":[{"nodes":[0,1,2,3]}],"nodes":[{"mesh":0},{"mesh":1},{"camera":0,"translation":[0,1.5,4]},{"name)J"
    R"J(":"lamp","translation":[0.5,2,0.5],"extensions":{"KHR_lights_punctual":{"light":0}}}],"cameras":[{"t)J"
    R"J(ype":"perspective","perspective":{"yfov":0.9,"znear":0.1,"zfar":20,"aspectRatio":1.5}}],"meshes":[{")J"
    R"J(primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2},"indices":3,"material":0}]},{"pr)J"
    R"J(imitives":[{"attributes":{"POSITION":4,"NORMAL":5,"TEXCOORD_0":6},"indices":7,"material":1}]}],"mate)J"
    R"J(rials":[{"name":"floor","pbrMetallicRoughness":{"baseColorFactor":[0.6,0.5,0.4,1]},"extras":{"source)J"
    R"J(":{"shader":"LightmappedGeneric"}}},{"name":"model","pbrMetallicRoughness":{"baseColorFactor":[0.8,0)J"
    R"J(.8,0.8,1]}}],"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-2,0,-)J"
    R"J(2],"max":[2,0,2]},{"bufferView":1,"componentType":5126,"count":4,"type":"VEC3"},{"bufferView":2,"com)J"
    R"J(ponentType":5126,"count":4,"type":"VEC2"},{"bufferView":3,"componentType":5123,"count":6,"type":"SCA)J"
    R"J(LAR"},{"bufferView":4,"componentType":5126,"count":3,"type":"VEC3","min":[-0.3,0.8,0],"max":[0.3,1.3)J"
    R"J(,0]},{"bufferView":5,"componentType":5126,"count":3,"type":"VEC3"},{"bufferView":6,"componentType":5)J"
    R"J(126,"count":3,"type":"VEC2"},{"bufferView":7,"componentType":5123,"count":3,"type":"SCALAR"}],"buffe)J"
    R"J(rViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":48},{")J"
    R"J(buffer":0,"byteOffset":96,"byteLength":32},{"buffer":0,"byteOffset":128,"byteLength":12},{"buffer":0)J"
    R"J(,"byteOffset":140,"byteLength":36},{"buffer":0,"byteOffset":176,"byteLength":36},{"buffer":0,"byteOf)J"
    R"J(fset":212,"byteLength":24},{"buffer":0,"byteOffset":236,"byteLength":6}],"buffers":[{"uri":"data:app)J"
    R"J(lication/octet-stream;base64,AAAAwAAAAAAAAADAAAAAQAAAAAAAAADAAAAAQAAAAAAAAABAAAAAwAAAAAAAAABAAAAAAAA)J"
    R"J(AgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAgD8AAIA/AAAAAAAAgD8)J"
    R"J(AAAIAAQAAAAMAAgCamZm+zcxMPwAAAACamZk+zcxMPwAAAAAAAAAAZmamPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8AAAA)J"
    R"J(AAAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAPwAAgD8AAAEAAgAAAA==","byteLength":244}],"extras":{"tiershade":)J"
    R"J({"camera":0,"hdr":{"path":"integer","tone_map_scale":1.0},"lightmaps":{"luxels_per_unit":2,"encoding)J"
    R"J(":"float","page":[64,64],"bounces":2},"volume":{"bounds":[[-2,0.2,-2],[2,2,2]],"spacing":[2,1.8,2]}})J"
    R"J(}})J";

const char kVolumeMark[] = "\n@@volume.bin\n", kPassMark[] = "\n@@pass.bin\n";
const char kHashKeys[6][10] = {"geometry", "materials", "lights", "probes", "settings", "all"};

std::string slurp(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

void replace_all(std::string *s, const std::string &from, const std::string &to) {
  for (size_t at = s->find(from); at != std::string::npos; at = s->find(from, at + to.size())) s->replace(at, from.size(), to);
}

uint64_t hash_of(const std::string &b) {
  ContentHash h;
  h.bytes(b.data(), b.size());
  return h.h;
}

// The baked directory and what the placeholders stand for.
struct Setup {
  std::string bake_dir, read_scene, checkpoint;  // checkpoint: the first bounce's pass.bin
  BakeHash hash;
  std::string volume_inputs;
  Setup() {
    const std::string d = fuzz::dir();
    bake_dir = d + "/bake";
    Scene s;
    SceneSelection sel;
    PreparedScene ps;
    std::string err;
    if (!load_scene(fuzz::write_text("bake_src.gltf", kScene), &s, &err)) fail(err);
    s.lightmaps.bake_checkpoint = bake_dir;  // as `tiershade bake -o DIR` runs it
    if (!select_scene_variants(s, Tier::SM3, "", &sel, &err) || !prepare_scene(s, sel, 16, 16, Api::GL33, 1.f, &ps, &err))
      fail(err);
    checkpoint = slurp(bake_checkpoint_dir(bake_dir) + "/pass.bin");
    if (checkpoint.size() < 8 || ps.volume.cube.empty()) fail("the setup bake has no checkpoint or no volume");
    if (!write_bake_dir(bake_dir, "bake_src.gltf", ps.bake_summary, ps.lightmap_page, {}, &err, &ps.volume)) fail(err);
    hash = ps.bake_summary.hash;
    const nlohmann::json m = nlohmann::json::parse(slurp(bake_dir + "/manifest.json"));
    volume_inputs = m.at("volume").at("inputs_hash").get<std::string>();
    std::string text = kScene;
    const std::string key = "\"lightmaps\":{";
    text.replace(text.find(key), key.size(), key + "\"bake\":\"" + bake_dir + "\",");
    read_scene = fuzz::write_text("bake_read.gltf", text);
    if (const char *seeds = std::getenv("TIERSHADE_FUZZ_SEEDS")) write_seeds(seeds, m);
  }
  [[noreturn]] static void fail(const std::string &why) {
    std::fprintf(stderr, "fuzz_bakedir setup: %s\n", why.c_str());
    std::abort();
  }
  // The real bake as inputs, its hashes as placeholders.
  void write_seeds(const std::string &out, nlohmann::json m) const {
    for (const char *k : kHashKeys) m["hash"][k] = std::string("@hash.") + k + "@";
    m["volume"]["inputs_hash"] = "@volume.inputs_hash@";
    m["volume"]["content_hash"] = "@volume.content_hash@";
    std::string text = m.dump(1);
    replace_all(&text, "\"bytes\": " + std::to_string(m["volume"]["bytes"].get<uint64_t>()), "\"bytes\": @volume.bytes@");
    std::string body = checkpoint.substr(0, checkpoint.size() - 8);
    uint64_t all = hash.all();
    for (size_t at = 0; at + 8 <= body.size(); ++at)
      if (std::memcmp(body.data() + at, &all, 8) == 0) {
        body.replace(at, 8, "@BAKEHS@");
        break;
      }
    const std::string vol = slurp(bake_dir + "/volume.bin");
    const std::string files[3][2] = {{"whole", text + kVolumeMark + vol + kPassMark + body},
                                     {"manifest_volume", text + kVolumeMark + vol},
                                     {"manifest_pass", text + kPassMark + body}};
    for (const auto &f : files) {
      std::ofstream o(out + "/" + f[0], std::ios::binary);
      o << f[1];
    }
  }
};

void write(const std::string &path, const std::string &bytes, bool present) {
  if (!present) {
    std::remove(path.c_str());
    return;
  }
  fuzz::write_file(path.substr(fuzz::dir().size() + 1), reinterpret_cast<const uint8_t *>(bytes.data()), bytes.size());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const Setup setup;
  const std::string in(reinterpret_cast<const char *>(data), size);
  const size_t vm = in.find(kVolumeMark), pm = in.find(kPassMark, vm == std::string::npos ? 0 : vm);
  std::string manifest = in.substr(0, std::min(vm, pm));
  std::string volume, body;
  if (vm != std::string::npos) volume = in.substr(vm + std::strlen(kVolumeMark), pm == std::string::npos ? std::string::npos : pm - vm - std::strlen(kVolumeMark));
  if (pm != std::string::npos) body = in.substr(pm + std::strlen(kPassMark));

  const uint64_t parts[6] = {setup.hash.geometry, setup.hash.materials, setup.hash.lights, setup.hash.probes,
                             setup.hash.settings, setup.hash.all()};
  for (int i = 0; i < 6; ++i) replace_all(&manifest, std::string("@hash.") + kHashKeys[i] + "@", hash_hex(parts[i]));
  replace_all(&manifest, "@volume.inputs_hash@", setup.volume_inputs);
  replace_all(&manifest, "@volume.content_hash@", hash_hex(hash_of(volume)));
  replace_all(&manifest, "@volume.bytes@", std::to_string(volume.size()));
  write(setup.bake_dir + "/manifest.json", manifest, true);
  write(setup.bake_dir + "/volume.bin", volume, vm != std::string::npos);

  // A render of the scene naming the directory: the manifest, the page and the volume.
  Scene s;
  SceneSelection sel;
  PreparedScene ps;
  std::string err;
  if (load_scene(setup.read_scene, &s, &err) && select_scene_variants(s, Tier::SM3, "", &sel, &err))
    prepare_scene(s, sel, 16, 16, Api::GL33, 1.f, &ps, &err);

  // A resumed bake: the checkpoint.
  if (pm != std::string::npos) {
    const uint64_t all = setup.hash.all();
    for (size_t at = body.find("@BAKEHS@"); at != std::string::npos; at = body.find("@BAKEHS@", at + 8))
      body.replace(at, 8, reinterpret_cast<const char *>(&all), 8);
    const uint64_t tail = hash_of(body);
    body.append(reinterpret_cast<const char *>(&tail), 8);
    const std::string ck = fuzz::dir() + "/ck";
    std::error_code ec;
    std::filesystem::create_directories(bake_checkpoint_dir(ck), ec);
    write(bake_checkpoint_dir(ck) + "/pass.bin", body, true);
    BakePassState st;
    std::string note;
    load_checkpoint(ck, setup.hash, &st, &note);
  }
  return 0;
}

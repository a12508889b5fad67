// tiershade bake: the irradiance volume's file and manifest entry in the bake directory, its inputs'
// hash, reading it back (volume_file.h).
#include "bake/volume_file.h"

#include "bake/area_lights.h"

#include <cinttypes>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bake/bake_dir.h"
#include "bake/content_hash.h"
#include "bake/world_faces.h"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

const char kVolumeFile[] = "volume.bin";

namespace {

const char kMagic[8] = {'T', 'S', 'V', 'O', 'L', 'U', 'M', 'E'};
const uint32_t kVersion = 1;
// Header: magic (8), version u32 (4), n i32 x 3 (12), origin f64 x 3 (24), step f64 x 3 (24),
// inputs hash u64 (8). Each sample, in index order ((k * ny + j) * nx + i): position f32 x 3,
// valid u32 (0 or 1), back-face share f32, cube f32 x 18 (+X -X +Y -Y +Z -Z, RGB each).
const size_t kHeader = 8 + 4 + 12 + 24 + 24 + 8, kSample = 12 + 4 + 4 + 72;
const long kManifestMaxBytes = 64l << 20;

void vec(ContentHash &h, const ts_vec3d &v) {
  h.value(v.x);
  h.value(v.y);
  h.value(v.z);
}

template <class T>
void put(std::string &s, const T &v) {
  s.append(reinterpret_cast<const char *>(&v), sizeof v);
}
template <class T>
T get(const std::string &s, size_t at) {
  T v;
  std::memcpy(&v, s.data() + at, sizeof v);
  return v;
}

uint64_t bytes_hash(const std::string &b) {
  ContentHash h;
  h.bytes(b.data(), b.size());
  return h.h;
}

}  // namespace

VolumeInputs volume_inputs(const double lo[3], const double hi[3], const VolumeSettings &set,
                           const std::vector<WorldFace> &faces, const std::vector<LuxelGrid> &grids,
                           uint64_t rays_hash, uint64_t sky_hash) {
  VolumeInputs in;
  ContentHash box, st, geo, mat, lm, sky;
  st.value(kVersion);
  for (int a = 0; a < 3; ++a) {
    in.lo[a] = lo[a];
    in.hi[a] = hi[a];
    in.spacing[a] = set.spacing[a];
    box.value(lo[a]);
    box.value(hi[a]);
    st.value(set.spacing[a]);
  }
  // Where models can be narrows the box (hashed with it only when named: a volume over the whole
  // box keeps the hash it had).
  in.regions = set.regions;
  if (!set.regions.empty()) box.value(static_cast<uint64_t>(set.regions.size()));
  for (const std::array<double, 6> &r : set.regions)
    for (double x : r) box.value(x);
  in.fit = set.fit;
  in.max_back_share = set.max_back_share;
  in.models_occlude = set.models_occlude;
  st.value(static_cast<int>(set.fit));
  st.value(set.max_back_share);
  st.value(set.models_occlude);
  geo.value(rays_hash);
  sky.value(sky_hash);
  for (const WorldFace &f : faces) {
    vec(geo, f.origin);
    vec(geo, f.u);
    vec(geo, f.v);
    geo.value(f.su);
    geo.value(f.sv);
    vec(geo, f.normal);
    vec(mat, f.reflectivity);
    vec(mat, f.emission);
  }
  if (set.model_emitters)  // the emissive models' light (their triangles are the rays' geometry)
    for (const ModelEmitter &e : *set.model_emitters) {
      vec(mat, e.emission);
      mat.values(e.tri);
    }
  for (const LuxelGrid &g : grids) {
    lm.value(g.w);
    lm.value(g.h);
    for (size_t i = 0; i < g.v.size(); i += 4) vec(lm, g.v[i]);  // value k = 0: the flat lightmap
  }
  in.bounds = box.h;
  in.settings = st.h;
  in.geometry = geo.h;
  in.materials = mat.h;
  in.lightmaps = lm.h;
  in.sky = sky.h;
  return in;
}

uint64_t volume_inputs_hash(const VolumeInputs &in) {
  ContentHash h;
  for (uint64_t v : {in.bounds, in.settings, in.geometry, in.materials, in.lightmaps, in.sky}) h.value(v);
  return h.h;
}

namespace {

json vec3_json(const double v[3]) { return json::array({v[0], v[1], v[2]}); }

json regions_json(const std::vector<std::array<double, 6>> &regions) {
  json a = json::array();
  for (const std::array<double, 6> &r : regions) a.push_back(json::array({vec3_json(&r[0]), vec3_json(&r[3])}));
  return a;
}

// The entry's record of the inputs: the parts' hashes and the box's and settings' values.
json inputs_json(const VolumeInputs &in) {
  return {{"hash",
           {{"bounds", hash_hex(in.bounds)},
            {"settings", hash_hex(in.settings)},
            {"geometry", hash_hex(in.geometry)},
            {"materials", hash_hex(in.materials)},
            {"lightmaps", hash_hex(in.lightmaps)},
            {"sky", hash_hex(in.sky)}}},
          {"bounds", json::array({vec3_json(in.lo), vec3_json(in.hi)})},
          {"regions", regions_json(in.regions)},
          {"spacing", vec3_json(in.spacing)},
          {"fit", ambient_fit_name(in.fit)},
          {"max_back_share", in.max_back_share},
          {"models_occlude", in.models_occlude}};
}

const char *const kPartWords[6] = {
    "the volume's bounds", "the volume's settings", "the geometry (world faces or any triangle the rays see)",
    "the world faces' materials (reflectivity, emission)", "the lightmaps", "the sky"};

// What differs between a recorded inputs object (the manifest's) and `now`, in words; "" when the
// record is not readable (an older manifest) or nothing differs.
std::string inputs_changed(const json &was, const VolumeInputs &now) {
  const json n = inputs_json(now);
  if (!was.is_object() || !was.contains("hash") || !was["hash"].is_object()) return "";
  const char *keys[6] = {"bounds", "settings", "geometry", "materials", "lightmaps", "sky"};
  std::string s;
  for (int i = 0; i < 6; ++i) {
    if (was["hash"].contains(keys[i]) && was["hash"][keys[i]] == n["hash"][keys[i]]) continue;
    std::string what = kPartWords[i], values;
    // The box's and settings' values that differ, by name (the manifest's -> the scene's).
    const std::vector<const char *> named = i == 0 ? std::vector<const char *>{"bounds", "regions"}
        : i == 1 ? std::vector<const char *>{"spacing", "fit", "max_back_share", "models_occlude"}
                 : std::vector<const char *>{};
    for (const char *k : named)
      if (!was.contains(k) || was[k] != n[k])
        values += std::string(values.empty() ? " (" : ", ") + k + " " + (was.contains(k) ? was[k].dump() : "?") +
            " -> " + n[k].dump();
    if (!values.empty()) what += values + ")";
    s += (s.empty() ? "" : ", ") + what;
  }
  return s;
}

}  // namespace

std::string volume_inputs_changed(const VolumeInputs &was, const VolumeInputs &now) {
  return inputs_changed(inputs_json(was), now);
}

std::string volume_file_bytes(const IrradianceVolume &v) {
  std::string s(kMagic, sizeof kMagic);
  put(s, kVersion);
  for (int a = 0; a < 3; ++a) put(s, static_cast<int32_t>(v.n[a]));
  for (int a = 0; a < 3; ++a) put(s, v.origin[a]);
  for (int a = 0; a < 3; ++a) put(s, v.step[a]);
  put(s, v.inputs_hash);
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const size_t idx = v.index(i, j, k);
        const glm::dvec3 p = v.position(i, j, k);
        put(s, static_cast<float>(p.x));
        put(s, static_cast<float>(p.y));
        put(s, static_cast<float>(p.z));
        put(s, static_cast<uint32_t>(v.valid[idx] ? 1 : 0));
        put(s, v.back_share[idx]);
        for (int f = 0; f < 6; ++f)
          for (int c = 0; c < 3; ++c) put(s, v.cube[idx][f][c]);
      }
  return s;
}

json volume_manifest_entry(const IrradianceVolume &v, const std::string &bytes) {
  int valid = 0;
  for (uint8_t x : v.valid) valid += x;
  return {{"file", kVolumeFile},
          {"bytes", bytes.size()},
          {"content_hash", hash_hex(bytes_hash(bytes))},
          {"inputs_hash", hash_hex(v.inputs_hash)},
          {"inputs", inputs_json(v.inputs)},
          {"samples", {v.n[0], v.n[1], v.n[2]}},
          {"valid", valid},
          {"baked", v.baked},
          {"origin", {v.origin[0], v.origin[1], v.origin[2]}},
          {"step", {v.step[0], v.step[1], v.step[2]}},
          {"rays", v.rays},
          {"ms", v.bake_ms},
          {"layout",
           "little-endian: header (magic TSVOLUME, u32 version 1, i32 n[3], f64 origin[3], f64 step[3], u64 inputs "
           "hash), then per sample in (k * ny + j) * nx + i order: f32 position[3], u32 valid, f32 back-face share, "
           "f32 cube[6][3] (+X -X +Y -Y +Z -Z; docs/irradiance_volume.md)"}};
}

bool read_volume_dir(const std::string &dir, const VolumeInputs &inputs, IrradianceVolume *out, std::string *err) {
  const uint64_t inputs_hash = volume_inputs_hash(inputs);
  *out = IrradianceVolume();
  const std::string mf = dir + "/manifest.json", vf = dir + "/" + kVolumeFile;
  const std::string rebake = "; rebake with tiershade bake SCENE -o " + dir;
  std::error_code ec;
  const auto msize = fs::file_size(mf, ec);
  if (ec || static_cast<long>(msize) > kManifestMaxBytes) {
    *err = mf + ": cannot read" + (ec ? ": " + ec.message() : std::string(": too large"));
    return false;
  }
  std::ifstream mfs(mf, std::ios::binary);
  std::stringstream ss;
  ss << mfs.rdbuf();
  const json m = json::parse(ss.str(), nullptr, false);
  if (m.is_discarded() || !m.is_object()) {
    *err = mf + ": not a JSON object";
    return false;
  }
  if (!m.contains("volume")) {
    *err = mf + ": /volume: missing: the bake has no irradiance volume and the scene's models need one" + rebake;
    return false;
  }
  const json &e = m["volume"];
  auto field = [&](const char *key, bool number) -> const json * {
    if (!e.is_object() || !e.contains(key)) {
      *err = mf + ": /volume/" + key + ": missing";
      return nullptr;
    }
    const json &x = e[key];
    if (number ? !x.is_number_unsigned() : !x.is_string()) {
      *err = mf + ": /volume/" + key + ": expected " + (number ? "a non-negative integer" : "a string") + ", found " +
          x.type_name();
      return nullptr;
    }
    return &x;
  };
  const json *file = field("file", false), *nbytes = file ? field("bytes", true) : nullptr;
  const json *chash = nbytes ? field("content_hash", false) : nullptr;
  const json *ihash = chash ? field("inputs_hash", false) : nullptr;
  if (!ihash) return false;
  if (*file != kVolumeFile) {
    *err = mf + ": /volume/file: " + file->dump() + " is not \"" + kVolumeFile + "\"";
    return false;
  }
  if (ihash->get<std::string>() != hash_hex(inputs_hash)) {
    // What changed, from the entry's record of the parts (a manifest without one: the generic words).
    const json *rec = e.contains("inputs") ? &e["inputs"] : nullptr;
    const std::string what = rec ? inputs_changed(*rec, inputs) : std::string();
    const bool readable = rec && rec->is_object() && rec->contains("hash") && (*rec)["hash"].is_object();
    if (readable && what.empty())
      *err = mf + ": /volume/inputs_hash: stale irradiance volume: the hash is not the one of its parts "
                  "(/volume/inputs/hash: the manifest was edited)" + rebake;
    else
      *err = mf + ": /volume/inputs_hash: stale irradiance volume: " +
          (what.empty() ? std::string("the world, its lightmaps, the sky or the volume settings") : what) +
          " changed since it was baked" + rebake;
    return false;
  }
  const auto fsize = fs::file_size(vf, ec);
  if (ec) {
    *err = vf + ": cannot read: " + ec.message();
    return false;
  }
  if (fsize != nbytes->get<uint64_t>()) {
    *err = vf + ": " + std::to_string(fsize) + " bytes, the manifest's /volume/bytes says " + nbytes->dump();
    return false;
  }
  std::ifstream vfs(vf, std::ios::binary);
  std::string b(static_cast<size_t>(fsize), '\0');
  if (!vfs.read(&b[0], static_cast<std::streamsize>(b.size()))) {
    *err = vf + ": cannot read " + std::to_string(fsize) + " bytes";
    return false;
  }
  if (hash_hex(bytes_hash(b)) != chash->get<std::string>()) {
    *err = vf + ": content hash " + hash_hex(bytes_hash(b)) + " is not the manifest's /volume/content_hash " +
        chash->get<std::string>() + " (the file was changed or damaged)" + rebake;
    return false;
  }
  // The hashes agree: the checks below catch a file and manifest edited together.
  if (b.size() < kHeader || std::memcmp(b.data(), kMagic, sizeof kMagic) != 0) {
    *err = vf + ": byte 0: not a tiershade volume file (no TSVOLUME header)";
    return false;
  }
  if (get<uint32_t>(b, 8) != kVersion) {
    *err = vf + ": byte 8: version " + std::to_string(get<uint32_t>(b, 8)) + ", this tiershade reads version 1";
    return false;
  }
  IrradianceVolume v;
  long long count = 1;
  for (int a = 0; a < 3; ++a) {
    v.n[a] = get<int32_t>(b, 12 + 4 * a);
    v.origin[a] = get<double>(b, 24 + 8 * a);
    v.step[a] = get<double>(b, 48 + 8 * a);
    if (v.n[a] < 1 || v.n[a] > (1 << 22) || !std::isfinite(v.origin[a]) || !(v.step[a] > 0) ||
        !std::isfinite(v.step[a])) {
      *err = vf + ": bytes 12-71: axis " + std::to_string(a) + ": " + std::to_string(v.n[a]) +
          " samples, origin or step out of range";
      return false;
    }
    count *= v.n[a];
  }
  if (count > (1LL << 22) || b.size() != kHeader + static_cast<size_t>(count) * kSample) {
    *err = vf + ": " + std::to_string(b.size()) + " bytes, a " + std::to_string(v.n[0]) + " x " +
        std::to_string(v.n[1]) + " x " + std::to_string(v.n[2]) + " volume takes " +
        std::to_string(kHeader + static_cast<size_t>(count) * kSample);
    return false;
  }
  v.inputs_hash = get<uint64_t>(b, 72);
  if (v.inputs_hash != inputs_hash) {
    *err = vf + ": byte 72: inputs hash " + hash_hex(v.inputs_hash) + " is not the manifest's" + rebake;
    return false;
  }
  v.cube.assign(static_cast<size_t>(count), {});
  v.valid.assign(static_cast<size_t>(count), 0);
  v.back_share.assign(static_cast<size_t>(count), 0.f);
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const size_t idx = v.index(i, j, k), at = kHeader + idx * kSample;
        const std::string where = vf + ": sample (" + std::to_string(i) + ", " + std::to_string(j) + ", " +
            std::to_string(k) + ") at byte " + std::to_string(at);
        const glm::dvec3 p = v.position(i, j, k);
        if (get<float>(b, at) != static_cast<float>(p.x) || get<float>(b, at + 4) != static_cast<float>(p.y) ||
            get<float>(b, at + 8) != static_cast<float>(p.z)) {
          *err = where + ": its position is not the grid's";
          return false;
        }
        const uint32_t ok = get<uint32_t>(b, at + 12);
        const float share = get<float>(b, at + 16);
        if (ok > 1 || !(share >= 0 && share <= 1)) {
          *err = where + ": validity " + std::to_string(ok) + " (0 or 1) or back-face share out of [0, 1]";
          return false;
        }
        v.valid[idx] = static_cast<uint8_t>(ok);
        v.back_share[idx] = share;
        for (int f = 0; f < 6; ++f)
          for (int c = 0; c < 3; ++c) {
            const float x = get<float>(b, at + 20 + 4 * (3 * f + c));
            if (!std::isfinite(x) || x < 0) {
              *err = where + ": colour " + std::to_string(f) + "." + std::to_string(c) + " is negative or not finite";
              return false;
            }
            v.cube[idx][f][c] = x;
          }
      }
  if (e.contains("rays") && e["rays"].is_number_integer()) v.rays = e["rays"].get<long>();
  v.baked = static_cast<long>(v.cube.size());  // an older manifest: every sample
  if (e.contains("baked") && e["baked"].is_number_integer() && e["baked"].get<long>() >= 0 &&
      e["baked"].get<long>() <= v.baked)
    v.baked = e["baked"].get<long>();
  v.inputs = inputs;  // the hash says they are the scene's
  *out = std::move(v);
  return true;
}

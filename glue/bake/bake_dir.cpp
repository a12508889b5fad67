// tiershade bake: the bake directory: hash, manifest, reading it back, the bake with checkpoints
// and progress (bake_dir.h). The checkpoint files are in bake_checkpoint.cpp.
#include "bake/bake_dir.h"

#include <unistd.h>

#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bake/content_hash.h"
#include "bake/ray_scene.h"
#include "bake/volume_file.h"
#include "base/image.h"
#include "io/atomic_dir.h"
#include "io/exr.h"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

const int kManifestVersion = 1;
const char kManifest[] = "manifest.json", kPage[] = "page.exr";
const long kManifestMaxBytes = 64l << 20;  // bounded: a face is ~300 bytes of manifest

// Every input the bake reads goes into the hash: a field added to these structs must be hashed
// below (and its size here updated), else a stale bake would pass for a current one.
static_assert(sizeof(WorldFace) == 200, "WorldFace changed: hash the new field in bake_input_hash");
static_assert(sizeof(rnm_light) == 160, "rnm_light changed: hash the new field in bake_input_hash");
// (BounceSettings::emission_sampled and model_emitters are set by bake_world from area_samples and
// WorldBakeInput::model_emitters, which are hashed.)
static_assert(sizeof(BounceSettings) == 48, "BounceSettings changed: hash the new field in bake_input_hash");
// (WorldBakeInput::trace_cube is not hashed: which probes' cubes are ray traced changes no page texel,
// and the cubes are not stored here; they are made at load, glue/scene/probe_render.h.)
static_assert(sizeof(WorldBakeInput) == 296, "WorldBakeInput changed: hash the new field in bake_input_hash");

void vec(ContentHash &h, const ts_vec3d &v) {
  h.value(v.x);
  h.value(v.y);
  h.value(v.z);
}

}  // namespace

uint64_t BakeHash::all() const {
  ContentHash h;
  for (uint64_t v : {geometry, materials, lights, probes, settings}) h.value(v);
  return h.h;
}

std::string BakeHash::changed(const BakeHash &o) const {
  std::string s;
  auto add = [&](bool differ, const char *what) {
    if (differ) s += (s.empty() ? "" : ", ") + std::string(what);
  };
  add(geometry != o.geometry, "the geometry");
  add(materials != o.materials, "the materials (reflectivity, emission, normal maps)");
  add(lights != o.lights, "the lights");
  add(probes != o.probes, "the probes");
  add(settings != o.settings, "the bake settings");
  return s;
}

std::string hash_hex(uint64_t h) {
  char b[24];
  snprintf(b, sizeof b, "%016" PRIx64, h);
  return b;
}

BakeHash bake_input_hash(const WorldBakeInput &in) {
  ContentHash g, m, l, p, s;
  g.value(in.rays ? in.rays->content_hash() : 0);
  for (const WorldFace &f : in.faces) {
    vec(g, f.origin);
    vec(g, f.u);
    vec(g, f.v);
    g.value(f.su);
    g.value(f.sv);
    vec(g, f.normal);
    g.value(f.chart != nullptr);  // a TEXCOORD_1 chart (glue/bake/charts.h): what it bakes from
    if (f.chart) chart_hash(&g, *f.chart);
    p.value(f.probe);
    vec(m, f.reflectivity);
    vec(m, f.emission);
    m.value(f.bumped);
  }
  for (const ModelEmitter &e : in.model_emitters) {  // emissive models (glue/bake/area_lights.h)
    g.values(e.tri);
    vec(m, e.emission);
  }
  for (const rnm_light &r : in.lights) {
    l.value(r.directional);
    vec(l, r.pos);
    vec(l, r.dir);
    vec(l, r.color);
    for (double a : r.atten) l.value(a);
    l.value(r.spot);
    vec(l, r.spot_dir);
    l.value(r.cos_inner);
    l.value(r.cos_outer);
    l.value(r.exponent);
  }
  // The sky and the suns' spread (glue/bake/sky.h, world_bake.h) light the scene like the lights.
  for (double a : in.light_spread) l.value(a);
  l.value(in.sky.present());
  if (in.sky.present()) {
    l.value(in.sky.w);
    l.value(in.sky.h);
    l.value(in.sky.scale);
    for (size_t i = 0; i < static_cast<size_t>(in.sky.w) * in.sky.h * 4; ++i) l.value(in.sky.rgba[i]);
  }
  for (const ts_vec3d &q : in.probes) vec(p, q);
  s.value(kManifestVersion);
  s.value(in.sky.samples);
  s.value(in.area_samples);
  s.value(in.spread_samples);
  s.value(in.luxels_per_unit);
  s.value(in.page_w);
  s.value(in.page_h);
  s.value(in.cube_size);
  s.value(in.supersample);
  s.value(in.bounce.max_bounces);
  s.value(in.bounce.gather_rays);
  s.value(in.bounce.threshold);
  s.value(in.bounce.seed);
  return BakeHash{g.h, m.h, l.h, p.h, s.h};
}

namespace {

// The progress line (stderr): on a terminal, updated in place per face; otherwise one line per
// pass, and only once the bake has run 2 s (a short bake prints nothing).
struct Progress {
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  bool tty = isatty(2) != 0;
  void operator()(const std::string &pass, long done, long total) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (done < total) {
      if (tty) fprintf(stderr, "\rbake: %s: %ld / %ld luxels (%.1f s)", pass.c_str(), done, total, s);
      return;
    }
    if (tty || s > 2.0)
      fprintf(stderr, "%sbake: %s: %ld / %ld luxels (%.1f s)\n", tty ? "\r" : "", pass.c_str(), done, total, s);
  }
};

// The hashed settings by name (the quality's values among them: bake_quality.h), for the manifest
// and for saying which of them a stale bake differs in.
json settings_json(double luxels_per_unit, int page_w, int page_h, int supersample, int area_samples,
                   int spread_samples, int sky_samples, const BounceSettings &b, int cube_size) {
  return {{"luxels_per_unit", luxels_per_unit},
          {"page", {page_w, page_h}},
          {"supersample", supersample},
          {"area_samples", area_samples},
          {"spread_samples", spread_samples},
          {"sky_samples", sky_samples},
          {"bounces", b.max_bounces},
          {"gather_rays", b.gather_rays},
          {"threshold", b.threshold},
          {"seed", b.seed},
          {"cube_size", cube_size}};
}

}  // namespace

bool bake_world_dir(const BakeDirUse &use, WorldBakeInput in, const std::vector<std::string> &where, WorldBake *out,
                    BakeSummary *sum, std::string *err) {
  *sum = BakeSummary();
  sum->hash = bake_input_hash(in);
  std::vector<float> page;
  BakePassState resume;
  BakeHooks hooks;
  if (!use.read.empty()) {
    if (!read_bake_dir(use.read, in, &page, err)) return false;
    in.page_in = &page;
    sum->from_dir = use.read;
  } else {
    if (!use.checkpoint_dir.empty()) {
      if (load_checkpoint(use.checkpoint_dir, sum->hash, &resume, &sum->resume_note)) hooks.resume = &resume;
      const std::string dir = use.checkpoint_dir;
      const BakeHash h = sum->hash;
      hooks.on_pass = [dir, h](const BakePassState &st, std::string *e) { return save_checkpoint(dir, h, st, e); };
    }
    if (use.progress) hooks.progress = Progress();
    in.hooks = &hooks;
  }
  if (!bake_world(in, out, err)) return false;
  sum->resumed_after = out->resumed_after;
  sum->page_w = in.page_w;
  sum->page_h = in.page_h;
  sum->luxels_per_unit = in.luxels_per_unit;
  sum->supersample = in.supersample;
  sum->cube_size = in.cube_size;
  sum->probes = static_cast<int>(in.probes.size());
  sum->traced_cubes = 0;
  for (const TextureDesc &c : out->cubes) sum->traced_cubes += c.w > 0;
  sum->lights = static_cast<int>(in.lights.size());
  sum->bounce = in.bounce;
  sum->luxels = out->luxels;
  sum->direct_rays = out->direct_rays;
  sum->direct_ms = out->direct_ms;
  sum->report = out->bounce;
  sum->sky = in.sky.present();
  sum->area_samples = in.area_samples;
  sum->spread_samples = in.spread_samples;
  sum->sky_samples = in.sky.samples;
  for (const WorldFace &f : in.faces)
    sum->emitters += f.emission.x > 0 || f.emission.y > 0 || f.emission.z > 0;
  for (const ModelEmitter &e : in.model_emitters)
    sum->model_emitters += e.emission.x > 0 || e.emission.y > 0 || e.emission.z > 0;
  sum->sky_pass = out->sky;
  sum->area_pass = out->area;
  for (size_t i = 0; i < in.faces.size(); ++i) {
    BakeFace f;
    f.name = in.faces[i].name ? in.faces[i].name : "";
    f.where = i < where.size() ? where[i] : "";
    f.face = in.faces[i];
    f.face.name = nullptr;
    f.place = out->place[i];
    f.luxels_w = f.place.block_w - 2;
    f.luxels_h = f.place.block_h - 2;
    sum->faces.push_back(f);
  }
  return true;
}

bool write_bake_dir(const std::string &dir, const std::string &scene_name, const BakeSummary &sum,
                    const std::vector<float> &page, const std::vector<std::string> &baked_why, std::string *err,
                    const IrradianceVolume *volume) {
  DirWriter w;
  if (!w.begin(dir, kManifest, "bake directory", err)) return false;
  ImageF img;
  img.w = sum.page_w;
  img.h = static_cast<int>(page.size() / 4 / static_cast<size_t>(sum.page_w));  // the pages stacked
  img.rgba = page;
  if (!write_exr(w.path(kPage), img, err)) return false;
  json m;
  m["format"] = "tiershade bake";
  m["version"] = kManifestVersion;
  m["scene"] = scene_name;
  m["hash"] = {{"all", hash_hex(sum.hash.all())},           {"geometry", hash_hex(sum.hash.geometry)},
               {"materials", hash_hex(sum.hash.materials)}, {"lights", hash_hex(sum.hash.lights)},
               {"probes", hash_hex(sum.hash.probes)},       {"settings", hash_hex(sum.hash.settings)}};
  m["page"] = {{"file", kPage},
               {"width", sum.page_w},
               {"height", sum.page_h},
               {"pages", img.h / sum.page_h},
               {"texels", "RGBA float32, row 0 at the bottom; flat, b0, b1, b2 blocks per face (docs/baking.md)"}};
  m["settings"] =
      settings_json(sum.luxels_per_unit, sum.page_w, sum.page_h, sum.supersample, sum.area_samples, sum.spread_samples,
                    sum.sky_samples, sum.bounce, sum.cube_size);
  m["settings"]["quality"] = sum.quality.preset;  // the preset's name (not hashed: the values are)
  json faces = json::array();
  for (const BakeFace &f : sum.faces)
    faces.push_back({{"material", f.name},
                     {"primitive", f.where},
                     {"luxels", {f.luxels_w, f.luxels_h}},
                     {"lightmaps", f.place.count},
                     {"bumped", f.face.bumped},
                     {"place",
                      {{"x", f.place.x},
                       {"y", f.place.y},
                       {"block_w", f.place.block_w},
                       {"block_h", f.place.block_h},
                       {"offset", {f.place.offset[0], f.place.offset[1]}}}}});
  m["faces"] = faces;
  json passes = json::array();
  passes.push_back({{"pass", "direct"},
                    {"rays", sum.direct_rays},
                    {"ms", sum.direct_ms},
                    {"from_checkpoint", sum.resumed_after >= 0}});
  for (int k = 0; k < sum.report.passes && k < static_cast<int>(sum.report.pass_rays.size()); ++k)
    passes.push_back(
        {{"pass", "bounce " + std::to_string(k + 1)},
         {"rays", sum.report.pass_rays[static_cast<size_t>(k)]},
         {"ms", k < static_cast<int>(sum.report.pass_ms.size()) ? sum.report.pass_ms[static_cast<size_t>(k)] : 0.0},
         {"largest_flat_added", sum.report.added[static_cast<size_t>(k)]},
         {"from_checkpoint", k + 1 <= sum.resumed_after}});
  m["passes"] = passes;
  m["resumed_after_pass"] = sum.resumed_after;
  m["luxels"] = sum.luxels;
  m["baked"] = baked_why;
  if (volume && !volume->cube.empty()) {  // the models' irradiance volume (docs/irradiance_volume.md)
    const std::string vb = volume_file_bytes(*volume);
    if (!w.write(kVolumeFile, vb, err)) return false;
    m["volume"] = volume_manifest_entry(*volume, vb);
  }
  if (!w.write(kManifest, m.dump(1) + "\n", err) || !w.commit(err)) return false;
  std::error_code ec;
  fs::remove_all(bake_checkpoint_dir(dir), ec);  // the bake is complete: its checkpoints are spent
  return true;
}

namespace {

// A JSON place's value of the expected kind, or an error naming the file and the place.
struct ManifestReader {
  std::string file;
  std::string *err;
  const json *get(const json &obj, const std::string &place, const char *key, json::value_t want, bool number = false) {
    const json::json_pointer ptr(place + "/" + key);
    if (!obj.is_object() || !obj.contains(key)) {
      *err = file + ": " + ptr.to_string() + ": missing";
      return nullptr;
    }
    const json &v = obj.at(key);
    if (number ? !v.is_number() : v.type() != want) {
      *err = file + ": " + ptr.to_string() + ": expected " + (number ? "a number" : json(want).type_name()) +
          ", found " + v.type_name();
      return nullptr;
    }
    return &v;
  }
};

// DIR/manifest.json parsed (bounded in size); errors name the file.
bool load_manifest(const std::string &dir, json *m, std::string *err) {
  const std::string mf = dir + "/" + kManifest;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    *err = dir + ": no bake directory there (write one with tiershade bake SCENE -o " + dir + ")";
    return false;
  }
  const auto size = fs::file_size(mf, ec);
  if (ec) {
    *err = mf + ": cannot read: " + ec.message();
    return false;
  }
  if (static_cast<long>(size) > kManifestMaxBytes) {
    *err = mf + ": " + std::to_string(size) + " bytes, a manifest is at most " + std::to_string(kManifestMaxBytes);
    return false;
  }
  std::ifstream f(mf, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  *m = json::parse(ss.str(), nullptr, false);
  if (m->is_discarded()) {
    *err = mf + ": not valid JSON";
    return false;
  }
  return true;
}

}  // namespace

bool read_bake_quality(const std::string &dir, BakeQuality *q) {
  json m;
  std::string err;
  if (!load_manifest(dir, &m, &err) || !m.is_object() || !m.contains("settings") || !m["settings"].is_object())
    return false;
  const json &s = m["settings"];
  BakeQuality got;
  if (!s.contains("quality") || !s["quality"].is_string() ||
      !bake_quality_preset(s["quality"].get<std::string>(), &got))
    return false;
  // Each value a number within the range its scene key takes (glue/scene/gltf_extras.cpp).
  auto num = [&](const char *key, double lo, double hi, double *out) {
    if (!s.contains(key) || !s[key].is_number()) return false;
    const double v = s[key].get<double>();
    if (!(v >= lo && v <= hi)) return false;
    *out = v;
    return true;
  };
  auto integer = [&](const char *key, int lo, int hi, int *out) {
    double v = 0;
    if (!num(key, lo, hi, &v) || v != static_cast<int>(v)) return false;
    *out = static_cast<int>(v);
    return true;
  };
  if (!num("luxels_per_unit", 0.01, 1024, &got.luxels_per_unit) || !integer("supersample", 1, 8, &got.supersample) ||
      !integer("area_samples", 0, 1024, &got.area_samples) ||
      !integer("spread_samples", 1, 1024, &got.spread_samples) || !integer("sky_samples", 1, 4096, &got.sky_samples) ||
      !integer("bounces", 0, 100, &got.bounces) || !integer("gather_rays", 1, 1024, &got.gather_rays) ||
      !num("threshold", 0, 1, &got.threshold))
    return false;
  *q = got;
  return true;
}

bool read_bake_dir(const std::string &dir, const WorldBakeInput &in, std::vector<float> *page, std::string *err) {
  const BakeHash expect = bake_input_hash(in);
  const int page_w = in.page_w, page_h = in.page_h;
  const std::string mf = dir + "/" + kManifest;
  json m;
  if (!load_manifest(dir, &m, err)) return false;
  ManifestReader r{mf, err};
  const json *fmt = r.get(m, "", "format", json::value_t::string);
  if (!fmt) return false;
  if (*fmt != "tiershade bake") {
    *err = mf + ": /format: \"" + fmt->get<std::string>() + "\" is not \"tiershade bake\"";
    return false;
  }
  const json *ver = r.get(m, "", "version", json::value_t::number_integer, true);
  if (!ver) return false;
  if (*ver != kManifestVersion) {
    *err = mf + ": /version: " + ver->dump() + ", this tiershade reads version " + std::to_string(kManifestVersion) +
        " (rebake with tiershade bake)";
    return false;
  }
  const json *hash = r.get(m, "", "hash", json::value_t::object);
  if (!hash) return false;
  BakeHash got;
  const char *keys[] = {"geometry", "materials", "lights", "probes", "settings", "all"};
  uint64_t *parts[] = {&got.geometry, &got.materials, &got.lights, &got.probes, &got.settings, nullptr};
  uint64_t all = 0;
  for (int i = 0; i < 6; ++i) {
    const json *h = r.get(*hash, "/hash", keys[i], json::value_t::string);
    if (!h) return false;
    const std::string t = h->get<std::string>();
    char *end = nullptr;
    const uint64_t v = std::strtoull(t.c_str(), &end, 16);
    if (t.size() != 16 || !end || *end) {
      *err = mf + ": /hash/" + keys[i] + ": \"" + t + "\" is not 16 hex digits";
      return false;
    }
    (parts[i] ? *parts[i] : all) = v;
  }
  if (all != got.all()) {
    *err = mf + ": /hash/all: does not match its parts (the manifest was edited)";
    return false;
  }
  if (got.all() != expect.all()) {
    // The settings that differ, by name (the manifest's against the scene's).
    std::string diff;
    const json now = settings_json(in.luxels_per_unit, in.page_w, in.page_h, in.supersample, in.area_samples,
                                   in.spread_samples, in.sky.samples, in.bounce, in.cube_size);
    if (m.contains("settings") && m["settings"].is_object())
      for (const auto &kv : now.items())
        if (!m["settings"].contains(kv.key()) || m["settings"][kv.key()] != kv.value())
          diff += std::string(diff.empty() ? " (" : ", ") + kv.key() + " " +
              (m["settings"].contains(kv.key()) ? m["settings"][kv.key()].dump() : "?") + " -> " + kv.value().dump();
    if (!diff.empty()) diff += ")";
    *err = mf + ": stale bake: " + got.changed(expect) + diff +
        " changed since it was baked; rebake with tiershade bake SCENE -o " + dir;
    return false;
  }
  const json *pg = r.get(m, "", "page", json::value_t::object);
  if (!pg) return false;
  const json *file = r.get(*pg, "/page", "file", json::value_t::string);
  const json *pw = file ? r.get(*pg, "/page", "width", json::value_t::number_integer, true) : nullptr;
  const json *ph = pw ? r.get(*pg, "/page", "height", json::value_t::number_integer, true) : nullptr;
  if (!ph) return false;
  if (*file != kPage || *pw != page_w || *ph != page_h) {
    *err = mf + ": /page: " + pg->dump() + " is not " + kPage + " of " + std::to_string(page_w) + " x " +
        std::to_string(page_h);
    return false;
  }
  ImageF img;
  const std::string pf = dir + "/" + kPage;
  if (!read_exr(pf, &img, err)) return false;
  if (img.w != page_w || img.h < page_h || img.h % page_h != 0) {  // pages of page_h rows, stacked
    *err = pf + ": " + std::to_string(img.w) + " x " + std::to_string(img.h) + " texels, the manifest says pages of " +
        std::to_string(page_w) + " x " + std::to_string(page_h);
    return false;
  }
  for (size_t i = 0; i < img.rgba.size(); ++i)
    if (!std::isfinite(img.rgba[i]) || img.rgba[i] < 0) {
      *err = pf + ": texel (" + std::to_string(i / 4 % page_w) + ", " + std::to_string(i / 4 / page_w) +
          ") is negative or not finite";
      return false;
    }
  *page = std::move(img.rgba);
  return true;
}

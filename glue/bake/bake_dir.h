// tiershade bake: the bake directory (`tiershade bake SCENE -o DIR`, docs/baking.md): the lightmap
// page as float EXR and manifest.json (format version, scene, the content hash of what the bake
// depends on, page size, each face's place on the page, the settings, each pass's rays and time,
// what was baked and why), written atomically; reading it back for a scene that names it
// (extras.tiershade.lightmaps.bake), refused when stale; and the checkpoints of a bake being
// written (DIR.partial/pass.bin: the latest finished pass, resumed by the next run with the same
// hash).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bake/irradiance_volume.h"
#include "bake/world_bake.h"

// What a bake depends on, hashed in parts (glue/bake/content_hash.h) so that a stale bake can say
// what changed. geometry: the faces' frames and every triangle of the ray scene; materials: the
// faces' reflectivity, emission and bump flag; lights; probes; settings: luxel density, page size,
// supersampling, bounces, gather rays, threshold, seed, cube size.
struct BakeHash {
  uint64_t geometry = 0, materials = 0, lights = 0, probes = 0, settings = 0;
  uint64_t all() const;
  // The parts that differ from `o`, as words ("the lights, the settings"); empty when equal.
  std::string changed(const BakeHash &o) const;
};
BakeHash bake_input_hash(const WorldBakeInput &in);  // in.rays: the scene's ray scene (set)
std::string hash_hex(uint64_t h);

// One face as the manifest and `tiershade light` see it.
struct BakeFace {
  std::string name, where;  // material, primitive
  WorldFace face;  // its frame (name pointing into `name`'s copy is not kept: use `name`)
  lm_face_place place;
  int luxels_w = 0, luxels_h = 0;
};
// What a bake was, for the manifest, `tiershade bake`'s report and `tiershade light`.
struct BakeSummary {
  BakeHash hash;
  std::string from_dir;  // the bake directory the page came from ("": baked here)
  int resumed_after = -1;  // baked here: the checkpointed pass resumed after (-1: none)
  std::string resume_note;  // why a checkpoint was discarded, if one was
  int page_w = 0, page_h = 0;
  double luxels_per_unit = 0;
  int supersample = 0, cube_size = 0, probes = 0, lights = 0;
  int traced_cubes = 0;  // probes whose cube the bake ray traced (the others are rendered in-engine at load)
  BounceSettings bounce;
  std::vector<BakeFace> faces;
  long luxels = 0, direct_rays = 0;
  double direct_ms = 0;
  bool sky = false;  // the scene has a sky (glue/bake/sky.h)
  int emitters = 0, area_samples = 0;  // faces with emission, sampled as area lights
  int model_emitters = 0;  // model primitives with emission (area lights too)
  int spread_samples = 0, sky_samples = 0;
  // The quality the bake was made at (glue/bake/bake_quality.h; set by its caller: the preset's name
  // goes into the manifest).
  BakeQuality quality;
  SkyReport sky_pass;  // rays 0 on a resumed bake (the saved pass 0 holds it)
  AreaLightReport area_pass;
  BounceReport report;
};

// How prepare_scene runs a scene's bake: from a bake directory (read), or baked here, with the
// checkpoints of a bake directory being written (checkpoint_dir: DIR of `tiershade bake -o DIR`)
// and a progress line on stderr (on a terminal, or once the bake has run 2 s).
struct BakeDirUse {
  std::string read, checkpoint_dir;
  bool progress = false;
};
// Bakes (or reads) the world: *in's page_in/hooks are set here; where[i]: face i's primitive.
bool bake_world_dir(const BakeDirUse &use, WorldBakeInput in, const std::vector<std::string> &where, WorldBake *out,
                    BakeSummary *sum, std::string *err);

// Writes DIR (page.exr, manifest.json) atomically (glue/io/atomic_dir.h: DIR appears whole or not
// at all; an existing DIR is replaced only if it holds a manifest.json), then removes DIR.partial.
// `volume` (may be null or empty): the scene's irradiance volume, written as volume.bin with the
// manifest's "volume" entry (glue/bake/volume_file.h).
bool write_bake_dir(const std::string &dir, const std::string &scene_name, const BakeSummary &sum,
                    const std::vector<float> &page, const std::vector<std::string> &baked_why, std::string *err,
                    const IrradianceVolume *volume = nullptr);
// Reads DIR/manifest.json and DIR/page.exr: every error names the file and the JSON place; a
// manifest whose hash is not bake_input_hash(in) is refused, naming what changed.
bool read_bake_dir(const std::string &dir, const WorldBakeInput &in, std::vector<float> *page, std::string *err);

// The quality DIR/manifest.json records (its /settings: the preset's name and every value, each
// within the range a scene key takes): true with *q filled; false when the manifest cannot be read
// or records none (a render then takes the scene's quality, and read_bake_dir says what differs).
bool read_bake_quality(const std::string &dir, BakeQuality *q);

// The checkpoint area of DIR: DIR.partial (beside DIR, which appears only when complete).
std::string bake_checkpoint_dir(const std::string &dir);
// The latest pass saved in DIR.partial, if its hash is `hash`: true with *st filled; false when
// there is none (*note empty) or it does not belong to this bake (*note says why; it is removed).
bool load_checkpoint(const std::string &dir, const BakeHash &hash, BakePassState *st, std::string *note);
// Saves the pass atomically as DIR.partial/pass.bin (replacing the previous one).
bool save_checkpoint(const std::string &dir, const BakeHash &hash, const BakePassState &st, std::string *err);

// tiershade bundle: shader bundles for engines (docs/bundles.md). Writes the production GLSL of
// a set of variants as standalone files, plus a manifest (JSON) with each variant's defines,
// attributes, uniforms, samplers (with the texture unit the engine binds them to), outputs
// and instruction slots, found by compiling and linking each program on llvmpipe.
#pragma once
#include <string>
#include <vector>

#include "shaderlib/assembler.h"
#include "shaderlib/variants.h"

struct BundleEntry {
  const Variant *variant = nullptr;
  std::vector<std::string> why;  // why the scene needs it (empty for explicit variants)
};

// "<tier>_<8 hex digits of FNV-1a of v.name()>", e.g. "sm3_1a2b3c4d": short, stable, safe.
std::string bundle_file_stem(const Variant &v);

// Writes DIR/<shader>/<stem>.vert|.frag and DIR/manifest.json for `entries` (duplicates are
// written once) for `target`. Everything is written into DIR.tmp.<pid> first and renamed into
// place; an existing DIR is replaced only when it is a previous bundle (holds manifest.json).
// source_desc: what the bundle was made from (the scene path, or "explicit variants").
// On failure returns false with *err and leaves DIR as it was and no temporary behind.
bool write_bundle(const std::vector<BundleEntry> &entries, Target target, const std::string &dir,
                  const std::string &source_desc, std::string *err);

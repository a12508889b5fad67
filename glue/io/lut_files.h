// tiershade io: colour LUT files.
//
//  * .cube (the format colourists export; Adobe "Cube LUT Specification 1.0", plus the
//    DaVinci Resolve variant): read strictly, written atomically.
//  * Source's raw colour-correction LUT: 32^3 RGB8 entries = 98,304 bytes (fact sheet
//    section 9). The entry order is INFERRED (the loader is not in the SDK): red fastest,
//    then green, then blue, as the index of an RGBX5551 key whose fields are r, g, b from
//    the low bits up (IColorCorrection.h SetLookup(RGBX5551_t in, color24 out)).
//
// Every failure fills *err with "<file>: <problem>" or "<file>:<line>: <problem>".
// Writers write atomically (io/atomic_file.h): on failure the temporary is removed and <path>
// is untouched.
// Grammar accepted for .cube: docs/color_correction.md, "LUT files".
#pragma once
#include <string>
#include <vector>

#include "base/lut3d.h"

struct CubeFile {
  std::string title;
  int size_1d = 0;  // LUT_1D_SIZE, 0 = none
  int size_3d = 0;  // LUT_3D_SIZE, 0 = none
  float domain_min[3] = {0.f, 0.f, 0.f};  // DOMAIN_MIN / LUT_*_INPUT_RANGE
  float domain_max[3] = {1.f, 1.f, 1.f};
  std::vector<float> table_1d;  // size_1d RGB triples
  std::vector<float> table_3d;  // size_3d^3 RGB triples, red fastest
};

// Inputs must be regular files (a FIFO or a device is refused before it is opened); a .cube
// is at most kMaxCubeBytes, a .raw exactly kSourceRawBytes.
constexpr long long kMaxCubeBytes = 128LL << 20;
bool read_cube(const std::string &path, CubeFile *out, std::string *err);

// A .cube that is a plain 3D table on the unit domain, as a Lut3D; otherwise an error that
// says why (a 1D table, another domain) and that the file must be baked (lut_bake.h).
bool cube_as_lut3d(const std::string &path, const CubeFile &cube, Lut3D *out, std::string *err);

// Writes LUT_3D_SIZE n on the unit domain; values with 9 significant digits (exact for
// float). The title may not hold a double quote or a line break.
bool write_cube(const std::string &path, const Lut3D &lut, std::string *err);

constexpr int kSourceRawEdge = 32;
constexpr long kSourceRawBytes = 32L * 32 * 32 * 3;  // 98,304
// Reads a Source .raw LUT (code / 255).
bool read_source_raw(const std::string &path, Lut3D *out, std::string *err);
// Writes an edge-32 LUT as a Source .raw: each value clamped to [0, 1] and rounded to the
// nearest of 256 codes. A LUT of another edge is an error (bake it at 32 first).
bool write_source_raw(const std::string &path, const Lut3D &lut, std::string *err);

// Reads any LUT tiershade can use directly: .cube (a 3D table on the unit domain) or .raw,
// chosen by the file name's extension.
bool read_lut_file(const std::string &path, Lut3D *out, std::string *err);
